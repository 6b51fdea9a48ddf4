// Point location in a finished triangulation (ridt/locate.hpp): visibility walks from each
// answer to the next query, in the queries' own order while that keeps the walks short (a
// grid, a scan line, sorted queries), else along a Hilbert curve through them.
#include "ridt/locate.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>
#include <thread>

#include "order/order.hpp"
#include "predicates/predicates.hpp"
#include "queries/arrays.hpp"
#include "queries/near.hpp"
#include "runtime/parallel.hpp"
#include "tds/tds.hpp"

namespace ridt {
namespace {

using detail::next3;
using detail::prev3;

// The result's arrays: triangle t has vertices triangles[3t + i] and, across from vertex i,
// the neighbour neighbors[3t + i] (-1 on the hull).
struct Result {
  const Point* points;
  const VertexId* triangles;
  const std::int32_t* neighbors;
  std::size_t size;  // triangles

  const Point& corner(std::size_t t, int i) const { return points[triangles[3 * t + i]]; }

  detail::NearHull near;  // whether a point outside answers from the hull triangle beside it

  // Whether the closed triangle t holds q.
  bool holds(std::size_t t, const Point& q) const {
    for (int i = 0; i < 3; ++i)
      if (detail::orient2d(corner(t, next3(i)), corner(t, prev3(i)), q) < 0) return false;
    return true;
  }

  // What detail::visibility_walk reads: the corners, and the link across edge i (the
  // neighbour's edge that looks back).
  const VertexId* corners(std::size_t t) const { return triangles + 3 * t; }
  detail::Link link(std::size_t t, int i) const {
    const std::int32_t u = neighbors[3 * t + i];
    if (u < 0) return detail::kNoLink;
    const std::size_t ub = 3 * static_cast<std::size_t>(u);
    const int j = neighbors[ub] == static_cast<std::int32_t>(t) ? 0
        : neighbors[ub + 1] == static_cast<std::int32_t>(t)     ? 1
                                                                : 2;
    return static_cast<detail::Link>(ub + static_cast<std::size_t>(j));
  }

  // The one visibility walk (tds/tds.hpp) from triangle t towards q, never across a hull edge
  // while another edge leads on. In a Delaunay triangulation it cannot cycle, whatever the
  // point of view (Edelsbrunner 1990), so it ends at a triangle that holds q, or at one whose
  // only edges with q beyond them are on the hull: q is then outside the hull, whose edges'
  // lines support it, and beside that triangle, which answers when q is near it (see near). t
  // is left at the last triangle reached, and `steps` grows by the triangles it crossed. The
  // step limit only guards against arrays that are not a Delaunay triangulation; a scan of
  // every triangle answers then.
  std::int32_t walk(std::size_t& t, const Point& q, std::size_t& steps) const {
    auto t32 = static_cast<TriangleId>(t);
    std::size_t taken = 0;
    const detail::Walked end = detail::visibility_walk(
        *this, t32, [&](VertexId a, VertexId b) { return detail::orient2d(points[a], points[b], q); },
        [&](detail::Link l) {
          if (l == detail::kNoLink) return detail::Step::Blocked;
          return ++taken > size ? detail::Step::Stop : detail::Step::Cross;
        });
    t = t32;
    steps += taken;
    if (end.edge < 0) {
      const bool answers = end.reached || near(corner(t, 0), corner(t, 1), corner(t, 2), q);
      return answers ? static_cast<std::int32_t>(t) : -1;
    }
    for (std::size_t s = 0; s < size; ++s)
      if (holds(s, q)) return static_cast<std::int32_t>(s);
    return -1;
  }
};

bool finite(const Point& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Walks the finite queries of [begin, end) in Hilbert order over their own box, from t.
void locate_sorted(const Result& mesh, const Point* queries, std::size_t begin, std::size_t end, std::size_t& t,
                   std::int32_t* out) {
  std::vector<Point> local;
  std::vector<std::uint32_t> where;  // local position -> query index
  local.reserve(end - begin);
  where.reserve(end - begin);
  for (std::size_t i = begin; i < end; ++i) {
    if (finite(queries[i])) {
      local.push_back(queries[i]);
      where.push_back(static_cast<std::uint32_t>(i - begin));
    } else {
      out[i] = -1;
    }
  }
  const auto count = static_cast<std::uint32_t>(local.size());
  const std::vector<std::uint32_t> key = detail::hilbert_keys(local.data(), count);
  std::vector<std::uint32_t> order(count);
  for (std::uint32_t i = 0; i < count; ++i) order[i] = i;
  detail::hilbert_sort(local.data(), key.data(), order.data(), count);
  std::size_t steps = 0;
  for (const std::uint32_t i : order) out[begin + where[i]] = mesh.walk(t, local[i], steps);
}

// Answers queries [begin, end). First in their own order, each walk starting at the last
// answer: while the walks average at most kSteps triangles (after a first allowance for the
// walk to the first query), the queries come in an order near in the plane and a sort would
// only cost. Once they do not, the rest are sorted along the curve.
void locate_share(const Result& mesh, const Point* queries, std::size_t begin, std::size_t end, std::int32_t* out) {
  constexpr std::size_t kSteps = 6, kAllowance = 1024;
  std::size_t t = 0, steps = 0, i = begin;
  for (; i < end; ++i) {
    if (!finite(queries[i])) {
      out[i] = -1;
      continue;
    }
    out[i] = mesh.walk(t, queries[i], steps);
    if (steps > kSteps * (i - begin + kAllowance)) {
      ++i;
      break;
    }
  }
  if (i < end) locate_sorted(mesh, queries, i, end, t, out);
}

}  // namespace

void locate(std::span<const Point> points, std::span<const VertexId> triangles, std::span<const std::int32_t> neighbors,
            std::span<const Point> queries, std::span<std::int32_t> out, unsigned threads, double tolerance) {
  detail::check_arrays("locate", points.size(), triangles, neighbors);
  if (out.size() != queries.size())
    throw InputError("locate: " + std::to_string(queries.size()) + " queries but room for " +
                     std::to_string(out.size()) + " answers");
  if (queries.size() > 0xffffffffu) throw InputError("locate: more than 2^32 queries");
  const std::size_t size = triangles.size() / 3;
  if (size == 0) {
    std::fill(out.begin(), out.end(), -1);
    return;
  }
  const Result mesh{points.data(), triangles.data(), neighbors.data(), size, detail::NearHull(points, tolerance)};
  // A share of fewer than some 16,000 queries is not worth a thread.
  detail::parallel_for(queries.size(), threads, 16384, [&](std::size_t first, std::size_t last) {
    locate_share(mesh, queries.data(), first, last, out.data());
  });
}

std::vector<std::int32_t> locate(std::span<const Point> points, const Triangulation& triangulation,
                                 std::span<const Point> queries, unsigned threads, double tolerance) {
  std::vector<std::int32_t> out(queries.size());
  locate(points, triangulation.triangles, triangulation.neighbors, queries, out, threads, tolerance);
  return out;
}

}  // namespace ridt
