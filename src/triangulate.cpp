// The public entry point: checks the input and the options, orders and copies the points, runs
// the chosen method on the chosen kernel and finishes.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <string>

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "methods/method.hpp"
#include "order/order.hpp"
#include "output/output.hpp"
#include "predicates/predicates.hpp"
#include "ridt/ridt.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"
#include "tds/delaunay.hpp"

namespace ridt {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The options made definite: the method chosen, threads counted, the location chosen. Throws
// InputError for a combination that cannot run, saying why.
struct Plan {
  const detail::MethodEntry* method = nullptr;
  unsigned threads = 1;
  bool walk = false;
  bool from_root = false;  // Locate::Root: the DAG, each descent from its root
  bool brio = false;
  bool symbolic = true;
  bool canonical = false;  // Options::canonical_order
};

// Method::Auto: serial on one thread (and for the profile, which times the serial method); on
// more, partition where the location may walk and the order lets it (walking asked for: it
// says what the order lacks), else optimistic.
Method choose(Method method, unsigned threads, const Options& options) {
  if (method != Method::Auto) return method;
  if (threads == 1 || options.experiment.profile) return Method::Serial;
  const bool brio_walk = options.order == Order::Brio && options.locate == Locate::Auto;
  return brio_walk || options.locate == Locate::Walk ? Method::Partition : Method::Optimistic;
}

// "serial or partition": the methods that walk, for a message.
std::string walking_methods() {
  std::string list;
  for (const detail::MethodEntry& m : detail::methods())
    if (m.walk != nullptr) list += std::string(list.empty() ? "" : " and ") + std::string(to_string(m.method));
  return list;
}

// Where the method walks and where it descends the DAG, from the location asked for.
void plan_location(Plan& p, const Options& options) {
  const detail::MethodEntry& m = *p.method;
  const std::string name(to_string(m.method));
  switch (options.locate) {
    case Locate::Auto:
      p.walk = m.walk != nullptr && (p.brio || m.dag == nullptr);
      break;
    case Locate::Dag:
      p.walk = false;
      break;
    case Locate::Walk:
      p.walk = true;
      break;
    case Locate::Root:
      p.from_root = true;
      break;
  }
  if (m.dag == nullptr) {
    if (p.from_root)
      throw InputError("the " + name + " method keeps no DAG to descend from its root (use --locate walk or auto)");
    if (!p.brio)
      throw InputError("the " + name +
                       " method needs the BRIO order: its threads own stretches of each round's "
                       "curve (use --order brio)");
    if (!p.walk) throw InputError("the " + name + " method keeps no DAG: it walks (use --locate walk or auto)");
  } else if (p.walk && m.walk == nullptr) {
    throw InputError("walking location works with the " + walking_methods() +
                     " methods only: the paper's "
                     "threaded methods locate points while others insert, by descending the history DAG, whose "
                     "nodes never change (use --locate dag)");
  }
  if (p.walk && !p.brio)
    throw InputError(
        "walking location needs the BRIO order: in random order each walk crosses about sqrt(n) "
        "triangles (use --order brio)");
}

Plan plan(std::size_t n, const Options& options) {
  Plan p;
  // Three bounding vertices follow the points, and ids must stay below kIdMask.
  if (n > 0x7ffffff0u) throw InputError("too many points (at most 2^31 - 16)");
  p.symbolic = options.experiment.bounding == Bounding::Symbolic;
  p.canonical = options.canonical_order;
  p.brio = options.order == Order::Brio;
  const unsigned threads = detail::thread_count(options.threads);
  p.method = &detail::method_entry(choose(options.method, threads, options));
  if (p.method->threaded) p.threads = threads;
  if (p.threads > kMaxThreads)
    throw InputError("at most " + std::to_string(kMaxThreads) + " threads (got " + std::to_string(p.threads) + ")");
  if (options.experiment.profile && p.method->threaded)
    throw InputError("profiling (Fig. 8) times the serial method only");
  plan_location(p, options);
  if (!p.symbolic && !(options.experiment.k >= 2))
    throw InputError("the finite bounding triangle needs k >= 2 (got " + std::to_string(options.experiment.k) + ")");
  return p;
}

// Bytes a point at the call's peak, the result included, as measured at 10^6 and 10^7 uniform
// points (the process's peak resident memory less its input, docs/design.md#memory): the
// walking kernel and its finish, the canonical order after it (the result's arrays, the
// triangles in buckets, each one's new number, and the blocks the memory cache keeps
// for the next call), and the history DAG (its records are never freed during the run), with
// 10 % over the largest seen. Each thread adds its own buffers.
constexpr double kWalkBytesPerPoint = 94;  // 85 measured (serial walk and partition alike)
constexpr double kWalkCanonicalBytesPerPoint = 109;  // 99 measured
constexpr double kDagBytesPerPoint = 307;  // 279 measured (every DAG method alike)
constexpr std::size_t kBytesPerThread = std::size_t{8} << 20;
constexpr std::size_t kFixedBytes = std::size_t{32} << 20;

std::size_t estimate(const Plan& p, std::size_t n) {
  const double per_point = !p.walk ? kDagBytesPerPoint : p.canonical ? kWalkCanonicalBytesPerPoint : kWalkBytesPerPoint;
  return static_cast<std::size_t>(per_point * static_cast<double>(n)) + kFixedBytes + p.threads * kBytesPerThread;
}

// Throws MemoryError, before anything large is allocated, when the plan needs more than the
// limit (the options' or what the system can give); names what would fit where walking would.
void check_memory(const Plan& p, std::size_t n, const Options& options) {
  const std::size_t limit = detail::memory_room(options.memory_limit);
  const std::size_t needed = estimate(p, n);
  if (limit == 0 || needed <= limit) return;
  std::string what = "triangulating " + std::to_string(n) + " points with the " +
      std::string(to_string(p.method->method)) + " method (" + (p.walk ? "walking" : "the history DAG") +
      ") needs about " + detail::gigabytes(needed) + "; " + detail::gigabytes(limit) + " is available";
  Plan walking = p;
  walking.walk = true;
  if (!p.walk && estimate(walking, n) <= limit)
    what += " (the walking methods, serial or partition with the BRIO order, need about " +
        detail::gigabytes(estimate(walking, n)) + ")";
  throw MemoryError(what, needed, limit);
}

// The points in insertion order (vertex v is input point order[v]), scaled by 2^scale, then
// the three bounding vertices. Inserting them from a copy in that order keeps the points that
// successive insertions read close together in memory.
detail::Block<Point> copy_in_order(std::span<const Point> points, const std::vector<std::uint32_t>& order, int scale,
                                   unsigned threads) {
  const std::size_t n = points.size();
  auto pts = detail::allocate_huge<Point>(n + 3);
  detail::parallel_for(n, threads, 65536, [&](std::size_t first, std::size_t last) {
    // The reads are at random: one some way ahead is asked for first, so that misses overlap
    // (some 13 % off this loop at 10^6 points).
    constexpr std::size_t kAhead = 16;
    for (std::size_t v = first; v < last; ++v) {
      if (v + kAhead < last) __builtin_prefetch(&points[order[v + kAhead]]);
      const Point& p = points[order[v]];
      pts[v] = scale == 0 ? p : Point{std::ldexp(p.x, scale), std::ldexp(p.y, scale)};
    }
  });
  pts[n] = pts[n + 1] = pts[n + 2] = detail::Vertices::kBoundingNaN;  // symbolic (finite: placed later)
  return pts;
}

// The paper's (K, 0), (0, K), (-K, -K) around the centre of the points' box, K = k * M, into
// pts[n .. n+2]; every point must lie strictly inside.
void place_finite_bounding(Point* pts, std::uint32_t n, const std::vector<std::uint32_t>& order, double k_factor) {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  if (n > 0) x0 = x1 = pts[0].x, y0 = y1 = pts[0].y;
  for (std::uint32_t v = 0; v < n; ++v) {
    x0 = std::min(x0, pts[v].x), x1 = std::max(x1, pts[v].x);
    y0 = std::min(y0, pts[v].y), y1 = std::max(y1, pts[v].y);
  }
  // M is the box's size, but at least 2^-40 of the largest coordinate and at least 2^-960
  // (far above the subnormals): a box that is a single point, or flat far from the origin,
  // would otherwise give a K that rounds away beside the coordinates (or to 0), and a
  // triangle through the points.
  const double far = std::max({std::fabs(x0), std::fabs(x1), std::fabs(y0), std::fabs(y1)});
  const double m = std::max({x1 - x0, y1 - y0, far * 0x1p-40, 0x1p-960});
  const double cx = x0 / 2 + x1 / 2, cy = y0 / 2 + y1 / 2, k = k_factor * m;
  const Point b[3] = {{cx + k, cy}, {cx, cy + k}, {cx - k, cy - k}};
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(b[i].x) || !std::isfinite(b[i].y))
      throw InputError("the finite bounding triangle overflows for these coordinates");
    pts[n + i] = b[i];
  }
  for (std::uint32_t v = 0; v < n; ++v)
    for (int i = 0; i < 3; ++i)
      if (detail::orient2d(b[i], b[(i + 1) % 3], pts[v]) <= 0)
        throw InputError("the finite bounding triangle does not enclose point " + std::to_string(order[v]) +
                         "; use the symbolic one");
}

