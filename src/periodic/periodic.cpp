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
// of those. The rest have circles that cross the domain's sides: at most the largest circle's
// diameter from them, so they are the whole way's triangles over the points within m of the
// sides (a band, some 4 m / side of the points) whose circles are not inside and at most m
// across. One test (circle_inside), on the same arguments, sorts the triangles of both, so each
// periodic triangle comes once; the two parts are joined by the twins of the edges between
// them, and checked as the whole way's are.
//
// Both stand on exact predicates of the copies' true coordinates (predicates/shifted.hpp);
// only where a circle lies is measured in rounded arithmetic, with room for its rounding, and
// where that room alone leaves a circle in doubt the result is checked by the exact validator.
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

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

// From this many points on, the Delaunay triangulation of the points and a band (split).
constexpr std::size_t kSplitPoints = 4096;

// The ends of a directed edge and the offset from its tail to its head: the key its twin is
// found by (the twin runs back, the offset negated).
struct EdgeKey {
  VertexId tail, head;
  std::int32_t dx, dy;
  friend bool operator==(const EdgeKey&, const EdgeKey&) = default;
};
struct EdgeKeyHash {
  std::size_t operator()(const EdgeKey& e) const {
    return mix64((std::uint64_t{e.tail} << 32 | e.head) ^
                 mix64(std::uint64_t(std::uint32_t(e.dx)) << 32 | std::uint32_t(e.dy)));
  }
};

// The two parts as one: first the triangles of `p` whose id is not -1 (their least corner
// first, at offset 0; neighbours from p's where those are kept too), then the rim's. Every
// other neighbour is found through its edge's twin; nothing where one has none, or several.
std::optional<PeriodicTriangulation> join(Triangulation& p, const std::vector<std::uint32_t>& input,
                                          const std::vector<std::uint8_t>& first, const std::vector<std::int32_t>& id,
                                          std::size_t inner, PeriodicTriangulation rim, unsigned threads) {
  const std::size_t total = inner + rim.size(), count = id.size();
  PeriodicTriangulation out;
  out.domain = rim.domain;
  // Written over p's arrays (kept triangle id[k] <= k), made for the 2n + 1 slots of n points.
  out.triangles = std::move(p.triangles), out.neighbors = std::move(p.neighbors);
  for (std::size_t k = 0; k < count; ++k) {
    if (id[k] < 0) continue;
    const auto g = static_cast<std::size_t>(id[k]);
    VertexId t[3];
    std::int32_t u[3];
    for (std::size_t j = 0; j < 3; ++j) {
      const std::size_t i = 3 * k + (first[k] + j) % 3;
      t[j] = input[out.triangles[i]],
      u[j] = out.neighbors[i] >= 0 ? id[static_cast<std::size_t>(out.neighbors[i])] : -1;
    }
    for (std::size_t j = 0; j < 3; ++j) out.triangles[3 * g + j] = t[j], out.neighbors[3 * g + j] = u[j];
  }
  out.triangles.resize(3 * total), out.neighbors.resize(3 * total);
  resize_present(out.offsets, 3 * total, threads), resize_present(out.neighbor_offsets, 3 * total, threads);
  std::copy(rim.triangles.begin(), rim.triangles.end(), out.triangles.begin() + 3 * inner);
  std::copy(rim.offsets.begin(), rim.offsets.end(), out.offsets.begin() + 3 * inner);
  std::fill(out.neighbors.begin() + 3 * inner, out.neighbors.end(), -1);
  // The edges without a neighbour yet, and their table.
  auto key = [&](std::size_t e) {
    const std::size_t b = e - e % 3, t = b + (e + 1) % 3, h = b + (e + 2) % 3;
    return EdgeKey{out.triangles[t], out.triangles[h], out.offsets[h].dx - out.offsets[t].dx,
                   out.offsets[h].dy - out.offsets[t].dy};
  };
  std::vector<std::size_t> open;
  for (std::size_t e = 0; e < 3 * total; ++e)
    if (out.neighbors[e] < 0) open.push_back(e);
  std::unordered_map<EdgeKey, std::size_t, EdgeKeyHash> table(2 * open.size());
  for (const std::size_t e : open)
    if (!table.emplace(key(e), e).second) return std::nullopt;
  for (const std::size_t e : open) {
    const EdgeKey k = key(e);
    const auto found = table.find({k.head, k.tail, -k.dx, -k.dy});
    if (found == table.end()) return std::nullopt;
    const std::size_t f = found->second, head = e - e % 3 + (e + 2) % 3, tail = f - f % 3 + (f + 1) % 3;
    out.neighbors[e] = static_cast<std::int32_t>(f / 3);
    out.neighbor_offsets[e] = {out.offsets[head].dx - out.offsets[tail].dx,
                               out.offsets[head].dy - out.offsets[tail].dy};
  }
  return out;
}

