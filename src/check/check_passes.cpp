// The validator in passes (ridt/check.hpp check_in_passes): what check() asks, of triangles
// read again for each pass instead of held with a table of all their sides.
//
// The first pass checks each triangle (its indices, its orientation), marks its vertices and
// counts the sides filed under each vertex (a side's smaller end). The vertices are then cut
// into ranges whose sides fit the budget, and each range takes a pass: its sides are filed
// there (a counting sort by the smaller end, then by the larger one within each file), the two
// sides of an interior edge meet for the in-circle test, and a side alone is on the boundary.
// The convex hull is that of the few points not strictly inside the polygon of some extreme
// points (Akl and Toussaint's filter), exact orientation deciding. A point that no triangle
// uses must equal one that some triangle does. Two vertices at one point need no test of their
// own: with every triangle counter-clockwise, every edge matched and the boundary the hull,
// the triangles cover the hull once, so no point can be in two stars.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "check/parts.hpp"
#include "predicates/predicates.hpp"
#include "ridt/check.hpp"
#include "runtime/parallel.hpp"

namespace ridt {
namespace {

using detail::Edge;
using detail::incircle;
using detail::InOrder;
using detail::lex_less;
using detail::orient2d;
using detail::Report;

// A feed that breaks its promise (a file changed between passes, say).
constexpr const char* kChanged = "check_in_passes: the triangles changed from one pass to the next";

// One side of a triangle, filed under its smaller end lo.
struct Side {
  VertexId hi;
  VertexId opposite;  // the triangle's third corner
  std::uint32_t forward;  // 1 where the triangle runs lo -> hi
};

// The first pass: every index in range, every triangle counter-clockwise and not degenerate,
// the vertices marked, and the sides filed under each vertex counted (in files[v + 1]).
std::size_t first_pass(std::span<const Point> pts, const TriangleFeed& feed, std::vector<std::uint8_t>& used,
                       std::vector<std::uint32_t>& files, unsigned threads, Report& report) {
  const std::size_t n = pts.size();
  std::size_t count = 0;
  feed([&](std::span<const VertexId> tris) {
    if (tris.size() % 3 != 0) report.problem("a chunk of triangles is not a multiple of 3 long");
    const std::size_t k = tris.size() / 3;
    InOrder<Report> reports;
    detail::parallel_for(k, threads, 1 << 14, [&](std::size_t first, std::size_t last) {
      Report r;
      for (std::size_t t = first; t < last; ++t) {
        const VertexId* v = &tris[3 * t];
        if (v[0] >= n || v[1] >= n || v[2] >= n) {
          r.problem("triangle ", count + t, " has a vertex index out of range");
          continue;
        }
        if (orient2d(pts[v[0]], pts[v[1]], pts[v[2]]) <= 0)
          r.problem("triangle ", count + t, " (", v[0], " ", v[1], " ", v[2],
                    ") is not counter-clockwise or is degenerate");
      }
      reports.put(first, std::move(r));
    });
    for (const Report& r : reports.take()) report.merge(r);
    // The marks and counts, atomic: triangles on two threads may share a vertex.
    detail::parallel_for(k, threads, 1 << 14, [&](std::size_t first, std::size_t last) {
      for (std::size_t t = first; t < last; ++t) {
        const VertexId* v = &tris[3 * t];
        if (v[0] >= n || v[1] >= n || v[2] >= n) continue;
        for (int i = 0; i < 3; ++i) {
          std::atomic_ref<std::uint8_t>(used[v[i]]).store(1, std::memory_order_relaxed);
          std::atomic_ref<std::uint32_t>(files[std::min(v[i], v[i == 2 ? 0 : i + 1]) + 1])
              .fetch_add(1, std::memory_order_relaxed);
        }
      }
    });
    count += k;
  });
  return count;
}

// The sides filed under the vertices [lo, hi), in the files that `files` begin (from lo's, then
// where they all end), which then each hold where the next one begins. On threads, each side's
// place taken atomically: the order within a file is the threads' race, which a sort undoes.
std::vector<Side> file_sides(const TriangleFeed& feed, std::size_t count, VertexId lo, VertexId hi,
                             std::vector<std::size_t>& files, unsigned threads) {
  std::vector<Side> sides(files.back());
  std::size_t again = 0;
  feed([&](std::span<const VertexId> tris) {
    detail::parallel_for(tris.size() / 3, threads, 1 << 14, [&](std::size_t first, std::size_t last) {
      for (std::size_t k = 3 * first; k < 3 * last; k += 3)
        for (int i = 0; i < 3; ++i) {
          const VertexId a = tris[k + i], b = tris[k + (i + 1) % 3];
          const VertexId least = std::min(a, b);
          if (least >= lo && least < hi) {
            const std::size_t at =
                std::atomic_ref<std::size_t>(files[least - lo]).fetch_add(1, std::memory_order_relaxed);
            if (at >= sides.size()) throw InputError(kChanged);
            sides[at] = {std::max(a, b), tris[k + (i + 2) % 3], a < b ? 1u : 0u};
          }
        }
    });
    again += tris.size() / 3;
  });
  if (again != count) throw InputError(kChanged);
  return sides;
}

// The sides filed under the vertices [lo, hi) (`files` as file_sides takes them), each edge's
// two sides tested, the boundary's sides added to `boundary`.
void edges_of_range(std::span<const Point> pts, const TriangleFeed& feed, std::size_t count, VertexId lo, VertexId hi,
                    std::vector<std::size_t> files, unsigned threads, std::vector<Edge>& boundary, Report& report) {
  std::vector<Side> sides = file_sides(feed, count, lo, hi, files, threads);
  // files[j] is now the end of vertex lo + j's file, the start of the next one's.
  struct Found {
    Report report;
    std::vector<Edge> boundary;
  };
  InOrder<Found> found;
  detail::parallel_for(hi - lo, threads, 1 << 12, [&](std::size_t first, std::size_t last) {
    Found f;
    for (std::size_t j = first; j < last; ++j) {
      const VertexId v = lo + static_cast<VertexId>(j);
      Side* const begin = sides.data() + (j == 0 ? 0 : files[j - 1]);
      Side* const end = sides.data() + files[j];
      std::sort(begin, end, [](const Side& x, const Side& y) {
        return x.hi < y.hi ||
            (x.hi == y.hi && (x.forward < y.forward || (x.forward == y.forward && x.opposite < y.opposite)));
      });
      for (Side* e = begin; e != end;) {
        Side* run = e;
        while (e != end && e->hi == run->hi) ++e;
        const VertexId w = run->hi;
        if (e - run == 1) {
          f.boundary.push_back(run->forward ? Edge{v, w} : Edge{w, v});
        } else if (e - run > 2 || run[0].forward == run[1].forward) {
          f.report.problem("edge ", v, "-", w, " is used by two triangles in the same direction");
        } else if (incircle(pts[v], pts[w], pts[run[1].opposite], pts[run[0].opposite]) > 0) {
          // run[1] is the triangle v -> w -> its opposite, counter-clockwise.
          f.report.problem("edge ", v, "-", w, " is not locally Delaunay (vertex ", run[0].opposite,
                           " lies inside the circle of triangle ", v, " ", w, " ", run[1].opposite, ")");
        }
      }
    }
    found.put(first, std::move(f));
  });
  for (Found& f : found.take()) {
    report.merge(f.report);
    boundary.insert(boundary.end(), f.boundary.begin(), f.boundary.end());
  }
}

// Every point that no triangle uses equal to one that some triangle does; returns the number
// of vertices.
std::size_t check_unused(std::span<const Point> pts, const std::vector<std::uint8_t>& used, unsigned threads,
                         Report& report) {
  std::vector<VertexId> unused;
  std::size_t vertices = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (used[i])
      ++vertices;
    else
      unused.push_back(static_cast<VertexId>(i));
  }
  if (unused.empty()) return vertices;
  auto less = [&](VertexId a, VertexId b) { return lex_less(pts[a], pts[b]); };
  std::sort(unused.begin(), unused.end(),
            [&](VertexId a, VertexId b) { return less(a, b) || (pts[a] == pts[b] && a < b); });
  std::vector<std::uint8_t> matched(unused.size(), 0);
  detail::parallel_for(pts.size(), threads, 1 << 16, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
      if (!used[i]) continue;
      const auto [b, e] = std::equal_range(unused.begin(), unused.end(), static_cast<VertexId>(i), less);
      for (auto it = b; it != e; ++it)  // two threads may mark one
        std::atomic_ref<std::uint8_t>(matched[static_cast<std::size_t>(it - unused.begin())])
            .store(1, std::memory_order_relaxed);
    }
  });
  for (std::size_t k = 0; k < unused.size(); ++k)
    if (!matched[k] && (k == 0 || !(pts[unused[k]] == pts[unused[k - 1]])))
      report.problem("point ", unused[k], " is not a vertex of any triangle");
  return vertices;
}

}  // namespace

