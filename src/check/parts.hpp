// The validator's parts that check_constrained (check/check.cpp) and check_mesh
// (check/check_mesh.cpp) share: the report, the triangles' orientation, the edge table with its
// local Delaunay test, the convex hull.
#pragma once

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <span>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "ridt/check.hpp"

namespace ridt::detail {

class Report {
 public:
  template <typename... Args>
  void problem(const Args&... args) {
    if (problems_++ == 0) {
      std::ostringstream s;
      (s << ... << args);
      first_ = s.str();
    }
  }
  std::size_t problems() const { return problems_; }
  // Another report's problems, after this one's.
  void merge(const Report& other) {
    if (other.problems_ == 0) return;
    if (problems_ == 0) first_ = other.first_;
    problems_ += other.problems_;
  }
  // The verdict: the first problem and their count, or `valid` when there is none.
  CheckResult result(const std::string& valid = {}) const {
    if (problems_ == 0) return {true, valid, 0};
    std::ostringstream s;
    s << "invalid: " << first_ << " (" << problems_ << " problem" << (problems_ == 1 ? "" : "s") << ")";
    return {false, s.str(), problems_};
  }

 private:
  std::size_t problems_ = 0;
  std::string first_;
};

// Results of parts of a parallel loop, merged in the order of the parts: the first problem
// is then the one a single thread would have met first.
template <class Result>
class InOrder {
 public:
  void put(std::size_t first, Result r) {
    const std::lock_guard<std::mutex> lock(mutex_);
    parts_.emplace_back(first, std::move(r));
  }
  // The parts' results, by where they began.
  std::vector<Result> take() {
    std::sort(parts_.begin(), parts_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<Result> out;
    for (auto& p : parts_) out.push_back(std::move(p.second));
    return out;
  }

 private:
  std::mutex mutex_;
  std::vector<std::pair<std::size_t, Result>> parts_;
};

using Edge = std::pair<VertexId, VertexId>;

/// Lists of neighbours of n points in one array (no allocation a point): list v runs from
/// list[start[v]] to list[start[v + 1]].
struct Adjacency {
  std::vector<std::size_t> start;
  std::vector<VertexId> list;
  std::span<const VertexId> operator[](VertexId v) const { return {list.data() + start[v], start[v + 1] - start[v]}; }
  /// Of pairs (flat: u0, w0, u1, w1, ...), each in the other's list, in their order.
  static Adjacency of_pairs(std::size_t n, std::span<const VertexId> pairs);
  /// Of the triangles' sides, both ways: an interior edge twice, from its two triangles.
  static Adjacency of_triangles(std::size_t n, std::span<const VertexId> tris);
};

/// The points' indices sorted lexicographically (equal points by index), the first index of
/// each group of equal points, and whether the distinct points are fewer than three or
/// collinear (then no triangle is right).
struct Distinct {
  std::vector<VertexId> sorted;
  std::vector<VertexId> first;
  bool degenerate = false;
};

/// The Distinct of points whose indices `sorted` holds lexicographically (equal points by
/// index): the first of each group of equal points, and whether those are degenerate.
Distinct grouped(std::span<const Point> pts, std::vector<VertexId> sorted);

/// Huge or tiny coordinates: an exactly scaled copy keeps the predicates on their fast path.
/// Empty when the input needs none.
std::vector<Point> exactly_scaled(std::span<const Point> input);

/// Every index in range, every triangle counter-clockwise and not degenerate; marks the
/// vertices used.
void check_triangles(std::span<const Point> pts, std::span<const VertexId> tris, std::vector<std::uint8_t>& used,
                     Report& report);

/// Every directed edge used once, every interior edge locally Delaunay but those of segments
/// (`constrained`: (lo, hi), sorted). Returns the boundary edges, directed as their triangles run.
std::vector<Edge> check_edges(std::span<const Point> pts, std::span<const VertexId> tris,
                              const std::vector<Edge>& constrained, Report& report);

/// The convex hull, counter-clockwise, with points on its edges kept, over distinct points
/// given as indices sorted lexicographically (Andrew's monotone chain). Requires at least three
/// non-collinear points.
std::vector<VertexId> hull_with_collinear(std::span<const Point> pts, const std::vector<VertexId>& sorted);

/// The points not strictly inside the convex polygon of a few extreme points (all of them where
/// that is empty), grouped as for Distinct: `first` the least index of each group of equal
/// points, lexicographically. They hold the convex hull's corners and the points on its sides,
/// and are few: hull_with_collinear(pts, near_the_hull(pts).first) is the hull, without a sort
/// of every point; `degenerate` where the points have none. On `threads`.
Distinct near_the_hull(std::span<const Point> pts, unsigned threads);

/// Triangles exactly when the points are not degenerate; then the boundary edges (directed as
/// their triangles run, any index of a group of equal points) are the convex hull of the
/// points `d.first` (the hull of all the points, though `first` need hold only those not
/// strictly inside it), and Euler's count holds for `count` triangles and `vertices` vertices:
/// #T = 2V - 2 - H.
void check_hull_and_count(std::span<const Point> pts, const Distinct& d, std::vector<Edge> boundary, std::size_t count,
                          std::size_t vertices, Report& report);

}  // namespace ridt::detail
