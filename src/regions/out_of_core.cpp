// The out-of-core triangulation (ridt/out_of_core.hpp): strips of columns triangulated one
// after another, each checked exactly against the columns it did not load.
#include "ridt/out_of_core.hpp"

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>
#include <unordered_map>
#include <unordered_set>

#include "regions/cells.hpp"
#include "regions/files.hpp"
#include "ridt/predicates.hpp"
#include "ridt/regions.hpp"

namespace ridt {
namespace {

using detail::CellStore;
using detail::FileOut;
using regions::Box;
using regions::by_place;
using regions::Disc;
using regions::may_meet;
using regions::Site;

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// A strip's point at its peak: the walking kernel's (ridt::estimate_memory: 94 bytes, the
// result included), the loaded copy with its input index (24) and the reading's (24).
constexpr double kBytesPerPoint = 142;
constexpr std::size_t kFixedBytes = std::size_t{32} << 20;  // the cells' tables, a block, the process
constexpr std::size_t kThreadBytes = std::size_t{8} << 20;  // ridt::estimate_memory's a thread
constexpr std::size_t kOwnedColumns = 8;  // columns a strip owns; one more on either side loaded

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// A strip: the points of the columns [lo, hi), column after column (those of the owned columns
// [own_lo, own_hi) at positions [own_first, own_last)), then single points of other columns
// that its checks found it needs (`extra`, by input index: equal points keep their order).
struct Strip {
  std::size_t lo = 0, hi = 0, own_lo = 0, own_hi = 0;
  std::vector<Point> points;
  std::vector<std::uint64_t> ids;
  std::size_t own_first = 0, own_last = 0;
  std::vector<Site> extra;
  std::unordered_set<std::uint64_t> has;  // the input indices in `extra`

  bool owns(VertexId v) const { return v >= own_first && v < own_last; }
  bool loaded(std::size_t column) const { return column >= lo && column < hi; }

  void load(const CellStore& cells) {
    points.clear(), ids.clear();
    std::vector<Site> column;
    for (std::size_t c = lo; c < hi; ++c) {
      if (c == own_lo) own_first = points.size();
      column.clear();
      cells.read_column(c, column);
      for (const Site& p : column) points.push_back({p.x, p.y}), ids.push_back(p.id);
      if (c + 1 == own_hi) own_last = points.size();
    }
    std::sort(extra.begin(), extra.end(), [](const Site& p, const Site& q) { return p.id < q.id; });
    for (const Site& p : extra) points.push_back({p.x, p.y}), ids.push_back(p.id);
  }
};

// The exact checks of a strip's triangles against the columns it did not load, reading their
// cells as needed (kept until the strip is done, up to a budget). What a check finds wanting
// goes to `found`: single points, each with every point equal to it.
class Checker {
 public:
  Checker(const CellStore& cells, std::size_t budget) : cells_(cells), budget_(budget) {}

  void reset() { cache_.clear(), held_ = 0; }

  // The points of columns not loaded inside or on the circle through the counter-clockwise
  // (a, b, c). Only the columns the widened circle reaches are looked at, outward from the
  // loaded ones, and in them only the cells it meets.
  void circle(const Strip& s, const Point& a, const Point& b, const Point& c, std::vector<Site>& found) {
    const Disc d = regions::circle(a, b, c);
    auto look = [&](std::size_t k) {
      // The rows the disc meets over the column's width.
      const Box column = cells_.cell_box(k, 0);
      const double dx = d.x < column.x0 ? column.x0 - d.x : d.x > column.x1 ? d.x - column.x1 : 0;
      if (dx > d.r) return;
      const double half = std::sqrt(d.r - dx) * std::sqrt(d.r + dx) * (1 + 1e-9);
      const std::size_t last = std::isfinite(half) ? cells_.row_of(d.y + half) : cells_.rows() - 1;
      for (std::size_t r = std::isfinite(half) ? cells_.row_of(d.y - half) : 0; r <= last; ++r) {
        if (cells_.cell_size(k, r) == 0 || cells_.cell_box(k, r).distance(d.x, d.y) > d.r ||
            !may_meet(d, cells_.cell_hull(k, r)))
          continue;
        for (const Site& p : cell(k, r))
          if (in_circle(a, b, c, {p.x, p.y}) >= 0 && !s.has.count(p.id)) found.push_back(p);
      }
    };
    for (std::size_t k = s.lo; k-- > 0 && cells_.left(k + 1) > d.x - d.r;) look(k);
    for (std::size_t k = s.hi; k < cells_.columns() && cells_.left(k) <= d.x + d.r; ++k) look(k);
  }