CheckResult check_in_passes(std::span<const Point> input, const TriangleFeed& feed, std::size_t side_bytes,
                            unsigned threads) {
  threads = detail::thread_count(threads);
  if (side_bytes == 0) side_bytes = available_memory() / 4;
  const std::vector<Point> scaled = detail::exactly_scaled(input);
  const std::span<const Point> pts = scaled.empty() ? input : std::span<const Point>(scaled);
  const std::size_t n = pts.size();
  Report report;
  std::vector<std::uint8_t> used(n, 0);
  std::vector<std::uint32_t> files(n + 1, 0);
  const std::size_t count = first_pass(pts, feed, used, files, threads, report);
  if (count == 0 && report.problems() == 0) return check(input, {});
  if (report.problems() > 0) return report.result();  // what follows needs sound triangles
  // Each range of vertices whose sides, and their files' starts, fit the budget (one vertex's
  // at least).
  std::vector<Edge> boundary;
  auto cost = [&](std::size_t v) { return files[v + 1] * sizeof(Side) + sizeof(std::size_t); };
  for (std::size_t lo = 0, hi = 0; lo < n; lo = hi) {
    for (std::size_t bytes = 0; hi < n && (hi == lo || bytes + cost(hi) <= side_bytes); ++hi) bytes += cost(hi);
    std::vector<std::size_t> starts(hi - lo + 1, 0);
    for (std::size_t j = 0; j < hi - lo; ++j) starts[j + 1] = starts[j] + files[lo + j + 1];
    edges_of_range(pts, feed, count, static_cast<VertexId>(lo), static_cast<VertexId>(hi), std::move(starts), threads,
                   boundary, report);
  }
  const std::size_t vertices = check_unused(pts, used, threads, report);
  detail::check_hull_and_count(pts, detail::near_the_hull(pts, threads), std::move(boundary), count, vertices, report);
  std::string valid = "valid: " + std::to_string(count) + " triangles, " + std::to_string(vertices) + " vertices of " +
      std::to_string(n) + " points (" + std::to_string(vertices) + " distinct), exactly Delaunay";
  return report.result(valid);
}

}  // namespace ridt
