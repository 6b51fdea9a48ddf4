// Carving and regions (constrained/domain.hpp): floods across the edges that are not fixed.
#include "constrained/domain.hpp"

#include <algorithm>
#include <optional>

namespace ridt::detail {
namespace {

// Where q lies (inside a triangle, on an edge or at a corner), or nothing where no triangle
// holds it; `from` (a hint) moves to its triangle.
std::optional<Cdt::Place> place(const Cdt& m, const Point& q, TriangleId& from) {
  if (m.size() == 0) return std::nullopt;
  const Cdt::Place at = m.find(std::min<TriangleId>(from, static_cast<TriangleId>(m.size() - 1)), q);
  if (at.kind == Cdt::Place::Outside) return std::nullopt;
  from = at.t;
  return at;
}

// The triangles whose closure holds q: one, or two beside an edge, or every one about a vertex
// (a hole's seed there empties them all: the validator finds no seed inside or on a triangle;
// a region's marks them all, whichever the walk to it met first).
std::vector<TriangleId> holding_all(const Cdt& m, const Point& q, TriangleId& from) {
  std::vector<TriangleId> out;
  const std::optional<Cdt::Place> at = place(m, q, from);
  if (!at) return out;
  if (at->kind == Cdt::Place::Corner) {
    const VertexId v = m.at(at->t, at->k);
    bool open = false;  // a fan that ends at the boundary: where the domain touches itself at v, one of several
    m.around(v, [&](TriangleId t) {
      const int i = m.corner_of(t, v);
      open = open || m.boundary(link_to(t, next3(i))) || m.boundary(link_to(t, prev3(i)));
      return out.push_back(t), false;
    });
    if (open) {  // every triangle at v, whichever fan it is in
      out.clear();
      for (TriangleId t = 0; t < m.size(); ++t)
        if (m.at(t, 0) == v || m.at(t, 1) == v || m.at(t, 2) == v) out.push_back(t);
    }
    return out;
  }
  out.push_back(at->t);
  if (const TriangleId n = m.across(link_to(at->t, at->k)); at->kind == Cdt::Place::Edge && n != kNoTriangle)
    out.push_back(n);
  return out;
}

// Every triangle reached from `seed` across edges that are not fixed, given `mark` (those
// whose mark is already `mark` are not entered again). Breadth first: a triangle's links are
// asked for when it is queued, and read some way on, when its turn comes.
template <class T>
void flood(const Cdt& m, TriangleId seed, std::vector<T>& label, T mark) {
  if (label[seed] == mark) return;
  std::vector<TriangleId> queue{seed};
  label[seed] = mark;
  const Link* link = m.tds.link_array().data();
  const Constraint* constraint = m.tds.constraint_array().data();
  for (std::size_t next = 0; next < queue.size(); ++next) {
    const TriangleId t = queue[next];
    for (int j = 0; j < 3; ++j) {
      const Link l = link[3 * std::size_t{t} + j];
      if (l == kNoLink || constraint[3 * std::size_t{t} + j] != kFree) continue;
      const TriangleId n = triangle_of(l);
      if (label[n] == mark) continue;
      label[n] = mark;
      __builtin_prefetch(link + 3 * std::size_t{n});
      __builtin_prefetch(constraint + 3 * std::size_t{n});
      queue.push_back(n);
    }
  }
}

}  // namespace

std::vector<std::uint8_t> carve(Cdt& m, const std::vector<Point>& holes, const std::vector<Region>& regions,
                                bool convex_hull, bool compact) {
  const std::size_t nt = m.size();
  std::vector<std::uint8_t> gone(nt, 0);
  for (TriangleId t = 0; t < nt && !convex_hull; ++t)
    for (int j = 0; j < 3; ++j)
      if (m.boundary(link_to(t, j)) && !m.fixed(link_to(t, j))) flood<std::uint8_t>(m, t, gone, 1);
  TriangleId from = 0;
  for (const Point& h : holes)
    for (const TriangleId t : holding_all(m, h, from)) flood<std::uint8_t>(m, t, gone, 1);
  const bool removed = std::find(gone.begin(), gone.end(), 1) != gone.end();
  if (!removed) gone.clear();
  if (removed && compact) m.drop_slots(gone), gone.clear();
  if (!regions.empty()) {
    // A seed in a triangle marked gone (not removed) marks it, and its mark goes with it.
    m.region.assign(m.size(), -1);
    for (std::size_t r = 0; r < regions.size(); ++r)
      for (const TriangleId t : holding_all(m, regions[r].seed, from))
        flood<std::int32_t>(m, t, m.region, static_cast<std::int32_t>(r));
  }
  return gone;
}

std::vector<VertexId> split_pinches(Cdt& m) {
  // A fan about a vertex on the boundary begins at the boundary edge that leaves it (v -> w, the
  // fan's triangle on its left): count them.
  const Link slots = static_cast<Link>(3 * m.size());
  std::vector<std::uint32_t> fans(m.pts.size(), 0);
  for (Link s = 0; s < slots; ++s)
    if (m.boundary(s)) ++fans[m.tds.tail(s)];
  std::vector<VertexId> stands_for;
  for (Link s = 0; s < slots; ++s) {
    const VertexId v = m.tds.tail(s);
    if (!m.boundary(s) || v >= fans.size() || fans[v] < 2) continue;  // (a fan leaves its vertex once)
    --fans[v];  // the last fan found keeps v
    const auto alias = static_cast<VertexId>(m.pts.size());
    m.pts.push_back(m.pts[v]);
    m.corner.push_back(link_to(triangle_of(s), next3(edge_of(s))));
    stands_for.push_back(v);
    // Counter-clockwise about v from the leaving edge, across the edges that come into v.
    for (TriangleId t = triangle_of(s); t != kNoTriangle;) {
      const int i = m.corner_of(t, v);
      m.tds.set_vertex(t, i, alias);
      t = m.across(link_to(t, next3(i)));
    }
  }
  if (!stands_for.empty()) m.index_corners();
  return stands_for;
}

void merge_pinches(Cdt& m, VertexId first, const std::vector<VertexId>& stands_for) {
  if (stands_for.empty()) return;
  const auto count = static_cast<VertexId>(stands_for.size());
  VertexId* v = m.tds.vertex_array().data();
  for (std::size_t k = 0; k < 3 * m.size(); ++k)
    if (v[k] >= first) v[k] = v[k] < first + count ? stands_for[v[k] - first] : v[k] - count;
  m.pts.erase(m.pts.begin() + first, m.pts.begin() + first + count);
  m.index_corners();
}

}  // namespace ridt::detail