  // The points of columns not loaded strictly beyond the hull edge a -> b (to its right) that
  // are corners of their cells' hulls: if any point is beyond, a corner is. Columns whose hull
  // has no corner beyond are passed over whole.
  void hull_edge(const Strip& s, const Point& a, const Point& b, std::vector<Site>& found) {
    auto beyond = [&](const Site& p) { return orientation(a, b, {p.x, p.y}) < 0; };
    for (std::size_t k = 0; k < cells_.columns(); ++k) {
      if (s.loaded(k) || std::none_of(cells_.column_hull(k).begin(), cells_.column_hull(k).end(), beyond)) continue;
      for (std::size_t r = 0; r < cells_.rows(); ++r)
        for (const Site& p : cells_.cell_hull(k, r))
          if (beyond(p)) with_equals(s, cell(k, r), p, found);
    }
  }

  // p and the points of its cell equal to it, unless the strip has them.
  void with_equals(const Strip& s, const Site& p, std::vector<Site>& found) {
    with_equals(s, cell(cells_.column_of(p.x), cells_.row_of(p.y)), p, found);
  }

 private:
  // cell: sorted by_place.
  static void with_equals(const Strip& s, const std::vector<Site>& cell, const Site& p, std::vector<Site>& found) {
    const auto less = [](const Site& u, const Site& v) { return u.x != v.x ? u.x < v.x : u.y < v.y; };
    const auto [from, to] = std::equal_range(cell.begin(), cell.end(), p, less);
    for (auto it = from; it != to; ++it)
      if (!s.has.count(it->id)) found.push_back(*it);
  }

  // Cell (k, r)'s points sorted by_place, read once while the budget lasts.
  const std::vector<Site>& cell(std::size_t k, std::size_t r) {
    const std::size_t key = k * cells_.rows() + r;
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
    if (held_ > budget_) reset();
    std::vector<Site>& points = cache_[key];
    cells_.read_cell(k, r, points);
    std::sort(points.begin(), points.end(), by_place);
    held_ += points.size() * sizeof(Site);
    return points;
  }