// The history DAG's kernel and the method that drives it.
Triangulation run_dag(detail::Block<Point> pts, std::uint32_t n, const std::vector<std::uint32_t>& order,
                      const Plan& plan, const Options& options, Stats& stats) {
  detail::Kernel kernel(std::move(pts), n, plan.symbolic, plan.brio);
  std::vector<detail::DuplicateHit> duplicates;
  detail::Progress progress(options.progress, n);
  const auto t0 = Clock::now();
  plan.method->dag(kernel, {plan.threads, plan.from_root, options.experiment, nullptr, duplicates, stats, progress});
  stats.time_insert_s = since(t0);
  if (options.progress) options.progress(1.0);
  const auto t1 = Clock::now();
  Triangulation out = detail::finish(kernel, order, duplicates, options, plan.threads);
  stats.time_finish_s = since(t1);
  return out;
}

// The walking kernel and the method that drives it (`keys`: each vertex's Hilbert key, in
// insertion order, where the method asked for them).
Triangulation run_walking(detail::Block<Point>& pts, std::uint32_t n, const std::vector<std::uint32_t>& order,
                          std::vector<std::uint32_t> keys, detail::SlotArrays arrays, const Plan& plan,
                          const Options& options, Stats& stats, bool links, bool keep_points) {
  detail::DelaunayTds tds(detail::Vertices(pts.get(), n, plan.symbolic), std::move(arrays));
  std::vector<detail::DuplicateHit> duplicates;
  detail::Progress progress(options.progress, n);
  const auto t0 = Clock::now();
  plan.method->walk(tds, {plan.threads, false, options.experiment, keys.data(), duplicates, stats, progress});
  stats.time_insert_s = since(t0);
  if (options.progress) options.progress(1.0);
  const auto t1 = Clock::now();
  if (plan.symbolic && !keep_points) pts.reset();  // the finish reads no point: the copy goes before it
  Triangulation out = detail::finish_walking(tds, order, duplicates, options, plan.threads, links);
  stats.time_finish_s = since(t1);
  return out;
}

