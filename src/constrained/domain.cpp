// Carving and regions (constrained/domain.hpp): floods across the edges that are not fixed.
#include "constrained/domain.hpp"

#include <algorithm>
#include <optional>

namespace ridt::detail {
namespace {

// Where q lies (inside a triangle, on an edge or at a corner), or nothing where no triangle
// holds it; `from` (a hint) moves to its triangle.
std::optional<Cdt::Place> place(const Cdt& m, const Point& q, std::uint32_t& from) {
  if (m.size() == 0) return std::nullopt;
  const Cdt::Place at = m.find(std::min<std::uint32_t>(from, static_cast<std::uint32_t>(m.size() - 1)), q);
  if (at.kind == Cdt::Place::Outside) return std::nullopt;
  from = at.t;
  return at;
}

// The triangles whose closure holds q: one, or two beside an edge, or every one about a vertex
// (a hole's seed there empties them all: the validator finds no seed inside or on a triangle;
// a region's marks them all, whichever the walk to it met first).
std::vector<std::uint32_t> holding_all(const Cdt& m, const Point& q, std::uint32_t& from) {
  std::vector<std::uint32_t> out;
  const std::optional<Cdt::Place> at = place(m, q, from);
  if (!at) return out;
  if (at->kind == Cdt::Place::Corner) {
    const VertexId v = m.at(at->t, at->k);
    bool open = false;  // a fan that ends at the boundary: where the domain touches itself at v, one of several
    m.around(v, [&](std::uint32_t t) {
      const int i = m.corner_of(t, v);
      open = open || m.nbrs[3 * t + (i + 1) % 3] < 0 || m.nbrs[3 * t + (i + 2) % 3] < 0;
      return out.push_back(t), false;
    });
    if (open) {  // every triangle at v, whichever fan it is in
      out.clear();
      for (std::uint32_t t = 0; t < m.size(); ++t)
        if (m.tris[3 * t] == v || m.tris[3 * t + 1] == v || m.tris[3 * t + 2] == v) out.push_back(t);
    }
    return out;
  }
  out.push_back(at->t);
  if (const std::int32_t n = m.nbrs[3 * at->t + at->k]; at->kind == Cdt::Place::Edge && n >= 0)
    out.push_back(static_cast<std::uint32_t>(n));
  return out;
}

// Every triangle reached from `seed` across edges that are not fixed, given `mark` (those
// whose mark is already `mark` are not entered again). Breadth first: a triangle's links are
// asked for when it is queued, and read some way on, when its turn comes.
template <class T>
void flood(const Cdt& m, std::uint32_t seed, std::vector<T>& label, T mark) {
  if (label[seed] == mark) return;
  std::vector<std::uint32_t> queue{seed};
  label[seed] = mark;
  for (std::size_t next = 0; next < queue.size(); ++next) {
    const std::uint32_t t = queue[next];
    for (int j = 0; j < 3; ++j) {
      const std::int32_t n = m.nbrs[3 * t + j];
      if (n < 0 || m.fixed[3 * t + j] || label[n] == mark) continue;
      label[n] = mark;
      __builtin_prefetch(&m.nbrs[3 * static_cast<std::size_t>(n)]);
      __builtin_prefetch(&m.fixed[3 * static_cast<std::size_t>(n)]);
      queue.push_back(static_cast<std::uint32_t>(n));
    }
  }
}

// Triangles whose `gone` is set removed; the rest renumbered in order. The vertices' corners
// are set again where `corners` asks it, else left unset.
void remove(Cdt& m, const std::vector<std::uint8_t>& gone, bool corners) {
  const std::size_t nt = m.size();
  std::vector<std::int32_t> id(nt, -1);
  std::uint32_t kept = 0;
  for (std::size_t t = 0; t < nt; ++t)
    if (!gone[t]) id[t] = static_cast<std::int32_t>(kept++);
  for (std::size_t t = 0; t < nt; ++t) {
    if (gone[t]) continue;
    const auto to = static_cast<std::size_t>(id[t]);
    for (int j = 0; j < 3; ++j) {
      m.tris[3 * to + j] = m.tris[3 * t + j];
      m.fixed[3 * to + j] = m.fixed[3 * t + j];
      const std::int32_t n = m.nbrs[3 * t + j];
      m.nbrs[3 * to + j] = n < 0 ? -1 : id[static_cast<std::size_t>(n)];
    }
  }
  m.tris.resize(3 * kept), m.nbrs.resize(3 * kept), m.fixed.resize(3 * kept);
  if (corners)
    m.index_corners();
  else
    std::fill(m.corner.begin(), m.corner.end(), Cdt::kNone);
}

}  // namespace

bool carve(Cdt& m, const std::vector<Point>& holes, const std::vector<Region>& regions, bool convex_hull,
           bool corners) {
  const std::size_t nt = m.size();
  std::vector<std::uint8_t> gone(nt, 0);
  for (std::uint32_t t = 0; t < nt && !convex_hull; ++t)
    for (int j = 0; j < 3; ++j)
      if (m.nbrs[3 * t + j] < 0 && !m.fixed[3 * t + j]) flood<std::uint8_t>(m, t, gone, 1);
  std::uint32_t from = 0;
  for (const Point& h : holes)
    for (const std::uint32_t t : holding_all(m, h, from)) flood<std::uint8_t>(m, t, gone, 1);
  const bool removed = std::find(gone.begin(), gone.end(), 1) != gone.end();
  if (removed) remove(m, gone, corners || !regions.empty());  // a region's seed at a vertex walks round it
  if (regions.empty()) return removed;
  m.region.assign(m.size(), -1);
  for (std::size_t r = 0; r < regions.size(); ++r)
    for (const std::uint32_t t : holding_all(m, regions[r].seed, from))
      flood<std::int32_t>(m, t, m.region, static_cast<std::int32_t>(r));
  return removed;
}

std::vector<VertexId> split_pinches(Cdt& m) {
  // A fan about a vertex on the boundary begins at the boundary edge that leaves it (v -> w, the
  // fan's triangle on its left): count them.
  const auto tail = [&m](std::uint32_t s) { return m.tris[s - s % 3 + (s % 3 + 1) % 3]; };
  std::vector<std::uint32_t> fans(m.pts.size(), 0);
  for (std::uint32_t s = 0; s < m.tris.size(); ++s)
    if (m.nbrs[s] < 0) ++fans[tail(s)];
  std::vector<VertexId> stands_for;
  for (std::uint32_t s = 0; s < m.tris.size(); ++s) {
    const VertexId v = tail(s);
    if (m.nbrs[s] >= 0 || v >= fans.size() || fans[v] < 2) continue;  // (a fan leaves its vertex once)
    --fans[v];  // the last fan found keeps v
    const auto alias = static_cast<VertexId>(m.pts.size());
    m.pts.push_back(m.pts[v]);
    m.corner.push_back(s - s % 3 + (s % 3 + 1) % 3);
    stands_for.push_back(v);
    // Counter-clockwise about v from the leaving edge, across the edges that come into v.
    for (std::int32_t t = static_cast<std::int32_t>(s / 3); t >= 0;) {
      const int i = m.corner_of(static_cast<std::uint32_t>(t), v);
      m.tris[3 * t + i] = alias;
      t = m.nbrs[3 * t + (i + 1) % 3];
    }
  }
  if (!stands_for.empty()) m.index_corners();
  return stands_for;
}

void merge_pinches(Cdt& m, VertexId first, const std::vector<VertexId>& stands_for) {
  if (stands_for.empty()) return;
  const auto count = static_cast<VertexId>(stands_for.size());
  for (VertexId& v : m.tris)
    if (v >= first) v = v < first + count ? stands_for[v - first] : v - count;
  m.pts.erase(m.pts.begin() + first, m.pts.begin() + first + count);
  m.index_corners();
}

}  // namespace ridt::detail
