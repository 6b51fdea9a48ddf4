// The whole of a result, checked: the exact validator on the triangles, and everything else a
// Triangulation promises (neighbours, hull, duplicates, the warning). No test framework here:
// the fuzz targets use it too.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "ridt/check.hpp"
#include "ridt/predicates.hpp"
#include "ridt/ridt.hpp"

namespace ridt::test {

using TriangleSet = std::vector<std::array<VertexId, 3>>;

/// Triangles rotated to start at their smallest index, sorted.
inline TriangleSet canonical(const std::vector<VertexId>& tris) {
  TriangleSet out;
  for (std::size_t i = 0; i + 2 < tris.size(); i += 3) {
    std::array<VertexId, 3> t{tris[i], tris[i + 1], tris[i + 2]};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The hull cycle rotated to start at its smallest index.
inline std::vector<VertexId> canonical_hull(std::vector<VertexId> hull) {
  std::rotate(hull.begin(), std::min_element(hull.begin(), hull.end()), hull.end());
  return hull;
}

/// What is wrong with `t` as the triangulation of `points`; empty when nothing is:
///  - the exact validator accepts the triangles;
///  - the neighbours match the triangles (each interior edge's two triangles name each other,
///    -1 exactly on boundary edges);
///  - the hull is the cycle of boundary edges, counter-clockwise;
///  - the duplicates are exactly the points equal to a smaller-indexed one, each paired with
///    the smallest index of its kind, and no duplicate is a vertex;
///  - an empty result says why in the warning; the counts in the stats add up.
/// With `segments`, the validator is the constrained one.
/// The points where the triangulation's boundary turns (its hull without the points on its
/// sides), counter-clockwise from the least (by x, then y): the convex hull's corners, by
/// another algorithm than ridt::convex_hull's. Empty without triangles.
inline std::vector<Point> hull_turns(std::span<const Point> points, const Triangulation& t) {
  const std::vector<VertexId>& b = t.hull;
  std::vector<Point> out;
  for (std::size_t i = 0; i < b.size(); ++i)
    if (orientation(points[b[(i + b.size() - 1) % b.size()]], points[b[i]], points[b[(i + 1) % b.size()]]) != 0)
      out.push_back(points[b[i]]);
  auto least = [](const Point& p, const Point& q) { return p.x < q.x || (p.x == q.x && p.y < q.y); };
  std::rotate(out.begin(), std::min_element(out.begin(), out.end(), least), out.end());
  return out;
}

inline std::string audit(std::span<const Point> points, const Triangulation& t,
                         std::span<const VertexId> segments = {}) {
  const CheckResult verdict = check_constrained(points, t.triangles, segments);
  if (!verdict.valid) return "validator: " + verdict.message;
  const std::size_t nt = t.size();
  if (t.neighbors.size() != 3 * nt) return "neighbour list has the wrong size";

  // Neighbours, and the boundary edges as a successor map.
  std::vector<std::int64_t> next(points.size(), -1);
  std::size_t boundary = 0;
  for (std::size_t k = 0; k < nt; ++k) {
    for (int i = 0; i < 3; ++i) {
      const VertexId a = t.triangles[3 * k + (i + 1) % 3], b = t.triangles[3 * k + (i + 2) % 3];
      const std::int32_t nb = t.neighbors[3 * k + i];
      if (nb < 0) {
        if (nb != kNoNeighbor) return "negative neighbour other than -1";
        if (next[a] != -1) return "two boundary edges leave vertex " + std::to_string(a);
        next[a] = b;
        ++boundary;
        continue;
      }
      if (static_cast<std::size_t>(nb) >= nt) return "neighbour out of range";
      bool back = false;
      for (int j = 0; j < 3; ++j)
        back = back ||
            (t.triangles[3 * nb + (j + 1) % 3] == b && t.triangles[3 * nb + (j + 2) % 3] == a &&
             t.neighbors[3 * nb + j] == static_cast<std::int32_t>(k));
      if (!back) return "triangle " + std::to_string(k) + " and its neighbour disagree";
    }
  }
  if (t.hull.size() != boundary)
    return "hull has " + std::to_string(t.hull.size()) + " vertices for " + std::to_string(boundary) +
        " boundary edges";
  for (std::size_t i = 0; i < t.hull.size(); ++i)
    if (next[t.hull[i]] != static_cast<std::int64_t>(t.hull[(i + 1) % t.hull.size()]))
      return "hull is not the cycle of boundary edges at position " + std::to_string(i);

  // Duplicates: group equal points, smallest index first.
  std::vector<VertexId> order(points.size());
  std::iota(order.begin(), order.end(), VertexId{0});
  std::sort(order.begin(), order.end(), [&](VertexId a, VertexId b) {
    const Point &p = points[a], &q = points[b];
    if (p.x != q.x) return p.x < q.x;
    if (p.y != q.y) return p.y < q.y;
    return a < b;
  });
  std::vector<Duplicate> expected;
  for (std::size_t i = 1, kept = 0; i < order.size(); ++i) {
    if (points[order[i]] == points[order[kept]])
      expected.push_back({order[i], order[kept]});
    else
      kept = i;
  }
  std::sort(expected.begin(), expected.end(),
            [](const Duplicate& a, const Duplicate& b) { return a.dropped < b.dropped; });
  if (expected.size() != t.duplicates.size())
    return "expected " + std::to_string(expected.size()) + " duplicates, got " + std::to_string(t.duplicates.size());
  std::vector<bool> dropped(points.size(), false);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    if (expected[i].dropped != t.duplicates[i].dropped || expected[i].kept != t.duplicates[i].kept)
      return "duplicate " + std::to_string(i) + " is " + std::to_string(t.duplicates[i].dropped) + " -> " +
          std::to_string(t.duplicates[i].kept) + ", expected " + std::to_string(expected[i].dropped) + " -> " +
          std::to_string(expected[i].kept);
    dropped[expected[i].dropped] = true;
  }
  for (VertexId v : t.triangles)
    if (dropped[v]) return "duplicate point " + std::to_string(v) + " is a vertex";

  if (nt == 0 && t.warning.empty()) return "empty triangulation without a warning";
  if (t.stats.points != points.size() || t.stats.duplicates != expected.size() ||
      t.stats.distinct + t.stats.duplicates != t.stats.points)
    return "stats do not add up";
  return "";
}

/// What differs between two results of the same points; empty when they have the same
/// triangles, hull and duplicates (the order of the triangles aside).
inline std::string compare(const Triangulation& a, const Triangulation& b) {
  if (canonical(a.triangles) != canonical(b.triangles)) return "different triangles";
  if (canonical_hull(a.hull) != canonical_hull(b.hull)) return "different hulls";
  if (a.duplicates.size() != b.duplicates.size()) return "different duplicates";
  for (std::size_t i = 0; i < a.duplicates.size(); ++i)
    if (a.duplicates[i].dropped != b.duplicates[i].dropped || a.duplicates[i].kept != b.duplicates[i].kept)
      return "different duplicates";
  return "";
}

/// One way to run a triangulation.
struct Mode {
  std::string name;
  Method method = Method::Serial;
  unsigned threads = 1;
  Order order = Order::Brio;
  Locate locate = Locate::Dag;

  Options options(std::uint64_t seed = 1) const {
    Options o;
    o.method = method;
    o.threads = threads;
    o.order = order;
    o.locate = locate;
    o.seed = seed;
    return o;
  }
};

/// The serial method in both orders and walking, and each threaded method on `threads`
/// threads in `threaded_order` (the partition method in the BRIO order only).
inline std::vector<Mode> every_mode(unsigned threads, Order threaded_order = Order::Brio) {
  std::vector<Mode> modes = {{"serial random dag", Method::Serial, 1, Order::Random, Locate::Dag},
                             {"serial brio dag", Method::Serial, 1, Order::Brio, Locate::Dag},
                             {"serial brio walk", Method::Serial, 1, Order::Brio, Locate::Walk},
                             {"serial random root", Method::Serial, 1, Order::Random, Locate::Root}};
  for (const Method method : {Method::Pessimistic, Method::Optimistic, Method::Batch}) {
    std::ostringstream label;
    label << to_string(method) << ' ' << threads << ' ' << to_string(threaded_order);
    modes.push_back({label.str(), method, threads, threaded_order, Locate::Dag});
  }
  // The paper's configuration: every descent from the root.
  modes.push_back({"pessimistic " + std::to_string(threads) + " random root", Method::Pessimistic, threads,
                   Order::Random, Locate::Root});
  // The partition method walks, in the BRIO order only.
  if (threaded_order == Order::Brio)
    modes.push_back(
        {"partition " + std::to_string(threads) + " brio", Method::Partition, threads, Order::Brio, Locate::Walk});
  return modes;
}

/// Triangulates `points` in each mode: empty when every result passes the audit and all are
/// the same triangulation, else the first problem, naming its mode. `first`, when given,
/// receives the first mode's result.
inline std::string audit_every_mode(std::span<const Point> points, const std::vector<Mode>& modes,
                                    std::uint64_t seed = 1, Triangulation* first = nullptr) {
  Triangulation reference;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    Triangulation t = triangulate(points, modes[i].options(seed));
    if (const std::string problem = audit(points, t); !problem.empty()) return modes[i].name + ": " + problem;
    if (i == 0) {
      reference = std::move(t);
    } else if (const std::string diff = compare(reference, t); !diff.empty()) {
      return modes[i].name + " differs from " + modes[0].name + ": " + diff;
    }
  }
  if (first != nullptr) *first = std::move(reference);
  return "";
}

}  // namespace ridt::test