// The insertion order (vertex v is input point order[v]) and, for the partition method, each
// vertex's Hilbert key in that order. `slots`, when given, is the walking kernel's memory, made
// before the order so that the order's work needs no fresh pages.
std::vector<std::uint32_t> insertion_order(std::span<const Point> points, const detail::Extent& extent, const Plan& p,
                                           const Options& options, std::vector<std::uint32_t>& keys,
                                           detail::SlotArrays* slots) {
  const auto n = static_cast<std::uint32_t>(points.size());
  if (!p.brio) return detail::random_permutation(n, options.seed);
  detail::OrderScratch scratch;
  if (slots != nullptr) scratch = {slots->words(), slots->numbers()};
  std::vector<std::uint32_t> order =
      detail::brio_order(points.data(), n, options.seed, p.threads, p.method->keys ? &keys : nullptr, scratch, &extent);
#ifdef __GLIBC__
  // The order's buffers (its own, where no kernel lends it memory, and the cells' small ones),
  // freed, may stay with the allocator (glibc keeps freed blocks below its mmap threshold,
  // which a first large block raises): given back now, they do not add to the peak that the
  // kernel sets.
  malloc_trim(0);
#endif
  return order;
}

// 0, 1, ..., n - 1.
std::vector<std::uint32_t> places_of(std::uint32_t n, unsigned threads) {
  std::vector<std::uint32_t> places;
  detail::resize_present(places, n, threads);
  detail::parallel_for(n, threads, 65536, [&](std::size_t first, std::size_t last) {
    std::iota(places.begin() + static_cast<std::ptrdiff_t>(first), places.begin() + static_cast<std::ptrdiff_t>(last),
              static_cast<std::uint32_t>(first));
  });
  return places;
}

// The insertion order and the points in it: the kernel's copy `pts` where it is the points as
// given, else (scaled; or taken by the DAG's kernel) a copy made here.
detail::InOrder in_order_of(std::span<const Point> points, std::vector<std::uint32_t> order, detail::Block<Point> pts,
                            int scale, unsigned threads) {
  if (!pts || scale != 0) {
    pts = detail::allocate_huge<Point>(points.size() + 3);
    detail::parallel_for(points.size(), threads, 65536, [&](std::size_t first, std::size_t last) {
      for (std::size_t v = first; v < last; ++v) pts[v] = points[order[v]];
    });
  }
  return {std::move(order), std::move(pts)};
}

