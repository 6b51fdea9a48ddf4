// The constrained triangulation (constrained/cdt.hpp): walking, adding points and flipping,
// on the one mutable triangulation. Edge k of a triangle runs from its corner k + 1 to corner
// k + 2 (counter-clockwise), across from corner k.
#include "constrained/cdt.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>
#include <new>
#include <stdexcept>

#include "predicates/predicates.hpp"

namespace ridt::detail {

Cdt::Cdt(std::vector<Point> points, Triangulation& t, bool linked, unsigned threads)
    : tds(linked ? Tds::from_links(std::move(t.triangles), std::move(t.neighbors))
                 : Tds::from_neighbours(std::move(t.triangles), std::move(t.neighbors), threads)),
      pts(std::move(points)) {
  t.triangles = {}, t.neighbors = {};
  tds.use_constraints(true, threads);
  index_corners();
}

void Cdt::index_corners() {
  corner.assign(pts.size(), kNoTriangle);
  for (TriangleId t = 0; t < tds.slots(); ++t)
    for (int k = 0; k < 3; ++k) corner[tds.vertex(t, k)] = 3 * t + static_cast<TriangleId>(k);
}

SlotPool Cdt::fresh(TriangleId count, TriangleId like) {
  SlotPool pool = tds.fresh(count);
  if (!region.empty()) region.resize(tds.slots(), region[like]);
  return pool;
}

std::size_t Cdt::room() const {
  const std::size_t slots = tds.slots();
  auto left = [](const auto& v, std::size_t used) { return v.capacity() - std::min(v.capacity(), used); };
  std::size_t points = std::min({left(pts, pts.size()), left(corner, corner.size()), tds.room() / 2});
  if (!region.empty()) points = std::min(points, left(region, slots) / 2);
  if (!mark.empty()) points = std::min(points, left(mark, slots) / 2);
  return points;
}

void Cdt::make_room(std::size_t points, std::size_t least) {
  least = std::min(least, points);
  // v, with `used` items, grown to take n where it cannot take `least` points more (k items a
  // point).
  auto grow = [&](auto& v, std::size_t used, std::size_t n, std::size_t k) {
    if (used + k * least <= v.capacity() || n <= v.capacity()) return;
    try {
      v.reserve(std::max(n, 2 * v.capacity()));
    } catch (const std::bad_alloc&) {
      v.reserve(n);
    }
  };
  const std::size_t slots = tds.slots() + 2 * points;
  if (tds.room() < 2 * least) tds.reserve(static_cast<TriangleId>(slots));
  grow(pts, pts.size(), pts.size() + points, 1);
  grow(corner, corner.size(), corner.size() + points, 1);
  if (!region.empty()) grow(region, tds.slots(), slots, 2);
  if (!mark.empty()) grow(mark, tds.slots(), slots, 2);
  todo_.reserve(kScratch), spokes_.reserve(kScratch);
}

VertexId Cdt::add_point(const Point& p) {
  const auto v = static_cast<VertexId>(pts.size());
  pts.push_back(p);
  corner.push_back(kNoTriangle);
  return v;
}

Link Cdt::find_edge(VertexId a, VertexId b) const {
  Link slot = kNoLink;
  around(a, [&](TriangleId t) {
    const int i = corner_of(t, a);
    if (at(t, i + 1) == b) slot = link_to(t, prev3(i));
    if (at(t, i + 2) == b) slot = link_to(t, next3(i));
    return slot != kNoLink;
  });
  return slot;
}

std::vector<TriangleId> Cdt::ring(VertexId v) const {
  std::vector<TriangleId> out;
  around(v, [&](TriangleId t) {
    out.push_back(t);
    return false;
  });
  return out;
}

Cdt::Place Cdt::locate(TriangleId from, const Point& p, bool stop_at_fixed) const {
  TriangleId t = from;
  // A walk across fixed edges can circle: it is stopped after as many steps as the
  // triangulation could need.
  const std::size_t limit = 4 * size() + 64;
  std::size_t steps = 0;
  bool circled = false;
  const Walked end = tds.walk(
      t, [&](VertexId a, VertexId b) { return orient2d(pts[a], pts[b], p); },
      [&](Link l) {
        if (l == kNoLink) return Step::Stop;
        if (++steps > limit) return circled = true, Step::Stop;
        return stop_at_fixed && tds.fixed(l) ? Step::Stop : Step::Cross;
      });
  if (circled) throw std::logic_error("ridt: a walk in the constrained triangulation did not end");
  if (!end.reached) return {boundary(link_to(t, end.edge)) ? Place::Outside : Place::Blocked, t, end.edge};
  if (end.zeros == 0) return {Place::Inside, t, 0};
  if ((end.zeros & (end.zeros - 1)) == 0) return {Place::Edge, t, std::countr_zero(unsigned{end.zeros})};
  for (int k = 0; k < 3; ++k)
    if (!((end.zeros >> k) & 1)) return {Place::Corner, t, k};
  throw std::logic_error("ridt: a point on all three lines of a triangle");
}

VertexId Cdt::insert(const Point& p, const Place& where) {
  const VertexId v = add_point(p);
  const TriangleId t = where.t;
  if (where.kind == Place::Inside) {
    SlotPool pool = fresh(2, t);
    const std::array<TriangleId, 3> made = tds.split_triangle(t, v, pool);
    claim_corners(made);
    todo_.assign({made[0], made[1], made[2]});
    legalize(v);
    return v;
  }
  if (where.kind != Place::Edge) throw std::logic_error("ridt: a point added where it cannot be");
  const Link e = link_to(t, where.k);
  const TriangleId u = across(e);
  SlotPool pool = fresh(1, t);
  if (u != kNoTriangle) {
    // The second new slot follows the first, in the region of the triangle across.
    pool.end = tds.grow(1) + 1;
    if (!region.empty()) region.resize(tds.slots(), region[u]);
  }
  const std::array<TriangleId, 4> made = tds.split_edge(e, v, pool);
  claim_corners(made);
  todo_.assign({made[0], made[1]});
  if (u != kNoTriangle) todo_.push_back(made[2]), todo_.push_back(made[3]);
  legalize(v);
  return v;
}

void Cdt::legalize(VertexId p) {
  std::vector<TriangleId>& todo = todo_;
  while (!todo.empty()) {
    const TriangleId t = todo.back();
    todo.pop_back();
    const Link e = link_to(t, corner_of(t, p));
    const Link l = tds.link_at(e);
    if (l == kNoLink || tds.fixed(e)) continue;
    const VertexId d = tds.opposite(l);
    if (incircle(pts[at(t, 0)], pts[at(t, 1)], pts[at(t, 2)], pts[d]) <= 0) continue;
    const TriangleId n = triangle_of(l);
    tds.flip(e);
    claim_corners(std::array<TriangleId, 2>{t, n});
    todo.push_back(t), todo.push_back(n);
  }
}

// Whether p, added on edge k of t as though it lay on it, leaves every triangle there
// counter-clockwise (a rounded split point lies off its segment by a rounding error).
bool Cdt::fits_on_edge(TriangleId t, int k, const Point& p) const {
  const Point &x = pts[at(t, k + 1)], &y = pts[at(t, k + 2)];
  if (orient2d(pts[at(t, k)], x, p) <= 0 || orient2d(pts[at(t, k)], p, y) <= 0) return false;
  const VertexId d = apex_across(link_to(t, k));
  if (d == kNoVertex) return orient2d(x, y, p) >= 0;  // on the boundary: not beyond it
  return orient2d(pts[d], y, p) > 0 && orient2d(pts[d], p, x) > 0;
}

Point Cdt::not_beyond(TriangleId t, int k, Point p) const {
  const Point &x = pts[at(t, k + 1)], &y = pts[at(t, k + 2)];
  // t lies left of x -> y: toward it is the left normal's way, an ulp a step in each
  // coordinate that moves (a rounding off the line, so a few steps).
  const double nx = x.y - y.y, ny = y.x - x.x;
  for (int step = 0; step < 64 && orient2d(x, y, p) < 0; ++step) {
    if (nx != 0) p.x = std::nextafter(p.x, nx > 0 ? HUGE_VAL : -HUGE_VAL);
    if (ny != 0) p.y = std::nextafter(p.y, ny > 0 ? HUGE_VAL : -HUGE_VAL);
  }
  return p;
}

std::uint32_t Cdt::new_mark() {
  if (++marks_ == 0) std::fill(mark.begin(), mark.end(), 0), marks_ = 1;
  mark.resize(size(), 0);
  return marks_;
}

void Cdt::find_cavity(const Point& p, const Place& at) {
  // Triangles met are searched for among the cavity's while they are few, marked once they are
  // many (searches through m are m^2 steps, and m can be thousands where coordinates span the
  // doubles' range; for the few of a typical cavity the searches are faster).
  std::uint32_t stamp = 0;
  auto seen = [&](TriangleId u, const TriangleId* cavity, std::size_t count) {
    if (count <= kSearched) return std::find(cavity, cavity + count, u) != cavity + count;
    if (stamp == 0) {
      stamp = new_mark();
      for (std::size_t k = 0; k < count; ++k) mark[cavity[k]] = stamp;
    }
    if (mark[u] == stamp) return true;
    mark[u] = stamp;  // it joins
    return false;
  };
  tds.find_cavity<true>(
      at.t, scratch_, [&](const VertexId* w) { return incircle(pts[w[0]], pts[w[1]], pts[w[2]], p) > 0; },
      Tds::kAnywhere, [&](Link e) { return tds.fixed(e); }, seen);
}

VertexId Cdt::insert_cavity(const Point& p) {
  const CavityScratch& s = scratch_;
  if (s.revisited || s.edges != s.size + 2) return kNoVertex;  // not a disc
  for (std::size_t i = 0; i < s.edges; ++i)  // p must see every boundary edge from inside
    if (orient2d(pts[s.boundary[i].a], pts[s.boundary[(i + 1) % s.edges].a], p) <= 0) return kNoVertex;
  const VertexId v = add_point(p);
  SlotPool pool = fresh(2, s.cavity[0]);
  tds.fill_cavity(v, scratch_, pool);
  for (std::size_t i = 0; i < s.edges; ++i)
    for (int k = 0; k < 3; ++k) corner[at(s.cavity[i], k)] = 3 * s.cavity[i] + static_cast<TriangleId>(k);
  return v;
}

void Cdt::restore(std::vector<Link> edges) { flip_from(edges); }

bool Cdt::remove_free(VertexId v) {
  std::vector<TriangleId> star = ring(v);  // (what may allocate does so before any change)
  std::vector<std::pair<VertexId, VertexId>> made;  // the edges the flips made (their slots move)
  std::vector<Link> edges;  // Lawson's from those: at most some k^2 flips in a polygon of k sides
  made.reserve(star.size()), freed.reserve(freed.size() + 2), edges.reserve(4 * star.size() * star.size() + 8);
  for (const TriangleId t : star) {
    const int i = corner_of(t, v);
    if (boundary(link_to(t, next3(i))) || fixed(link_to(t, next3(i))) || fixed(link_to(t, prev3(i)))) return false;
  }
  auto restore_made = [&] {
    for (const auto& [a, b] : made)
      if (const Link e = find_edge(a, b); e != kNoLink) edges.push_back(e);
    flip_from(edges);
  };
  // Edge v-w of t = (v, a, w) flips to a-b (u = (v, w, b) beyond it) where a, w, b turn left and
  // so do b, v, a: both new triangles are counter-clockwise.
  while (star.size() > 3) {
    const auto flips = std::find_if(star.begin(), star.end(), [&](TriangleId t) {
      const int i = corner_of(t, v);
      const VertexId a = at(t, i + 1), w = at(t, i + 2), b = tds.opposite(tds.link(t, next3(i)));
      return orient2d(pts[a], pts[w], pts[b]) > 0 && orient2d(pts[b], pts[v], pts[a]) > 0;
    });
    if (flips == star.end()) {
      restore_made();
      return false;
    }
    const int i = corner_of(*flips, v);
    made.emplace_back(at(*flips, i + 1), tds.opposite(tds.link(*flips, next3(i))));
    flip(link_to(*flips, next3(i)));
    star.clear();  // (one fewer: no allocation)
    around(v, [&](TriangleId t) { return star.push_back(t), false; });
  }
  merge_three(v, star);
  restore_made();  // (the ring's edges were locally Delaunay from outside, so are still)
  return true;
}

void Cdt::merge_three(VertexId v, const std::vector<TriangleId>& star) {
  // (v, a, b), (v, b, c), (v, c, a) become (a, b, c) in the first's slot.
  const TriangleId t0 = star[0];
  VertexId corners[3] = {at(t0, corner_of(t0, v) + 1), at(t0, corner_of(t0, v) + 2), kNoVertex};
  Link outer[3];
  Constraint inner[3];
  for (const TriangleId t : star) {
    const int i = corner_of(t, v);
    const VertexId x = at(t, i + 1);
    const int k = x == corners[0] ? 2 : x == corners[1] ? 0 : 1;  // the new corner across from that edge
    if (k == 0) corners[2] = at(t, i + 2);
    outer[k] = tds.link(t, i), inner[k] = tds.constraint(link_to(t, i));
  }
  for (int k = 0; k < 3; ++k) {
    tds.set_vertex(t0, k, corners[k]);
    tds.set_link(link_to(t0, k), outer[k]);
    if (outer[k] != kNoLink) tds.set_link(outer[k], link_to(t0, k));
    tds.set_constraint(link_to(t0, k), inner[k]);
  }
  for (const TriangleId t : star)
    if (t != t0) tds.free_slot(t), freed.push_back(t);
  claim_corners(std::array<TriangleId, 1>{t0});
  corner[v] = kNoTriangle;
}

void Cdt::flip_from(std::vector<Link>& edges) {
  while (!edges.empty()) {
    const Link e = edges.back();
    edges.pop_back();
    const Link l = tds.link_at(e);
    if (l == kNoLink || tds.fixed(e)) continue;
    const TriangleId t = triangle_of(e), u = triangle_of(l);
    if (incircle(pts[at(t, 0)], pts[at(t, 1)], pts[at(t, 2)], pts[tds.opposite(l)]) <= 0) continue;
    tds.flip(e);  // t is now (p, a, d), u (p, d, b): their sides away from the new edge p-d
    claim_corners(std::array<TriangleId, 2>{t, u});
    edges.insert(edges.end(), {link_to(t, 0), link_to(t, 2), link_to(u, 0), link_to(u, 1)});
  }
}

void Cdt::drop_slots(const std::vector<std::uint8_t>& gone) {
  const std::size_t nt = size();
  std::vector<TriangleId> id(nt, kNoTriangle);
  TriangleId kept = 0;
  for (std::size_t t = 0; t < nt; ++t)
    if (!gone[t]) id[t] = kept++;
  for (TriangleId t = 0; t < nt; ++t) {
    if (gone[t]) continue;
    const TriangleId to = id[t];
    for (int j = 0; j < 3; ++j) {
      const Link l = tds.link(t, j);
      const TriangleId n = l == kNoLink ? kNoTriangle : id[triangle_of(l)];
      tds.set_vertex(to, j, tds.vertex(t, j));
      tds.set_constraint(link_to(to, j), tds.constraint(link_to(t, j)));
      tds.set_link(link_to(to, j), n == kNoTriangle ? kNoLink : link_to(n, edge_of(l)));
    }
    if (!region.empty()) region[to] = region[t];
  }
  tds.truncate(kept);
  if (!region.empty()) region.resize(kept);
  if (!mark.empty()) mark.assign(kept, 0);
  index_corners();
}

void Cdt::compact(std::vector<VertexId> dead) {
  // Each dead vertex's place taken by the last vertex, the largest first (so the last is alive),
  // its triangles and corner told; each freed slot's by the last slot, its neighbours and its
  // corners told. A few dozen moves, where renumbering every vertex and slot after the first
  // gap in order rewrote the whole mesh (0.3 s at 10^7 triangles, on one thread).
  std::sort(dead.begin(), dead.end(), std::greater<>());
  for (const VertexId d : dead) {
    const auto last = static_cast<VertexId>(pts.size() - 1);
    if (d != last) {
      if (corner[last] != kNoTriangle)
        for (const TriangleId t : ring(last)) tds.set_vertex(t, corner_of(t, last), d);
      pts[d] = pts[last], corner[d] = corner[last];
    }
    pts.pop_back(), corner.pop_back();
  }
  std::sort(freed.begin(), freed.end(), std::greater<>());
  for (const TriangleId f : freed) {
    const TriangleId last = size() - 1;
    if (f != last) {
      for (int j = 0; j < 3; ++j) {
        const Link l = tds.link(last, j);
        tds.set_vertex(f, j, tds.vertex(last, j));
        tds.set_constraint(link_to(f, j), tds.constraint(link_to(last, j)));
        tds.set_link(link_to(f, j), l);
        if (l != kNoLink) tds.set_link(l, link_to(f, j));
        if (corner[tds.vertex(f, j)] / 3 == last) corner[tds.vertex(f, j)] = 3 * f + static_cast<TriangleId>(j);
      }
      if (!region.empty()) region[f] = region[last];
    }
    tds.truncate(last);
  }
  if (!region.empty()) region.resize(size());
  if (!mark.empty()) mark.assign(size(), 0);
  freed.clear();
}

VertexId Cdt::insert_on_edge(const Point& p, TriangleId t, int k) {
  const bool on_line = orient2d(pts[at(t, k + 1)], pts[at(t, k + 2)], p) == 0;
  const VertexId v = insert(p, {Place::Edge, t, k});
  if (on_line) return v;
  std::vector<Link>& spokes = spokes_;
  spokes.clear();
  around(v, [&](TriangleId u) {
    const int i = corner_of(u, v);
    spokes.push_back(link_to(u, next3(i))), spokes.push_back(link_to(u, prev3(i)));
    return false;
  });
  flip_from(spokes);
  return v;
}

// Where x, a rounding away from edge k of t, lies: in t or the triangle across (inside, on
// an edge or at a corner), else Outside.
Cdt::Place Cdt::beside(TriangleId t, int k, const Point& x) const {
  const TriangleId n = k < 0 ? kNoTriangle : across(link_to(t, k));  // k < 0: t alone
  for (const TriangleId r : {t, n}) {
    if (r == kNoTriangle) continue;
    int zeros = 0, zero = 0, outside = 0;
    for (int j = 0; j < 3; ++j) {
      const int o = orient2d(pts[at(r, j + 1)], pts[at(r, j + 2)], x);
      outside += o < 0;
      if (o == 0) ++zeros, zero = j;
    }
    if (outside > 0) continue;
    if (zeros == 0) return {Place::Inside, r, 0};
    if (zeros == 1) return {Place::Edge, r, zero};
    for (int j = 0; j < 3; ++j)
      if (orient2d(pts[at(r, j + 1)], pts[at(r, j + 2)], x) != 0) return {Place::Corner, r, j};
  }
  return {Place::Outside, t, std::max(k, 0)};
}

Cdt::Place Cdt::find(TriangleId from, const Point& p) const {
  try {
    const Place at = locate(from, p, false);
    if (at.kind != Place::Outside) return at;
  } catch (const std::logic_error&) {  // a walk across fixed edges can circle
  }
  for (TriangleId t = 0; t < size(); ++t)
    if (const Place at = beside(t, -1, p); at.kind != Place::Outside) return at;
  return {Place::Outside, from, 0};
}

}  // namespace ridt::detail