  const CellStore& cells_;
  std::size_t budget_, held_ = 0;
  std::unordered_map<std::size_t, std::vector<Site>> cache_;
};

// Checks strip s's triangulation t: adds to s.extra the points of other columns that a
// triangle at an owned point or a hull edge at one finds wanting (and more columns when t has
// no triangle); true when nothing was wanting.
bool check(Strip& s, const Triangulation& t, const CellStore& cells, std::vector<Checker>& checkers) {
  if (t.size() == 0 && s.own_last > s.own_first && (s.lo > 0 || s.hi < cells.columns())) {
    // Points on a line tell nothing: as many columns again on either side, until a triangle
    // appears (the whole set is not on one line: triangulate_out_of_core sees to that).
    const std::size_t width = s.hi - s.lo;
    s.lo = s.lo > width ? s.lo - width : 0;
    s.hi = std::min(cells.columns(), s.hi + width);
    std::erase_if(s.extra, [&](const Site& p) { return s.loaded(cells.column_of(p.x)) && s.has.erase(p.id) > 0; });
    return false;
  }
  // The triangles shared among the checkers, each on a thread with what it finds.
  const std::size_t parts = std::clamp<std::size_t>(t.size() / 65536, 1, checkers.size());
  std::vector<std::vector<Site>> found(parts);
  auto look = [&](std::size_t p) {
    const std::size_t end = t.size() * (p + 1) / parts;
    for (std::size_t k = t.size() * p / parts; k < end; ++k) {
      // The points are read at random: those some triangles ahead are asked for first.
      if (k + 8 < end)
        for (int i = 0; i < 3; ++i) __builtin_prefetch(&s.points[t.triangles[3 * (k + 8) + i]]);
      const VertexId* v = &t.triangles[3 * k];
      if (s.owns(v[0]) || s.owns(v[1]) || s.owns(v[2]))
        checkers[p].circle(s, s.points[v[0]], s.points[v[1]], s.points[v[2]], found[p]);
    }
  };
  {
    std::vector<std::jthread> helpers;
    for (std::size_t p = 1; p < parts; ++p) helpers.emplace_back(look, p);
    look(0);
  }
  Checker& checker = checkers[0];
  for (std::size_t i = 0; i < t.hull.size(); ++i) {
    const VertexId a = t.hull[i], b = t.hull[(i + 1) % t.hull.size()];
    if (s.owns(a) || s.owns(b)) checker.hull_edge(s, s.points[a], s.points[b], found[0]);
  }
  std::size_t added = 0;
  for (const std::vector<Site>& some : found)
    for (const Site& p : some)
      if (s.has.insert(p.id).second) s.extra.push_back(p), ++added;
  return added == 0;
}

// The triangles strip s keeps (those whose smallest input index it owns), each from that
// index, as input indices: written to its part (.bin, uint32 triples, in one pass).
std::uint64_t write_part(const std::string& path, const Strip& s, const Triangulation& t,
                         const std::function<void(const std::string&)>& announce) {
  FileOut w(path, announce);
  std::uint64_t count = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const VertexId* v = &t.triangles[3 * k];
    if (!s.owns(v[0]) && !s.owns(v[1]) && !s.owns(v[2])) continue;
    int first = 0;
    for (int i = 1; i < 3; ++i)
      if (s.ids[v[i]] < s.ids[v[first]]) first = i;
    if (!s.owns(v[first])) continue;
    for (int j = 0; j < 3; ++j) w.put_u32_le(static_cast<std::uint32_t>(s.ids[v[(first + j) % 3]]));
    ++count;
  }
  w.commit();
  return count;
}

// The parts written so far, removed unless the whole run succeeds (FileOut told the caller of
// each, OutOfCoreOptions::wrote, which may remove them where a signal stops the run).
struct Parts {
  std::vector<std::string> written;
  bool done = false;
  void add(const std::string& part) {
    written.push_back(part);  // told to the caller by FileOut, before it was renamed into place
  }
  ~Parts() {
    if (done) return;
    for (const std::string& p : written) std::remove(p.c_str());
  }
};

// The points a strip may hold within `limit` (each thread of its triangulation keeps buffers).
std::size_t strip_points(std::size_t limit, unsigned threads) {
  const std::size_t fixed = kFixedBytes + threads * kThreadBytes;
  const auto least = fixed + static_cast<std::size_t>(4096 * kBytesPerPoint);
  if (limit <= least)
    throw InputError("the out-of-core mode needs a memory limit of at least " + std::to_string((least >> 20) + 1) +
                     " MiB (got " + std::to_string(limit >> 20) + " MiB)");
  return static_cast<std::size_t>(static_cast<double>(limit - fixed) / kBytesPerPoint);
}

// Triangulates strip s (owned columns [own_lo, own_hi)) until it knows its triangles, and
// writes them to `part`.
std::uint64_t run_strip(Strip& s, const CellStore& cells, std::vector<Checker>& checkers, const Options& o,
                        const std::string& part, OutOfCoreStats& st,
                        const std::function<void(const std::string&)>& o_wrote) {
  s.lo = s.own_lo > 0 ? s.own_lo - 1 : 0;
  s.hi = std::min(cells.columns(), s.own_hi + 1);
  for (Checker& c : checkers) c.reset();  // the cells they read stay good for the strip's next tries
  // The corners of the whole set's hull from the start: the strip's hull edges at its points
  // are then mostly the whole set's, with nothing beyond them.
  std::vector<Site> corners;
  auto take = [&](const std::vector<Site>& hull) {
    for (const Site& p : hull)
      if (!s.loaded(cells.column_of(p.x))) checkers[0].with_equals(s, p, corners);
  };
  take(cells.hull());
  for (std::size_t k = 0; k < cells.columns(); ++k)
    if (!s.loaded(k)) take(cells.cell_hull(k, 0)), take(cells.cell_hull(k, cells.rows() - 1));
  for (const Site& p : corners)
    if (s.has.insert(p.id).second) s.extra.push_back(p);
  for (;; ++st.retries) {
    auto t0 = Clock::now();
    s.load(cells);
    st.loaded += s.points.size();
    const Triangulation t = triangulate(std::span<const Point>(s.points), o);
    st.time_triangulate_s += since(t0);
    t0 = Clock::now();
    const bool known = check(s, t, cells, checkers);
    st.time_check_s += since(t0);
    if (known) {
      t0 = Clock::now();
      const std::uint64_t count = write_part(part, s, t, o_wrote);
      st.time_write_s += since(t0);
      return count;
    }
  }
}

}  // namespace