// The insertion's stats in the result, with the counts that the finish made.
void merge_stats(Triangulation& out, Stats stats) {
  if (stats.per_thread.empty()) stats.per_thread.push_back({"worker", out.stats.points, stats.time_insert_s, 0, 0, 0});
  stats.points = out.stats.points;
  stats.distinct = out.stats.distinct;
  stats.duplicates = out.stats.duplicates;
  stats.dag_nodes = out.stats.dag_nodes;
  out.stats = std::move(stats);
}

// triangulate(), its neighbours links where `links` asks and the walking kernel can (`linked`);
// with `in_order`, the vertices numbered by their places in the insertion order, which comes
// back in it with the points in that order.
Triangulation run(std::span<const Point> points, const Options& options, bool links, bool& linked,
                  detail::InOrder* in_order = nullptr) {
  const auto t0 = Clock::now();
  const Plan p = plan(points.size(), options);
  check_memory(p, points.size(), options);
  const auto n = static_cast<std::uint32_t>(points.size());
  Stats stats;
  auto phase = Clock::now();
  const auto lap = [&phase](double& seconds) {
    const auto now = Clock::now();
    seconds = std::chrono::duration<double>(now - phase).count();
    phase = now;
  };
  const detail::Extent extent = detail::checked_extent(points, p.threads);
  lap(stats.time_scan_s);
  // Huge or tiny coordinates: the kernel works on copies scaled by 2^scale (predicates/predicates.hpp).
  const int scale = detail::exact_scale_exponent(extent);
  std::optional<detail::SlotArrays> slots;
  if (p.walk) slots.emplace(n, p.threads);
  lap(stats.time_mesh_s);
  std::vector<std::uint32_t> keys;
  std::vector<std::uint32_t> order = insertion_order(points, extent, p, options, keys, slots ? &*slots : nullptr);
  // The finish writes each vertex as ids[v]: its input index, or its place.
  const std::vector<std::uint32_t> places =
      in_order != nullptr ? places_of(n, p.threads) : std::vector<std::uint32_t>{};
  const std::vector<std::uint32_t>& ids = in_order != nullptr ? places : order;
  lap(stats.time_order_s);
  detail::Block<Point> pts = copy_in_order(points, order, scale, p.threads);
  if (!p.symbolic) place_finite_bounding(pts.get(), n, order, options.experiment.k);
  lap(stats.time_copy_s);

  stats.threads = p.threads;
  stats.method = p.method->method;
  stats.locate = p.walk ? Locate::Walk : p.from_root ? Locate::Root : Locate::Dag;
  stats.memory_estimate = estimate(p, n);
  linked = links && p.walk && !options.canonical_order;
  Triangulation out = p.walk
      ? run_walking(pts, n, ids, std::move(keys), std::move(*slots), p, options, stats, linked, in_order != nullptr)
      : run_dag(std::move(pts), n, ids, p, options, stats);
  if (in_order != nullptr) *in_order = in_order_of(points, std::move(order), std::move(pts), scale, p.threads);
  // After the kernel is gone, so that the sort's copies do not raise the peak.
  phase = Clock::now();
  detail::apply_output_options(out, options, p.threads);
  lap(stats.time_canonical_s);
  merge_stats(out, std::move(stats));
  out.stats.time_triangulate_s = since(t0);
  return out;
}

}  // namespace

namespace detail {

Triangulation triangulate_linked(std::span<const Point> points, const Options& options, bool& linked) {
  return run(points, options, true, linked);
}

Triangulation triangulate_in_order(std::span<const Point> points, const Options& options, InOrder& order) {
  bool linked = false;
  return run(points, options, false, linked, &order);
}

}  // namespace detail

Triangulation triangulate(std::span<const Point> points, const Options& options) {
  bool linked = false;
  return run(points, options, false, linked);
}

std::size_t estimate_memory(std::size_t n, const Options& options) { return estimate(plan(n, options), n); }

Triangulation triangulate(std::span<const double> xy, const Options& options) {
  if (xy.size() % 2 != 0)
    throw InputError("a flat coordinate array needs an even size (got " + std::to_string(xy.size()) + ")");
  std::vector<Point> points(xy.size() / 2);
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = {xy[2 * i], xy[2 * i + 1]};
  return triangulate(std::span<const Point>(points), options);
}

}  // namespace ridt
