// The sphere's points made distinct (sphere/sphere.cpp): sorted lexicographically, their ranks
// the perturbation's keys, copies dropped and named.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "order/order.hpp"
#include "order/runs.hpp"
#include "ridt/sphere.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"
#include "tds/ids.hpp"

namespace ridt::detail {

inline bool lex_less3(const Point3& a, const Point3& b) {
  return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
}

// The distinct points in lexicographic order (their ranks are their vertex ids), the input
// index of each, and the copies dropped.
struct Distinct {
  std::vector<Point3> points;
  std::vector<VertexId> input;
  std::vector<Duplicate> duplicates;
};

inline Distinct distinct_points(std::span<const Point3> points, unsigned threads) {
  if (points.size() >= kMaxSlotPoints) throw InputError("triangulate_sphere: too many points");
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) || !std::isfinite(points[i].z))
      throw InputError("triangulate_sphere: point " + std::to_string(i) + " is not finite");
  // The indices sorted by x (a radix sort on its order-keeping bits' upper half, -0 made 0),
  // then each run of one key by x, y, z and index.
  const auto n = static_cast<std::uint32_t>(points.size());
  std::vector<std::uint64_t> words, sorted;
  resize_present(words, n, threads), resize_present(sorted, n, threads);
  parallel_for(n, threads, 65536, [&](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) {
      const auto bits = std::bit_cast<std::uint64_t>(points[i].x + 0.0);
      words[i] = (bits >> 63 ? ~bits : bits | std::uint64_t{1} << 63) >> 32 << 32 | i;
    }
  });
  sort_by_key(words.data(), sorted.data(), n, threads);
  sort_runs(sorted, threads, [&](std::uint32_t a, std::uint32_t b) {
    return lex_less3(points[a], points[b]) || (points[a] == points[b] && a < b);
  });
  Distinct d;
  resize_present(d.points, n, threads), resize_present(d.input, n, threads);
  parallel_for(n, threads, 65536, [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k)
      d.input[k] = static_cast<VertexId>(sorted[k]), d.points[k] = points[d.input[k]];
  });
  std::size_t kept = 0;  // copies dropped, in place
  for (std::size_t k = 0; k < n; ++k) {
    if (kept > 0 && d.points[kept - 1] == d.points[k]) {
      d.duplicates.push_back({d.input[k], d.input[kept - 1]});
      continue;
    }
    d.input[kept] = d.input[k], d.points[kept++] = d.points[k];
  }
  d.input.resize(kept), d.points.resize(kept);
  std::sort(d.duplicates.begin(), d.duplicates.end(),
            [](const Duplicate& a, const Duplicate& b) { return a.dropped < b.dropped; });
  return d;
}

}  // namespace ridt::detail