OutOfCoreStats triangulate_out_of_core(const OutOfCoreOptions& options) {
  const fs::path out(options.output);
  if (detail::extension_of(options.output) != ".parts")
    throw InputError(options.output + ": the out-of-core mode writes parts and their index, OUT.parts");
  if (detail::extension_of(options.input) != ".bin")
    throw InputError(options.input + ": the out-of-core mode reads .bin point files");
  std::error_code size_error;
  if (const auto bytes = fs::file_size(options.input, size_error); !size_error && bytes / 16 > UINT32_MAX)
    throw InputError(options.input +
                     ": the out-of-core mode takes at most 2^32 - 1 points (its parts hold 32-bit indices)");
  const std::size_t limit = options.memory_limit != 0 ? options.memory_limit : available_memory() / 4;
  const unsigned threads = std::max(options.threads, 1u);
  const std::size_t per_strip = strip_points(limit, threads);
  OutOfCoreStats st;
  auto t0 = Clock::now();
  const std::string stem = (out.parent_path() / out.stem()).string();
  const CellStore cells(
      options.input, stem + ".cells.tmp-" + std::to_string(::getpid()),
      options.column_points != 0 ? options.column_points : std::max<std::size_t>(1, per_strip / (kOwnedColumns + 4)),
      limit / 8, [&](double done) {
        if (options.progress) options.progress("bucketing", done);
      });
  st.time_bucket_s = since(t0);
  st.points = cells.points(), st.columns = cells.columns(), st.rows = cells.rows();
  st.strips = (cells.columns() + kOwnedColumns - 1) / kOwnedColumns;
  Options o;
  o.method = threads > 1 ? Method::Partition : Method::Serial;
  o.threads = threads;
  std::vector<Checker> checkers(threads, Checker(cells, limit / 16 / threads));
  Parts parts;
  auto name = [&](std::size_t k) {
    return out.stem().string() + "." + std::to_string(k) + "-of-" + std::to_string(st.strips) + ".bin";
  };
  for (std::size_t k = 0; k < st.strips; ++k) {
    if (options.progress) options.progress("triangulating", static_cast<double>(k) / static_cast<double>(st.strips));
    Strip s;
    s.own_lo = k * kOwnedColumns, s.own_hi = std::min(cells.columns(), (k + 1) * kOwnedColumns);
    const std::string part = (out.parent_path() / name(k)).string();
    // Points all on one line (their hull has no corner but the two ends) have no triangle.
    st.triangles += cells.hull().size() < 3 ? write_part(part, s, {}, options.wrote)
                                            : run_strip(s, cells, checkers, o, part, st, options.wrote);
    parts.add(part);
  }
  FileOut index(options.output, options.wrote);
  index.put("ridt parts " + std::to_string(st.strips) + "\n");
  for (std::size_t k = 0; k < st.strips; ++k) index.put(name(k) + "\n");
  index.commit();
  parts.done = true;
  return st;
}

}  // namespace ridt
