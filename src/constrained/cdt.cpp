// The mutable constrained triangulation (constrained/cdt.hpp): walking, adding points and
// flipping. Edge k of a triangle runs from its corner k + 1 to corner k + 2 (counter-clockwise),
// across from corner k; neighbour k is the triangle beyond it.
#include "constrained/cdt.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "predicates/predicates.hpp"

namespace ridt::detail {

Cdt::Cdt(std::vector<Point> points, Triangulation& t)
    : pts(std::move(points)), tris(std::move(t.triangles)), nbrs(std::move(t.neighbors)) {
  fixed.assign(tris.size(), 0);
  index_corners();
}

void Cdt::index_corners() {
  corner.assign(pts.size(), kNone);
  for (std::size_t k = 0; k < tris.size(); ++k) corner[tris[k]] = static_cast<std::uint32_t>(k);
}

void Cdt::set(std::uint32_t t, const VertexId (&v)[3], const std::int32_t (&n)[3], const std::uint8_t (&f)[3]) {
  for (int k = 0; k < 3; ++k) {
    tris[3 * t + k] = v[k];
    nbrs[3 * t + k] = n[k];
    fixed[3 * t + k] = f[k];
    corner[v[k]] = 3 * t + k;
  }
}

void Cdt::relink(std::int32_t n, std::uint32_t from, std::uint32_t to) {
  if (n >= 0) nbrs[3 * n + back(static_cast<std::uint32_t>(n), from)] = static_cast<std::int32_t>(to);
}

std::uint32_t Cdt::add_triangle(std::uint32_t like) {
  const auto t = static_cast<std::uint32_t>(size());
  tris.resize(tris.size() + 3);
  nbrs.resize(nbrs.size() + 3, -1);
  fixed.resize(fixed.size() + 3, 0);
  if (!region.empty()) region.push_back(region[like]);
  return t;
}

void Cdt::set_fixed(std::uint32_t t, int k, bool on) {
  fixed[3 * t + k] = on;
  if (const std::int32_t n = nbrs[3 * t + k]; n >= 0) fixed[3 * n + back(static_cast<std::uint32_t>(n), t)] = on;
}

std::uint32_t Cdt::find_edge(VertexId a, VertexId b) const {
  std::uint32_t slot = kNone;
  around(a, [&](std::uint32_t t) {
    const int i = corner_of(t, a);
    if (at(t, i + 1) == b) slot = 3 * t + (i + 2) % 3;
    if (at(t, i + 2) == b) slot = 3 * t + (i + 1) % 3;
    return slot != kNone;
  });
  return slot;
}

std::vector<std::uint32_t> Cdt::ring(VertexId v) const {
  std::vector<std::uint32_t> out;
  around(v, [&](std::uint32_t t) {
    out.push_back(t);
    return false;
  });
  return out;
}

Cdt::Place Cdt::locate(std::uint32_t from, const Point& p, bool stop_at_fixed) const {
  std::uint32_t t = from;
  const std::size_t limit = 4 * size() + 64;
  for (std::size_t steps = 0, turn = 0; steps < limit; ++steps) {
    int zeros = 0, zero = 0;
    bool moved = false;
    for (int r = 0; r < 3 && !moved; ++r) {
      const int k = static_cast<int>((r + turn) % 3);
      const int o = orient2d(pts[at(t, k + 1)], pts[at(t, k + 2)], p);
      if (o == 0) ++zeros, zero = k;
      if (o >= 0) continue;
      if (stop_at_fixed && fixed[3 * t + k]) return {Place::Blocked, t, k};
      if (nbrs[3 * t + k] < 0) return {Place::Outside, t, k};
      t = static_cast<std::uint32_t>(nbrs[3 * t + k]);
      moved = true;
    }
    turn += 7;
    if (moved) continue;
    if (zeros == 0) return {Place::Inside, t, 0};
    if (zeros == 1) return {Place::Edge, t, zero};
    for (int k = 0; k < 3; ++k)
      if (orient2d(pts[at(t, k + 1)], pts[at(t, k + 2)], p) != 0) return {Place::Corner, t, k};
  }
  throw std::logic_error("ridt: a walk in the constrained triangulation did not end");
}

VertexId Cdt::insert(const Point& p, const Place& where) {
  const auto v = static_cast<VertexId>(pts.size());
  pts.push_back(p);
  corner.push_back(kNone);
  const std::uint32_t t = where.t;
  if (where.kind == Place::Inside) {
    const VertexId a = tris[3 * t], b = tris[3 * t + 1], c = tris[3 * t + 2];
    const std::int32_t na = nbrs[3 * t], nb = nbrs[3 * t + 1], nc = nbrs[3 * t + 2];
    const std::uint8_t fa = fixed[3 * t], fb = fixed[3 * t + 1], fc = fixed[3 * t + 2];
    const std::uint32_t t1 = add_triangle(t), t2 = add_triangle(t);
    const auto i0 = std::int32_t(t), i1 = std::int32_t(t1), i2 = std::int32_t(t2);
    set(t, {a, b, v}, {i1, i2, nc}, {0, 0, fc});
    set(t1, {b, c, v}, {i2, i0, na}, {0, 0, fa});
    set(t2, {c, a, v}, {i0, i1, nb}, {0, 0, fb});
    relink(na, t, t1);
    relink(nb, t, t2);
    legalize(v, {t, t1, t2});
    return v;
  }
  if (where.kind != Place::Edge) throw std::logic_error("ridt: a point added where it cannot be");
  const int k = where.k;
  const VertexId a = at(t, k), x = at(t, k + 1), y = at(t, k + 2);
  const std::int32_t n1 = nbrs[3 * t + (k + 1) % 3], n2 = nbrs[3 * t + (k + 2) % 3];
  const std::uint8_t f1 = fixed[3 * t + (k + 1) % 3], f2 = fixed[3 * t + (k + 2) % 3], fe = fixed[3 * t + k];
  const std::int32_t n = nbrs[3 * t + k];
  const std::uint32_t t1 = add_triangle(t);
  std::uint32_t m1 = kNone;
  if (n >= 0) m1 = add_triangle(static_cast<std::uint32_t>(n));
  const std::int32_t out1 = n >= 0 ? std::int32_t(m1) : -1, out2 = n;
  set(t, {a, x, v}, {out1, std::int32_t(t1), n2}, {fe, 0, f2});
  set(t1, {a, v, y}, {out2, n1, std::int32_t(t)}, {fe, f1, 0});
  relink(n1, t, t1);
  std::vector<std::uint32_t> todo{t, t1};
  if (n >= 0) {
    const auto u = static_cast<std::uint32_t>(n);
    const int j = back(u, t);
    const VertexId d = at(u, j);  // u is (d, y, x)
    const std::int32_t g1 = nbrs[3 * u + (j + 1) % 3], g2 = nbrs[3 * u + (j + 2) % 3];  // across (x, d), (d, y)
    const std::uint8_t h1 = fixed[3 * u + (j + 1) % 3], h2 = fixed[3 * u + (j + 2) % 3];
    set(u, {d, y, v}, {std::int32_t(t1), std::int32_t(m1), g2}, {fe, 0, h2});
    set(m1, {d, v, x}, {std::int32_t(t), g1, n}, {fe, h1, 0});
    relink(g1, u, m1);
    todo.push_back(u), todo.push_back(m1);
  }
  legalize(v, std::move(todo));
  return v;
}

void Cdt::flip(std::uint32_t t, int i) {
  const auto n = static_cast<std::uint32_t>(nbrs[3 * t + i]);
  const int j = back(n, t);
  const VertexId p = at(t, i), a = at(t, i + 1), b = at(t, i + 2), d = at(n, j);  // t (p, a, b), n (d, b, a)
  const std::int32_t ta = nbrs[3 * t + (i + 1) % 3], tb = nbrs[3 * t + (i + 2) % 3];
  const std::int32_t nb = nbrs[3 * n + (j + 1) % 3], na = nbrs[3 * n + (j + 2) % 3];
  const std::uint8_t fta = fixed[3 * t + (i + 1) % 3], ftb = fixed[3 * t + (i + 2) % 3];
  const std::uint8_t fnb = fixed[3 * n + (j + 1) % 3], fna = fixed[3 * n + (j + 2) % 3];
  set(t, {p, a, d}, {nb, std::int32_t(n), tb}, {fnb, 0, ftb});
  set(n, {p, d, b}, {na, ta, std::int32_t(t)}, {fna, fta, 0});
  relink(nb, n, t);
  relink(ta, t, n);
}

void Cdt::legalize(VertexId p, std::vector<std::uint32_t> todo) {
  while (!todo.empty()) {
    const std::uint32_t t = todo.back();
    todo.pop_back();
    const int i = corner_of(t, p);
    const std::int32_t n = nbrs[3 * t + i];
    if (n < 0 || fixed[3 * t + i]) continue;
    const VertexId d = at(static_cast<std::uint32_t>(n), back(static_cast<std::uint32_t>(n), t));
    if (incircle(pts[tris[3 * t]], pts[tris[3 * t + 1]], pts[tris[3 * t + 2]], pts[d]) <= 0) continue;
    flip(t, i);
    todo.push_back(t), todo.push_back(static_cast<std::uint32_t>(n));
  }
}

// Whether p, added on edge k of t as though it lay on it, leaves every triangle there
// counter-clockwise (a rounded split point lies off its segment by a rounding error).
bool Cdt::fits_on_edge(std::uint32_t t, int k, const Point& p) const {
  const Point &x = pts[at(t, k + 1)], &y = pts[at(t, k + 2)];
  if (orient2d(pts[at(t, k)], x, p) <= 0 || orient2d(pts[at(t, k)], p, y) <= 0) return false;
  const std::int32_t n = nbrs[3 * t + k];
  if (n < 0) return orient2d(x, y, p) >= 0;  // on the boundary: not beyond it
  const Point& d = pts[at(static_cast<std::uint32_t>(n), back(static_cast<std::uint32_t>(n), t))];
  return orient2d(d, y, p) > 0 && orient2d(d, p, x) > 0;
}

Point Cdt::not_beyond(std::uint32_t t, int k, Point p) const {
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

VertexId Cdt::insert_cavity(const Point& p, const std::vector<std::uint32_t>& cavity) {
  // A cavity's triangles, and below the rim edges by their ends, searched for where they are
  // few, marked and sorted where they are many (searches through m are m^2 steps, and m can
  // be thousands where coordinates span the doubles' range; for the few of a typical cavity
  // the searches are faster).
  const bool many = cavity.size() > kSearched;
  const std::uint32_t stamp = many ? new_mark() : 0;
  for (const std::uint32_t t : cavity)
    if (many) mark[t] = stamp;
  auto inside = [&](std::int32_t n) {
    if (n < 0) return false;
    const auto u = static_cast<std::uint32_t>(n);
    return many ? mark[u] == stamp : std::find(cavity.begin(), cavity.end(), u) != cavity.end();
  };
  rim_.clear();
  for (const std::uint32_t t : cavity)
    for (int k = 0; k < 3; ++k) {
      const std::int32_t n = nbrs[3 * t + k];
      if (inside(n)) continue;
      const VertexId x = at(t, k + 1), y = at(t, k + 2);
      if (orient2d(pts[x], pts[y], p) <= 0) return kNone;  // p does not see this edge from inside
      rim_.push_back({x, y, n, n >= 0 ? back(static_cast<std::uint32_t>(n), t) : -1, fixed[3 * t + k]});
    }
  if (rim_.size() != cavity.size() + 2) return kNone;  // not a disc
  const auto v = static_cast<VertexId>(pts.size());
  pts.push_back(p);
  corner.push_back(kNone);
  std::vector<std::uint32_t>& fan = fan_;
  fan.assign(cavity.begin(), cavity.end());
  fan.push_back(add_triangle(cavity[0]));
  fan.push_back(add_triangle(cavity[0]));
  // The fan triangle (x, y, p) of each rim edge; its neighbours across (y, p) and (p, x) are
  // the fan triangles that start at y and end at x (the first rim edge that does), found in
  // the rim edges sorted by their ends.
  from_.clear(), to_.clear();
  for (std::uint32_t i = 0; i < rim_.size() && many; ++i)
    from_.push_back({rim_[i].x, i}), to_.push_back({rim_[i].y, i});
  std::sort(from_.begin(), from_.end()), std::sort(to_.begin(), to_.end());
  auto first_of = [&](const std::vector<std::pair<VertexId, std::uint32_t>>& sorted, VertexId v, bool at_x) {
    if (!many) {
      for (std::size_t i = 0; i < rim_.size(); ++i)
        if ((at_x ? rim_[i].x : rim_[i].y) == v) return static_cast<std::int32_t>(fan[i]);
      return std::int32_t{-1};
    }
    const auto it = std::lower_bound(sorted.begin(), sorted.end(), std::pair{v, std::uint32_t{0}});
    return it != sorted.end() && it->first == v ? static_cast<std::int32_t>(fan[it->second]) : std::int32_t{-1};
  };
  auto starting = [&](VertexId x) { return first_of(from_, x, true); };
  auto ending = [&](VertexId y) { return first_of(to_, y, false); };
  for (std::size_t i = 0; i < rim_.size(); ++i) {
    const Rim& r = rim_[i];
    set(fan[i], {r.x, r.y, v}, {starting(r.y), ending(r.x), r.out}, {0, 0, r.fixed});
    if (r.out >= 0) nbrs[3 * static_cast<std::uint32_t>(r.out) + r.back] = static_cast<std::int32_t>(fan[i]);
  }
  return v;
}

void Cdt::restore(std::vector<std::uint32_t> slots) {
  while (!slots.empty()) {
    const std::uint32_t s = slots.back();
    slots.pop_back();
    const std::uint32_t t = s / 3;
    const int i = static_cast<int>(s % 3);
    const std::int32_t n = nbrs[s];
    if (n < 0 || fixed[s]) continue;
    const VertexId d = at(static_cast<std::uint32_t>(n), back(static_cast<std::uint32_t>(n), t));
    if (incircle(pts[tris[3 * t]], pts[tris[3 * t + 1]], pts[tris[3 * t + 2]], pts[d]) <= 0) continue;
    flip(t, i);  // t is now (p, a, d), n (p, d, b): their sides away from the new edge p-d
    const auto u = static_cast<std::uint32_t>(n);
    slots.insert(slots.end(), {3 * t, 3 * t + 2, 3 * u, 3 * u + 1});
  }
}

VertexId Cdt::insert_on_edge(const Point& p, std::uint32_t t, int k) {
  const bool on_line = orient2d(pts[at(t, k + 1)], pts[at(t, k + 2)], p) == 0;
  const VertexId v = insert(p, {Place::Edge, t, k});
  if (on_line) return v;
  std::vector<std::uint32_t> spokes;
  around(v, [&](std::uint32_t u) {
    const int i = corner_of(u, v);
    spokes.push_back(3 * u + (i + 1) % 3), spokes.push_back(3 * u + (i + 2) % 3);
    return false;
  });
  restore(std::move(spokes));
  return v;
}

// Where x, a rounding away from edge k of t, lies: in t or the triangle across (inside, on
// an edge or at a corner), else Outside.
Cdt::Place Cdt::beside(std::uint32_t t, int k, const Point& x) const {
  const std::int32_t n = k < 0 ? -1 : nbrs[3 * t + k];  // k < 0: t alone
  for (const std::int32_t c : {static_cast<std::int32_t>(t), n}) {
    if (c < 0) continue;
    const auto r = static_cast<std::uint32_t>(c);
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

Cdt::Place Cdt::find(std::uint32_t from, const Point& p) const {
  try {
    const Place at = locate(from, p, false);
    if (at.kind != Place::Outside) return at;
  } catch (const std::logic_error&) {  // a walk across fixed edges can circle
  }
  for (std::uint32_t t = 0; t < size(); ++t)
    if (const Place at = beside(t, -1, p); at.kind != Place::Outside) return at;
  return {Place::Outside, from, 0};
}

}  // namespace ridt::detail
