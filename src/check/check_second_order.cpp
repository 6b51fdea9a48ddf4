// The validator of six-node triangles (ridt/check.hpp: check_second_order).
#include <algorithm>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "ridt/check.hpp"

namespace ridt {

namespace {

// Each edge (a, b), a < b, with its node, from the triangle at hand.
struct Entry {
  std::uint64_t edge;
  VertexId node;
  std::size_t triangle;
};

// The entries of every triangle's three nodes, each checked where it stands: among the points,
// no corner, the rounded mean of its edge's ends.
template <class Fail>
std::vector<Entry> entries_of(std::span<const Point> points, std::span<const VertexId> triangles,
                              std::span<const VertexId> middles, Fail&& fail) {
  std::vector<std::uint8_t> corner(points.size(), 0);
  for (const VertexId v : triangles)
    if (v < points.size()) corner[v] = 1;
  std::vector<Entry> entries;
  entries.reserve(middles.size());
  for (std::size_t k = 0; k < triangles.size() / 3; ++k)
    for (int i = 0; i < 3; ++i) {
      const std::uint64_t a = triangles[3 * k + (i + 1) % 3], b = triangles[3 * k + (i + 2) % 3];
      const VertexId m = middles[3 * k + i];
      const std::string where = "triangle " + std::to_string(k) + "'s node " + std::to_string(3 + i);
      if (a >= points.size() || b >= points.size() || m >= points.size()) {
        fail(where + " or its edge's ends are not among the " + std::to_string(points.size()) + " points");
        continue;
      }
      if (corner[m]) fail(where + " (" + std::to_string(m) + ") is a corner of a triangle");
      const Point& p = points[m];
      if (p.x != std::midpoint(points[a].x, points[b].x) || p.y != std::midpoint(points[a].y, points[b].y))
        fail(where + " (" + std::to_string(m) + ") is not the middle of its edge " + std::to_string(a) + "-" +
             std::to_string(b));
      entries.push_back({std::min(a, b) << 32 | std::max(a, b), m, k});
    }
  return entries;
}

}  // namespace

CheckResult check_second_order(std::span<const Point> points, std::span<const VertexId> triangles,
                               std::span<const VertexId> middles) {
  CheckResult r;
  auto fail = [&r](std::string why) {
    if (r.problems++ == 0) r.message = "invalid: " + std::move(why);
  };
  const std::size_t count = triangles.size() / 3;
  if (middles.size() != 3 * count || triangles.size() != 3 * count) {
    fail("3 middle nodes a triangle are needed (" + std::to_string(middles.size()) + " for " + std::to_string(count) +
         " triangles)");
    return r;
  }
  std::vector<Entry> entries = entries_of(points, triangles, middles, fail);
  // Sorted by edge, an edge's entries side by side: one node an edge, one edge a node.
  std::sort(entries.begin(), entries.end(),
            [](const Entry& x, const Entry& y) { return x.edge != y.edge ? x.edge < y.edge : x.node < y.node; });
  std::vector<std::pair<VertexId, std::uint64_t>> owners;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (k > 0 && entries[k].edge == entries[k - 1].edge) {
      if (entries[k].node != entries[k - 1].node)
        fail("triangles " + std::to_string(entries[k - 1].triangle) + " and " + std::to_string(entries[k].triangle) +
             " give their shared edge two nodes");
      continue;
    }
    owners.push_back({entries[k].node, entries[k].edge});
  }
  std::sort(owners.begin(), owners.end());
  for (std::size_t k = 1; k < owners.size(); ++k)
    if (owners[k].first == owners[k - 1].first)
      fail("node " + std::to_string(owners[k].first) + " is the middle of two edges");
  if (r.problems > 0) {
    r.message += " (" + std::to_string(r.problems) + " problems)";
    return r;
  }
  r.valid = true;
  r.message = "valid: " + std::to_string(count) + " six-node triangles, " + std::to_string(owners.size()) +
      " edge middles, each the rounded mean of its edge's ends and shared by its triangles";
  return r;
}

}  // namespace ridt
