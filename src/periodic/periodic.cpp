// The periodic Delaunay triangulation (ridt/periodic.hpp), two ways.
//
// The copies of the points tile the plane, and their Delaunay triangulation repeats with the
// domain; one triangle of each class of translates is kept: the one whose least corner (by
// input index, then offset) is a point as given (periodic/builder.hpp).
//
// The whole way (any set): triangulate every point and its copies within a margin m of the
// domain on the one mutable triangulation, keep the triangles whose circles lie inside the
// domain grown by m, and check that there are 2n (the torus's count) and that every edge has its
// twin; else grow the margin and build again (uniform points rarely need it: the first margin is
// some 2.4 times the expected largest empty circle's diameter).
//
// The split way (from kSplitPoints points on): a triangle whose circle lies inside the domain
// holds no copy (they all lie outside) and, in the points' own Delaunay triangulation, no
// point: so that triangulation — triangulate(), the library's fastest, on threads — gives all
// of those. The rest have circles that cross the domain's sides (or come within the rounding of
// them): a translate of each lies across the side x = x0 or the side y = y0 (the opposite sides
// are the same on the torus), within its diameter of it. So they are the triangles of two
// strips, each the copies within m of one of those sides (some 2 m / side of the points, along
// the side and m beyond its ends) on the one mutable triangulation, whose circles lie in the
// strip and are not inside: complete where no such circle is more than m across. One test
// (circle_inside), on the same arguments, sorts the triangles of both parts, so each periodic
// triangle comes once; the two parts are joined by the twins of the edges between them, and
// checked as the whole way's are.
//
// Both stand on exact predicates of the copies' true coordinates (predicates/shifted.hpp);
// only where a circle lies is measured in rounded arithmetic, with room for its rounding, and
// where that room alone leaves a circle in doubt the result is checked by the exact validator.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>

#include "order/order.hpp"
#include "periodic/builder.hpp"
#include "ridt/periodic.hpp"

