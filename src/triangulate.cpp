// The public entry point: checks the input, sets up the bounding triangle, runs the chosen
// method and finishes.
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <thread>
#include <algorithm>

#include "driver.hpp"
#include "order.hpp"
#include "predicates.hpp"
#include "ridt/ridt.hpp"

namespace ridt {

Triangulation triangulate(std::span<const Point> points, const Options& options) {
  const auto t0 = std::chrono::steady_clock::now();
  // Three bounding vertices follow the points, and ids must stay below kIdMask.
  if (points.size() > 0x7ffffff0u) throw InputError("too many points (at most 2^31 - 16)");
  const auto n = static_cast<std::uint32_t>(points.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    const Point& p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw InputError("point " + std::to_string(i) + " has a " +
                       (std::isnan(p.x) || std::isnan(p.y) ? "NaN" : "infinite") + " coordinate");
  }
  // Huge or tiny coordinates: the kernel works on copies scaled by 2^scale (predicates.hpp).
  const int scale = detail::exact_scale_exponent(points);
  const bool symbolic = options.bounding == Bounding::Symbolic;
  unsigned threads = 1;
  if (options.method != Method::Serial) {
    threads = options.threads != 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    // Optimistic owners are numbered 1 .. kMaxOwner (mesh.hpp).
    if (threads > detail::kMaxOwner)
      throw InputError("at most " + std::to_string(detail::kMaxOwner) + " threads (got " +
                       std::to_string(threads) + ")");
  }
  if (options.profile && options.method != Method::Serial)
    throw InputError("profiling (Fig. 8) times the serial method only");
  const bool walk = options.locate == Locate::Walk;
  if (walk && options.method != Method::Serial)
    throw InputError("walking location works with the serial method only: the threaded methods "
                     "locate points while others insert, by descending the history DAG, whose "
                     "nodes never change (use --locate dag)");
  if (walk && options.order != Order::Brio)
    throw InputError("walking location needs the BRIO order: in random order each walk "
                     "crosses about sqrt(n) triangles (use --order brio)");
  if (!symbolic && !(options.k >= 2))
    throw InputError("the finite bounding triangle needs k >= 2 (got " +
                     std::to_string(options.k) + ")");

  // The mesh numbers vertices in insertion order: vertex v is input point order[v]. Then the
  // points met near the root of the DAG, inserted early, lie close together in memory, and in
  // the BRIO order successive points too.
  const bool brio = options.order == Order::Brio;
  const std::vector<std::uint32_t> order =
      brio ? detail::brio_order(points.data(), n, options.seed, threads)
           : detail::random_permutation(n, options.seed);
  auto pts = detail::allocate_huge<Point>(std::size_t{n} + 3);
  if (scale == 0) {
    for (std::uint32_t v = 0; v < n; ++v) pts[v] = points[order[v]];
  } else {
    for (std::uint32_t v = 0; v < n; ++v)
      pts[v] = {std::ldexp(points[order[v]].x, scale), std::ldexp(points[order[v]].y, scale)};
  }
  if (symbolic) {
    pts[n] = pts[n + 1] = pts[n + 2] = Point{};  // never read: decided combinatorially
  } else {
    // The paper's (K, 0), (0, K), (-K, -K) around the centre of the bounding box, K = k * M.
    // The box of the (possibly scaled) points.
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
    const double cx = x0 / 2 + x1 / 2, cy = y0 / 2 + y1 / 2, k = options.k * m;
    const Point b[3] = {{cx + k, cy}, {cx, cy + k}, {cx - k, cy - k}};
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(b[i].x) || !std::isfinite(b[i].y))
        throw InputError("the finite bounding triangle overflows for these coordinates");
      pts[n + i] = b[i];
    }
    // Every point strictly inside, exactly, or the kernel's premise fails.
    for (std::uint32_t v = 0; v < n; ++v)
      for (int i = 0; i < 3; ++i)
        if (detail::orient2d(b[i], b[(i + 1) % 3], pts[v]) <= 0)
          throw InputError("the finite bounding triangle does not enclose point " +
                           std::to_string(order[v]) + "; use the symbolic one");
  }

  Triangulation out;
  Stats stats;
  {
    detail::Kernel kernel(std::move(pts), n, symbolic, brio, /*history=*/!walk);
    std::vector<detail::DuplicateHit> duplicates;
    detail::Progress progress(options.progress, n);
    const auto t_insert = std::chrono::steady_clock::now();
    switch (options.method) {
      case Method::Serial:
        detail::insert_serial(kernel, options.profile, duplicates, stats, progress);
        break;
      case Method::Pessimistic:
        stats.threads = threads;
        detail::insert_pessimistic(kernel, threads, options.paper_locking, options.time_threads,
                                   duplicates, stats, progress);
        break;
      case Method::Optimistic:
        stats.threads = threads;
        detail::insert_optimistic(kernel, threads, options.time_threads, duplicates, stats, progress);
        break;
      case Method::Batch:
        stats.threads = threads;
        detail::insert_batch(kernel, threads, duplicates, stats, progress);
        break;
    }
    stats.time_insert_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t_insert).count();
    if (stats.per_thread.empty()) stats.per_thread.push_back({"worker", n, stats.time_insert_s, 0, 0, 0});
    if (options.progress) options.progress(1.0);
    out = detail::finish(kernel, order, duplicates, options, threads);
  }
  // After the DAG is gone, so that the sort's copies do not raise the peak.
  if (options.canonical_order) detail::canonicalize(out);
  // The finish counts the points, duplicates and DAG nodes; the insertion, everything else.
  stats.points = out.stats.points;
  stats.distinct = out.stats.distinct;
  stats.duplicates = out.stats.duplicates;
  stats.dag_nodes = out.stats.dag_nodes;
  out.stats = std::move(stats);
  out.stats.time_triangulate_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

Triangulation triangulate(std::span<const double> xy, const Options& options) {
  if (xy.size() % 2 != 0)
    throw InputError("a flat coordinate array needs an even size (got " +
                     std::to_string(xy.size()) + ")");
  std::vector<Point> points(xy.size() / 2);
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = {xy[2 * i], xy[2 * i + 1]};
  return triangulate(std::span<const Point>(points), options);
}

}  // namespace ridt