// The points' Delaunay triangulation with vertex i the point input[i]: triangulate() of the
// points in Hilbert order (BRIO's), so that what reads the triangles' corners reads memory in
// order; a group of equal points stands as its least input index. The duplicates in `dropped`.
Triangulation sorted_triangulation(std::span<const Point> points, unsigned threads, std::vector<std::uint32_t>& input,
                                   std::vector<Point>& sorted, std::vector<Duplicate>& dropped) {
  const auto n = static_cast<VertexId>(points.size());
  input = brio_order(points.data(), n, 0x5eed, threads);
  resize_present(sorted, n, threads);
  parallel_for(n, threads, 65536, [&](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) sorted[i] = points[input[i]];
  });
  Options options;
  options.threads = threads;
  Triangulation p = triangulate(sorted, options);
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

// The periodic triangulation as two parts that do not meet: the triangles of the points' own
// Delaunay triangulation (triangulate(), on threads) whose circle lies inside the domain — empty
// of the points, and of every copy, which lie outside the domain — and the periodic triangles
// whose circle is not inside, from the points within m of the domain's sides and their copies
// (Builder's band). circle_inside decides for both alike, so each periodic triangle is in one
// part. Checked as the whole is: 2n triangles, every edge with its twin (then neighbours);
// nothing (the caller builds the whole) where the points have no triangulation of their own
// (collinear) or the band would be a quarter of the domain.
std::optional<PeriodicTriangulation> split(std::span<const Point> points, const PeriodicDomain& d, double m,
                                           unsigned threads) {
  std::vector<std::uint32_t> input;
  std::vector<Point> sorted;
  std::vector<Duplicate> dropped;
  Triangulation p = sorted_triangulation(points, threads, input, sorted, dropped);
  if (p.size() == 0) return std::nullopt;
  const std::size_t count = p.size(), distinct = points.size() - dropped.size();
  // Each triangle's least corner (its rotation) and whether its circle is inside: on threads.
  std::vector<std::uint8_t> first(count), inside(count);
  parallel_for(count, threads, 16384, [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      const VertexId* t = &p.triangles[3 * k];
      const VertexId a = input[t[0]], b = input[t[1]], c = input[t[2]];
      const int low = a < b ? (a < c ? 0 : 2) : (b < c ? 1 : 2);
      first[k] = static_cast<std::uint8_t>(low);
      inside[k] = circle_inside(sorted[t[low]], sorted[t[(low + 1) % 3]], sorted[t[(low + 2) % 3]], d);
    }
  });
  std::vector<std::int32_t> id(count, -1);
  std::int32_t kept = 0;
  for (std::size_t k = 0; k < count; ++k)
    if (inside[k]) id[k] = kept++;
  std::vector<Point>().swap(sorted), std::vector<std::uint8_t>().swap(inside);  // memory for the result
  while (4 * m < std::min(d.width, d.height)) {
    std::vector<VertexId> band;
    for (VertexId i = 0; i < points.size(); ++i) {
      const double x = points[i].x - d.origin.x, y = points[i].y - d.origin.y, reach = m * (1 + 0x1p-20);
      if (x < reach || d.width - x < reach || y < reach || d.height - y < reach) band.push_back(i);
    }
    Builder b(points, d, threads, band);
    if (!b.band(m)) continue;  // m grown
    PeriodicTriangulation rim = b.take();
    if (static_cast<std::size_t>(kept) + rim.size() == 2 * distinct) {
      // (join takes p's arrays: whatever it finds, there is no second try)
      std::optional<PeriodicTriangulation> out =
          join(p, input, first, id, static_cast<std::size_t>(kept), std::move(rim), threads);
      if (!out || (b.verify() && !check_periodic(points, d, out->triangles, out->offsets).valid)) return std::nullopt;
      out->duplicates = std::move(dropped);
      return out;
    }
    m *= 2;
  }
  return std::nullopt;
}

// Some 2.4 times the diameter of the largest empty circle among n uniform points.
double first_margin(std::size_t points, const PeriodicDomain& d) {
  const auto n = static_cast<double>(points);
  return 2.4 * std::sqrt(d.width * d.height * std::log(n + 2) / (3.14159 * n));
}

}  // namespace

std::optional<PeriodicTriangulation> triangulate_periodic_split(std::span<const Point> points,
                                                                const PeriodicDomain& domain, unsigned threads) {
  check_input(points, domain);
  return split(points, domain, first_margin(points.size(), domain), thread_count(threads));
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
                                           unsigned threads) {
  using namespace detail;
  if (points.size() >= kSplitPoints)
    if (std::optional<PeriodicTriangulation> t = triangulate_periodic_split(points, domain, threads))
      return std::move(*t);
  return triangulate_periodic_whole(points, domain, threads);
}

}  // namespace ridt