namespace ridt {
namespace detail {
namespace {

// Whether x0 <= x < x0 + width, exactly: x - x0 = s + e (two_diff), compared with width.
bool within(double x, double x0, double width) {
  if (!(x >= x0)) return false;
  const double s = x - x0, bv = x - s, av = s + bv, e = (x - av) + (bv - x0);
  return s < width || (s == width && e < 0);
}

void check_input(std::span<const Point> points, const PeriodicDomain& d) {
  if (!(std::isfinite(d.width) && d.width > 0 && std::isfinite(d.height) && d.height > 0))
    throw InputError("triangulate_periodic: the domain's width and height must be positive and finite");
  if (!std::isfinite(d.origin.x) || !std::isfinite(d.origin.y))
    throw InputError("triangulate_periodic: the domain's origin is not finite");
  if (points.empty()) throw InputError("triangulate_periodic: no points");
  if (points.size() >= kMaxSlotPoints / 16) throw InputError("triangulate_periodic: too many points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw InputError("triangulate_periodic: point " + std::to_string(i) + " is not finite");
    if (!within(p.x, d.origin.x, d.width) || !within(p.y, d.origin.y, d.height))
      throw InputError("triangulate_periodic: point " + std::to_string(i) +
                       " lies outside the domain [x0, x0 + width) x [y0, y0 + height)");
  }
}

// From this many points on, the Delaunay triangulation of the points and two strips (split).
constexpr std::size_t kSplitPoints = 4096;

// An edge without a neighbour, by its ends and the offset from its tail to its head, turned so
// that an edge and its twin (which runs back, the offset negated) have the same key: the lesser
// of the two ways round. `back`: it runs the other way. Sorted, twins lie side by side.
struct OpenEdge {
  std::array<std::int64_t, 3> key;  // tail, head, offset (dx, dy packed)
  bool back;
  std::uint32_t e;
  bool operator<(const OpenEdge& o) const { return std::tie(key, back) < std::tie(o.key, o.back); }
};

// Every edge of `out` without a neighbour yet linked to its twin (its neighbour offset too,
// where `neighbors` asks for them); false where one has none, or several.
bool link_open_edges(PeriodicTriangulation& out, bool neighbors, unsigned threads) {
  auto tail = [](std::size_t e) { return e - e % 3 + (e + 1) % 3; };
  auto head = [](std::size_t e) { return e - e % 3 + (e + 2) % 3; };
  auto open_edge = [&](std::size_t e) {
    const std::size_t t = tail(e), h = head(e);
    const std::int64_t a = out.triangles[t], b = out.triangles[h];
    const std::int64_t dx = out.offsets[h].dx - out.offsets[t].dx, dy = out.offsets[h].dy - out.offsets[t].dy;
    const std::array<std::int64_t, 3> there{a, b, dx * 65536 + dy}, back{b, a, -dx * 65536 - dy};
    return there < back ? OpenEdge{there, false, static_cast<std::uint32_t>(e)}
                        : OpenEdge{back, true, static_cast<std::uint32_t>(e)};
  };
  // The edges without a neighbour (some one in 250 at 10^6 points, along the strips), found on
  // threads, 64 at a time by a test that vectorizes (edge by edge the scan took 13 ms there).
  const std::size_t count = out.triangles.size();
  const auto parts = static_cast<unsigned>(std::clamp<std::size_t>(count / 65536, 1, threads));
  std::vector<std::vector<OpenEdge>> found(parts);
  const std::int32_t* neighbour = out.neighbors.data();
  parallel_for(parts, parts, 1, [&](std::size_t from, std::size_t to) {
    for (std::size_t p = from; p < to; ++p) {
      const std::size_t end = count * (p + 1) / parts;
      for (std::size_t a = count * p / parts; a < end; a += 64) {
        const std::size_t b = std::min(end, a + 64);
        std::int32_t any = 0;
        for (std::size_t e = a; e < b; ++e) any |= neighbour[e];
        if (any < 0)
          for (std::size_t e = a; e < b; ++e)
            if (neighbour[e] < 0) found[p].push_back(open_edge(e));
      }
    }
  });
  std::vector<OpenEdge> open;
  for (const std::vector<OpenEdge>& f : found) open.insert(open.end(), f.begin(), f.end());
  std::sort(open.begin(), open.end());
  if (open.size() % 2 != 0) return false;
  for (std::size_t k = 0; k < open.size(); k += 2) {
    const OpenEdge &x = open[k], &y = open[k + 1];
    // Each key twice, one each way round, and no third.
    if (x.key != y.key || x.back == y.back || (k + 2 < open.size() && open[k + 2].key == x.key)) return false;
    for (const auto& [e, f] : {std::pair{x.e, y.e}, std::pair{y.e, x.e}}) {
      out.neighbors[e] = static_cast<std::int32_t>(f / 3);
      if (neighbors)
        out.neighbor_offsets[e] = make_offset(out.offsets[head(e)].dx - out.offsets[tail(f)].dx,
                                              out.offsets[head(e)].dy - out.offsets[tail(f)].dy);
    }
  }
  return true;
}

// Triangles [from, to) of p: whether each one's circle is inside (`inside`); those that are
// written in output terms in place: input indices, the least first (their neighbours turned with
// them, still p's ids).
void sort_out(Triangulation& p, const InOrder& in, const PeriodicDomain& d, std::vector<std::uint8_t>& inside,
              std::size_t from, std::size_t to) {
  constexpr std::size_t kAhead = 8;  // (the corners of a triangle some way on asked for ahead)
  for (std::size_t k = from; k < to; ++k) {
    if (k + kAhead < to)
      for (std::size_t j = 0; j < 3; ++j) {
        const VertexId v = p.triangles[3 * (k + kAhead) + j];
        __builtin_prefetch(&in.points[v]), __builtin_prefetch(&in.order[v]);
      }
    VertexId* t = &p.triangles[3 * k];
    const VertexId w[3] = {in.order[t[0]], in.order[t[1]], in.order[t[2]]};
    const int low = w[0] < w[1] ? (w[0] < w[2] ? 0 : 2) : (w[1] < w[2] ? 1 : 2);
    inside[k] = circle_inside(in.points[t[low]], in.points[t[next3(low)]], in.points[t[prev3(low)]], d);
    if (!inside[k]) continue;
    std::int32_t* u = &p.neighbors[3 * k];
    const std::int32_t v[3] = {u[0], u[1], u[2]};
    for (int j = 0, i = low; j < 3; ++j, i = i == 2 ? 0 : i + 1) t[j] = w[i], u[j] = v[i];
  }
}

// The two parts as one, over p's arrays (made for the 2n + 1 slots of n points), p's triangles
// sorted out (sort_out): those `inside` keep their places and their neighbours where those are
// inside too, the rim's fill the others' places, then follow. Every other neighbour is found
// through its edge's twin; nothing where one has none, or several.
std::optional<PeriodicTriangulation> join(Triangulation& p, const std::vector<std::uint8_t>& inside,
                                          PeriodicTriangulation rim, unsigned threads, bool neighbors) {
  const std::size_t count = inside.size();
  std::vector<std::size_t> place;  // rim triangle r's
  for (std::size_t k = 0; k < count; ++k)
    if (!inside[k]) place.push_back(k);
  // (the points' own triangulation has 2n - h - 2 triangles, h >= 3 on its hull: the rim has more)
  if (rim.size() < place.size()) return std::nullopt;
  const std::size_t holes = place.size(), total = count + rim.size() - holes;
  for (std::size_t h = 0; h < holes; ++h)  // the links into the triangles left out cut
    for (std::size_t j = 0; j < 3; ++j)
      if (const std::int32_t u = p.neighbors[3 * place[h] + j]; u >= 0 && inside[static_cast<std::size_t>(u)])
        for (std::size_t i = 0; i < 3; ++i)
          if (std::int32_t& back = p.neighbors[3 * static_cast<std::size_t>(u) + i];
              back == static_cast<std::int32_t>(place[h]))
            back = -1;
  while (place.size() < rim.size()) place.push_back(count + place.size() - holes);
  PeriodicTriangulation out;
  out.domain = rim.domain;
  out.triangles = std::move(p.triangles), out.neighbors = std::move(p.neighbors);
  out.triangles.resize(3 * total), out.neighbors.resize(3 * total);
  resize_present(out.offsets, 3 * total, threads);
  if (neighbors) resize_present(out.neighbor_offsets, 3 * total, threads);
  for (std::size_t r = 0; r < rim.size(); ++r)
    for (std::size_t j = 0; j < 3; ++j) {
      const std::size_t e = 3 * place[r] + j;
      out.triangles[e] = rim.triangles[3 * r + j], out.offsets[e] = rim.offsets[3 * r + j], out.neighbors[e] = -1;
    }
  if (!link_open_edges(out, neighbors, threads)) return std::nullopt;
  return out;
}

// The points' Delaunay triangulation with vertex v the point in.order[v] (in.points[v]):
// triangulate() numbering the vertices in its insertion order (BRIO's, along the Hilbert
// curve), so that what reads the triangles' corners reads memory in order; a group of equal
// points stands as its least input index. The duplicates in `dropped`.
Triangulation sorted_triangulation(std::span<const Point> points, unsigned threads, InOrder& in,
                                   std::vector<Duplicate>& dropped) {
  Options options;
  options.method = Method::Auto;  // (the partition method on several threads)
  options.threads = threads;
  Triangulation p = triangulate_in_order(points, options, in);
  std::vector<std::uint32_t>& input = in.order;
  // Each group (by the place that stands for it) and its members' input indices.
  std::vector<std::pair<VertexId, VertexId>> groups;
  for (const Duplicate& d : p.duplicates)
    groups.emplace_back(d.kept, input[d.dropped]), groups.emplace_back(d.kept, input[d.kept]);
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  for (std::size_t a = 0, b = 0; a < groups.size(); a = b) {
    for (b = a; b < groups.size() && groups[b].first == groups[a].first;) ++b;
    for (std::size_t k = a + 1; k < b; ++k) dropped.push_back({groups[k].second, groups[a].second});
    input[groups[a].first] = groups[a].second;  // the least
  }
  std::sort(dropped.begin(), dropped.end(),
            [](const Duplicate& x, const Duplicate& y) { return x.dropped < y.dropped; });
  return p;
}

// The strip of half-width m across the side x = x0 (`across_x`) or y = y0 (Builder::strip): the
// points within m of that side or the opposite one, their copies there.
struct Strip {
  PeriodicTriangulation rim;
  bool verify = false;
};
Strip strip(std::span<const Point> points, const PeriodicDomain& d, double m, bool across_x) {
  std::vector<VertexId> near;
  const double reach = m * (1 + 0x1p-20);
  for (VertexId i = 0; i < points.size(); ++i) {
    const double t = across_x ? points[i].x - d.origin.x : points[i].y - d.origin.y;
    if (t < reach || (across_x ? d.width : d.height) - t < reach) near.push_back(i);
  }
  if (near.empty()) return {};  // (no copy in the strip: no triangle; a Builder takes none as all)
  Builder b(points, d, 1, near);
  b.strip(m, across_x);
  return {b.take(), b.verify()};
}

// The rim: the periodic triangles whose circle is not inside, from the two strips (each one's
// triangles moved so that their least corner is at offset 0, so those found twice are equal):
// each once, in the order of their corners. Complete where every such circle is at most m
// across less the rounding: it then lies in one of the strips (where its copies are complete).
PeriodicTriangulation rim_of(Strip a, Strip b) {
  PeriodicTriangulation& r = a.rim;
  r.triangles.insert(r.triangles.end(), b.rim.triangles.begin(), b.rim.triangles.end());
  r.offsets.insert(r.offsets.end(), b.rim.offsets.begin(), b.rim.offsets.end());
  using Key = std::array<std::uint64_t, 3>;  // each corner: its index and offset (a period or two)
  std::vector<std::pair<Key, std::size_t>> keys(r.size());
  for (std::size_t t = 0; t < r.size(); ++t) {
    for (std::size_t j = 0; j < 3; ++j) {
      const Offset o = r.offsets[3 * t + j];
      keys[t].first[j] = std::uint64_t{r.triangles[3 * t + j]} << 32 ^ (std::uint64_t{std::uint16_t(o.dx)} << 16) ^
          std::uint16_t(o.dy);
    }
    keys[t].second = t;
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end(), [](const auto& x, const auto& y) { return x.first == y.first; }),
             keys.end());
  PeriodicTriangulation out;
  out.domain = r.domain;
  out.triangles.resize(3 * keys.size()), out.offsets.resize(3 * keys.size());
  for (std::size_t t = 0; t < keys.size(); ++t)
    for (std::size_t j = 0; j < 3; ++j) {
      out.triangles[3 * t + j] = r.triangles[3 * keys[t].second + j];
      out.offsets[3 * t + j] = r.offsets[3 * keys[t].second + j];
    }
  return out;
}

// The periodic triangulation as two parts that do not meet: the triangles of the points' own
// Delaunay triangulation (triangulate(), on threads) whose circle lies inside the domain — empty
// of the points, and of every copy, which lie outside the domain — and the periodic triangles
// whose circle is not inside, from two strips across the domain's sides (rim_of; made on two
// threads while the others test the circles). circle_inside decides for both alike, so each
// periodic triangle is in one part. Checked as the whole is: 2n triangles, every edge with its
// twin (then neighbours); nothing (the caller builds the whole) where the points have no
// triangulation of their own (collinear) or the strips would be a quarter of the domain wide.
std::optional<PeriodicTriangulation> split(std::span<const Point> points, const PeriodicDomain& d, double m,
                                           unsigned threads, bool neighbors) {
  if (!(4 * m < std::min(d.width, d.height))) return std::nullopt;
  InOrder in;
  std::vector<Duplicate> dropped;
  Triangulation p = sorted_triangulation(points, threads, in, dropped);
  if (p.size() == 0) return std::nullopt;
  const std::size_t count = p.size(), distinct = points.size() - dropped.size();
  // Whether each triangle's circle is inside (sort_out), in stretches that the threads take in
  // turn; the first two threads make the strips first (the first both, alone).
  std::vector<std::uint8_t> inside(count);
  std::atomic<std::size_t> next{0};
  Strip across_x, across_y;
  parallel_for(threads, threads, 1, [&](std::size_t w, std::size_t) {
    if (w == 0) across_x = strip(points, d, m, true);
    if (w == (threads > 1 ? 1 : 0)) across_y = strip(points, d, m, false);
    constexpr std::size_t kStretch = 16384;
    for (std::size_t a; (a = next.fetch_add(kStretch)) < count;)
      sort_out(p, in, d, inside, a, std::min(count, a + kStretch));
  });
  const auto kept = static_cast<std::size_t>(std::count(inside.begin(), inside.end(), std::uint8_t{1}));
  in.points.reset(), std::vector<std::uint32_t>().swap(in.order);  // memory for the result
  for (;;) {
    const bool verify = across_x.verify || across_y.verify;
    PeriodicTriangulation rim = rim_of(std::move(across_x), std::move(across_y));
    if (kept + rim.size() == 2 * distinct) {
      // (join takes p's arrays: whatever it finds, there is no second try)
      std::optional<PeriodicTriangulation> out = join(p, inside, std::move(rim), threads, neighbors);
      if (!out || (verify && !check_periodic(points, d, out->triangles, out->offsets).valid)) return std::nullopt;
      out->duplicates = std::move(dropped);
      return out;
    }
    m *= 2;
    if (!(4 * m < std::min(d.width, d.height))) return std::nullopt;
    across_x = strip(points, d, m, true), across_y = strip(points, d, m, false);
  }
}

// Some 2.4 times the diameter of the largest empty circle among n uniform points.
double first_margin(std::size_t points, const PeriodicDomain& d) {
  const auto n = static_cast<double>(points);
  return 2.4 * std::sqrt(d.width * d.height * std::log(n + 2) / (3.14159 * n));
}

}  // namespace

std::optional<PeriodicTriangulation> triangulate_periodic_split(std::span<const Point> points,
                                                                const PeriodicDomain& domain, unsigned threads,
                                                                bool neighbors) {
  check_input(points, domain);
  return split(points, domain, first_margin(points.size(), domain), thread_count(threads), neighbors);
}

PeriodicTriangulation triangulate_periodic_whole(std::span<const Point> points, const PeriodicDomain& domain,
                                                 unsigned threads) {
  check_input(points, domain);
  double m = first_margin(points.size(), domain);
  const double limit = 64 * std::max(domain.width, domain.height);
  Builder builder(points, domain, thread_count(threads));
  while (!builder.attempt(m))
    if (m > limit) throw std::logic_error("ridt: periodic triangulation: the margin grew past 64 periods");
  return builder.take();
}

}  // namespace detail

PeriodicTriangulation triangulate_periodic(std::span<const Point> points, const PeriodicDomain& domain,
                                           const PeriodicOptions& options) {
  using namespace detail;
  std::optional<PeriodicTriangulation> t;
  if (points.size() >= kSplitPoints) t = triangulate_periodic_split(points, domain, options.threads, options.neighbors);
  if (!t) t = triangulate_periodic_whole(points, domain, options.threads);
  if (!options.neighbors)
    std::vector<std::int32_t>().swap(t->neighbors), std::vector<Offset>().swap(t->neighbor_offsets);
  return std::move(*t);
}

PeriodicTriangulation triangulate_periodic(std::span<const Point> points, const PeriodicDomain& domain,
                                           unsigned threads) {
  return triangulate_periodic(points, domain, PeriodicOptions{threads, true});
}

}  // namespace ridt
