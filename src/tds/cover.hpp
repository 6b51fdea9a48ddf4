// A cavity that surrounds vertices, for the triangulations whose insertions may hide points (on
// the sphere, sphere/sphere.cpp; with weights, regular/regular.cpp): the faces a new point sees
// can enclose a vertex, and Tds::find_cavity, meeting a face again, leaves its boundary wrong.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tds/tds.hpp"

namespace ridt::detail {

/// find_cavity's `seen` for the triangulations whose cavities may meet a face twice: a face
/// is among those met where its stamp is this insertion's epoch, and is stamped as it is met.
inline auto stamped(std::span<std::uint32_t> stamp, std::uint32_t epoch) {
  return [stamp, epoch](TriangleId u, const TriangleId*, std::size_t) {
    if (stamp[u] == epoch) return true;
    stamp[u] = epoch;
    return false;
  };
}

/// What cover_cavity keeps between calls.
struct CoverScratch {
  std::vector<CavityScratch::Boundary> edges;
  std::vector<VertexId> inside;
};

/// The cavity in s (its `size` faces, all of them marked: in(t) says whether face t is one)
/// made whole again: its boundary found from the faces' edges whose far side is not in it and
/// ordered round (each edge a -> b followed by the one from b), each vertex of its faces that is
/// on no boundary edge passed to hide(v), and the slots beyond those the fan takes freed onto
/// `free`. `at` has an entry for every vertex id; its contents may be anything, the entries of
/// the cavity's vertices are written (each boundary vertex's edge: so each look-up is one read,
/// checked against the edge it names, where a sort and binary searches took a seventh of a
/// regular triangulation's time with heavy weights).
template <class In, class Hide>
void cover_cavity(Tds& tds, CavityScratch& s, In&& in, Hide&& hide, std::vector<TriangleId>& free, CoverScratch& c,
                  std::span<std::uint32_t> at) {
  const std::size_t m = s.size;
  c.edges.clear(), c.inside.clear();
  for (std::size_t k = 0; k < m; ++k) {
    const TriangleId t = s.cavity[k];
    for (int i = 0; i < 3; ++i) {
      const Link l = tds.link(t, i);
      c.inside.push_back(tds.vertex(t, i));
      if (!in(triangle_of(l))) c.edges.push_back({tds.vertex(t, next3(i)), l, link_to(t, i)});
    }
  }
  const std::vector<CavityScratch::Boundary>& edges = c.edges;
  const std::size_t k = edges.size();
  for (std::size_t e = 0; e < k; ++e) at[edges[e].a] = static_cast<std::uint32_t>(e);
  // The edge from vertex u, or k where u is on none.
  auto from = [&](VertexId u) -> std::size_t {
    const std::uint32_t e = at[u];
    return e < k && edges[e].a == u ? e : k;
  };
  s.make_room(k + 2);
  s.boundary[0] = edges[0];
  for (std::size_t e = 1; e < k; ++e) s.boundary[e] = edges[from(tds.head(s.boundary[e - 1].inside))];
  for (const VertexId u : c.inside)
    if (from(u) == k) hide(u);
  for (std::size_t i = k - 2; i < m; ++i) {
    tds.free_slot(s.cavity[i]);
    free.push_back(s.cavity[i]);
  }
  s.size = k - 2, s.edges = k;
}

}  // namespace ridt::detail
