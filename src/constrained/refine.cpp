// Delaunay refinement (constrained/refine.hpp), after Ruppert ("A Delaunay refinement
// algorithm for quality 2-dimensional mesh generation", 1995) and Shewchuk ("Delaunay
// refinement algorithms for triangular mesh generation", 2002): a subsegment is encroached
// when a vertex it sees (not one added on another subsegment, but for a conforming
// triangulation) lies strictly inside its diametral circle. A conforming triangulation splits
// each as it is found; a constrained one where it is encroached through a triangle that the
// angle bound exempts, or where a point to be added would lie inside its diametral lens
// (in_lens; Refiner::run says why).
// A split falls at the midpoint, or, where one end is a corner, at a power-of-two distance from
// it, so that splits near a small input angle fall on concentric shells and stop. Each bad
// triangle (a smallest angle below the bound, or an area above it) gets a point at its
// off-centre (Üngör, "Off-centers", 2004): the circumcentre, or, where that lies far from the
// shortest edge, the point on its bisector that makes an angle a little above the bound with it.
// A point that would encroach a subsegment is not added; the subsegment is split instead.
// Near small input angles: constrained/small_angles.cpp.
#include "constrained/refiner.hpp"

#include <new>

namespace ridt::detail {
namespace refining {

// Subsegment s split at its split point, or, where that cannot be placed (a vertex a rounding
// from the subsegment folds the triangles there), at a quarter or three eighths from either
// end instead; left whole where none can.
void Refiner::split(Link s) {
  if (!splittable(s) || frozen(s)) return;
  const Unsplit key = unsplit_key(s);
  if (unsplit_.count(key) != 0) return;
  const VertexId x = m_.tds.tail(s), y = m_.tds.head(s);
  const std::pair<VertexId, VertexId> ends = chain(x, y);
  const Point &a = m_.pts[x], &b = m_.pts[y];
  auto at = [&](double f) { return Point{a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f}; };
  const Point tries[5] = {split_point(x, y), at(0.25), at(0.75), at(0.375), at(0.625)};
  for (const Point& p : tries) {
    const VertexId v = split_at(s, p);
    if (deferred_) {  // a tile's: left for the whole mesh
      deferred_ = false;
      return;
    }
    if (v != kNoVertex) {
      ends_.resize(m_.pts.size(), {kNoVertex, kNoVertex});
      ends_[v] = ends;
      added(v);
      return;
    }
  }
  unsplit_.insert(key);
}

// p added on subsegment s as though it lay on it (it does, up to rounding; on the boundary never
// beyond it, lest the domain grow over a hole's seed); where that folds a triangle, inside the one
// beside it that holds p (x-y freed, p added, x-p and p-y given its constraint, the regions
// kept); else kNoVertex.
VertexId Refiner::split_at(Link s, const Point& given) {
  const TriangleId t = triangle_of(s);
  const int k = edge_of(s);
  const Point p = boundary(s) ? m_.not_beyond(t, k, given) : given;
  if (fenced_split(s, p)) {
    deferred_ = true;
    return kNoVertex;
  }
  if (m_.fits_on_edge(t, k, p)) return m_.insert_on_edge(p, t, k);
  if (boundary(s)) return kNoVertex;
  const Cdt::Place at = m_.beside(t, static_cast<int>(k), p);
  if (at.kind != Cdt::Place::Inside) return kNoVertex;
  const VertexId x = m_.tds.tail(s), y = m_.tds.head(s);
  // The regions of t (left of x -> y) and across, which the flips about p could mix.
  const TriangleId across = m_.across(s);
  const std::int32_t left = m_.region.empty() ? -1 : m_.region[t];
  const std::int32_t right = m_.region.empty() || across == kNoTriangle ? left : m_.region[across];
  const Constraint c = m_.tds.constraint(s);
  m_.constrain(s, kFree);
  const VertexId v = m_.insert(p, at);
  for (const VertexId e : {x, y})
    if (const Link f = m_.find_edge(v, e); f != kNoLink) m_.constrain(f, c);
  if (left != right) relabel(v, x, y, left, right);
  return v;
}

// The triangles about v, added beside segment x-y (now x-v-y), given the regions left and
// right of x -> v -> y: the flips made triangles about v, which v-x and v-y part into two fans.
// Triangle (v, p, q) is in the left one where v->p lies in the angle from v->y counter-clockwise
// to v->x (exact orientations; the angle is near a half-turn, either side of it).
void Refiner::relabel(VertexId v, VertexId x, VertexId y, std::int32_t left, std::int32_t right) {
  const Point &pv = m_.pts[v], &px = m_.pts[x], &py = m_.pts[y];
  const bool reflex = orient2d(pv, py, px) <= 0;  // the left angle is a half-turn or more
  m_.around(v, [&](std::uint32_t u) {
    const VertexId p = m_.at(u, m_.corner_of(u, v) + 1);
    bool in_left = p == y;
    if (p != x && p != y) {
      const bool after_y = orient2d(pv, py, m_.pts[p]) > 0, before_x = orient2d(pv, px, m_.pts[p]) < 0;
      in_left = reflex ? after_y || before_x : after_y && before_x;
    }
    m_.region[u] = in_left ? left : right;
    return false;
  });
}

bool Refiner::input_angle(TriangleId t, int s, const double (&l)[3], double twice) const {
  // (In a tile, an edge beside a ghost may be the fence's, not a segment's: not taken.)
  auto segment = [&](Link e) { return m_.fixed(e) && !frozen(e); };
  if (!segment(link_to(t, (s + 1) % 3)) || !segment(link_to(t, (s + 2) % 3))) return false;
  const int longest = l[(s + 1) % 3] >= l[(s + 2) % 3] ? (s + 1) % 3 : (s + 2) % 3;
  const int middle = 3 - s - longest;  // across from the second smallest angle (below 90 degrees)
  return twice * twice / (l[(middle + 1) % 3] * l[(middle + 2) % 3]) >= sin2_;
}

Point Refiner::split_point(VertexId x, VertexId y) const {
  const Point &a = m_.pts[x], &b = m_.pts[y];
  const Point mid{a.x / 2 + b.x / 2, a.y / 2 + b.y / 2};
  const bool sharp_x = corner(x) && small_[x], sharp_y = corner(y) && small_[y];
  VertexId shells = sharp_x != sharp_y ? (sharp_x ? x : y) : kNoVertex;
  if (!sharp_x && !sharp_y)
    if (const auto [z1, z2] = chain(x, y); z1 != kNoVertex && (small_[z1] != 0) != (small_[z2] != 0))
      shells = small_[z1] ? z1 : z2;
  if (shells == kNoVertex) {
    Point at;
    return matched(x, y, at) || matched(y, x, at) ? at : mid;
  }
  const Point& z = m_.pts[shells];
  const double dx = std::sqrt(dist2(z, a)), dy = std::sqrt(dist2(z, b));
  const double near = std::min(dx, dy), far = std::max(dx, dy);
  const double d = std::exp2(std::round(std::log2((near + far) / 2)));
  if (!(d > near * 1.0625 && d < far / 1.0625)) return mid;
  const Point& o = dx > dy ? a : b;
  return {z.x + (o.x - z.x) * (d / far), z.y + (o.y - z.y) * (d / far)};
}

// Where subsegment z-y, at corner z, is split when its corner's triangle keeps failing the bound.
// Between z-y and another segment's piece z-w at an angle from 60 degrees to 180 less twice the
// bound, the triangle z-y-w is good only where its two sides at z are about as long (an isosceles
// one has (180 - angle) / 2 at y and w). Split at midpoints, the two sides keep their segments'
// ratio of lengths, halved in turn, and where that ratio is far from a power of two the corner's
// triangle stays bad at every scale: refinement splits the two sides in turn towards z, without
// end (a corner of 100 degrees between segments 5.5 times as long as each other took 1,281
// triangles at 33 degrees, the smallest 10^-23 in area, where 255 do). So once z-y is down to a
// quarter of its segment, and from 1.25 to 2 times as long as such a z-w, it is split at z-w's
// length from z (the two sides then equal); else (false) as before.
bool Refiner::matched(VertexId z, VertexId y, Point& at) const {
  if (!corner(z) || sin2_ <= 0 || m_.corner[z] == kNoTriangle) return false;
  const Point &a = m_.pts[z], &b = m_.pts[y];
  const double long2 = dist2(a, b);
  if (const auto [z1, z2] = chain(z, y); z1 == kNoVertex || long2 * 16 > dist2(m_.pts[z1], m_.pts[z2])) return false;
  double best = 0;
  m_.around(z, [&](TriangleId t) {
    const int i = m_.corner_of(t, z);
    for (const int k : {next3(i), prev3(i)}) {
      const Link e = link_to(t, k);
      if (!m_.fixed(e) || frozen(e)) continue;  // (a tile's fence is no segment)
      const VertexId w = m_.tds.tail(e) == z ? m_.tds.head(e) : m_.tds.tail(e);
      const double short2 = dist2(a, m_.pts[w]);
      if (w == y || !(short2 * 1.5625 < long2 && short2 * 4 > long2)) continue;
      const double angle = std::fabs(turn(a, m_.pts[y], m_.pts[w]));
      if (angle > 3.14159265358979323846 / 3 && angle < 3.14159265358979323846 - 4 * half_bound_)
        best = std::max(best, short2);
    }
    return false;
  });
  if (best == 0) return false;
  const double f = std::sqrt(best / long2);
  at = {a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f};
  return true;
}

// The fixed edges that p, added in `at`, would encroach (in_lens), among those bounding the
// cavity of p (the triangles whose circles hold p, linked without crossing
// a fixed edge: Cdt::find_cavity, which insert_cavity then fills).
std::vector<Link>& Refiner::would_encroach(const Point& p, const Cdt::Place& at) {
  m_.find_cavity(p, at);
  const CavityScratch& s = m_.cavity();
  hit_.clear();
  for (std::size_t i = 0; i < s.edges; ++i)
    if (const Link e = s.boundary[i].inside; m_.fixed(e) && in_lens(m_.pts[m_.tds.tail(e)], m_.pts[m_.tds.head(e)], p))
      hit_.push_back(e);
  return hit_;
}

// Whether p, where a point is meant to go, encroaches subsegment a-b: p sees a-b at more
// than 180 degrees less twice the lens angle, max(bound, 30 degrees): inside Shewchuk's
// diametral lens, or, in a conforming triangulation, inside the diametral circle (above 90
// degrees). A point in the circle but outside the lens makes with a-b a triangle whose angles
// at a and b keep the bound where it stands over the middle, and that its own point mends
// where not; the circle turned such points into splits that graded the mesh down to the
// segment (docs/constrained.md: a coastline of 250,000 vertices at 33 degrees, 5 % fewer
// triangles).
bool Refiner::in_lens(const Point& a, const Point& b, const Point& p) const {
  // (Of degree 2 in the coordinates, as dot is: squared, both sides would be of degree 4.)
  const double d = dot(a, b, p);  // |pa| |pb| cos(angle a-p-b)
  return d < 0 && (r_.conforming || d < -lens_ * std::sqrt(dist2(a, p)) * std::sqrt(dist2(b, p)));
}

bool Refiner::make_room() {
  try {
    if (m_.room() < kAhead) m_.make_room(std::max(kAhead, m_.pts.size() / 4), kAhead);
    ends_.reserve(m_.pts.capacity());
  } catch (const std::bad_alloc&) {
    return false;
  }
  room_until_ = m_.pts.size() + std::min(m_.room(), ends_.capacity() - m_.pts.size());
  return true;
}

// Whether subsegment s is a flaw to mend before any bad triangle. A conforming triangulation
// splits every encroached subsegment. A constrained one with an angle bound splits those with a
// vertex inside their diametral lens (in_lens; the vertices that count in encroached), as
// Ruppert's algorithm splits encroached subsegments first: the pieces anchor the large
// triangles of a graded mesh, where splits left for the points refused beside the boundary came
// late, from a mesh already fine there, and the fine sizes spread over the domain (random point
// sets' hulls at 34 degrees: 12,283 triangles, from 15,598; Triangle 12,233). Not beside a small
// input angle, where it left more triangles below the bound, nor with no angle bound, where a
// vertex in a subsegment's lens is no flaw of a constrained mesh: there only those encroached
// through a triangle the angle bound exempts.
bool Refiner::to_split(Link s) const {
  if (r_.conforming || !(sin2_ > 0)) return encroached(s, !r_.conforming);
  if (const auto [z1, z2] = chain(m_.tds.tail(s), m_.tds.head(s)); z1 != kNoVertex && (small_[z1] || small_[z2]))
    return encroached(s, true);
  const Point &a = m_.pts[m_.tds.tail(s)], &b = m_.pts[m_.tds.head(s)];
  auto inside = [&](VertexId v) { return counts(v) && in_lens(a, b, m_.pts[v]); };
  if (inside(m_.tds.vertex_at(s))) return true;
  if (const VertexId across = m_.apex_across(s); across != kNoVertex && inside(across)) return true;
  return encroached(s, true);
}

// After v is added: its triangles queued where bad, its fixed edges where they are flaws.
void Refiner::added(VertexId v) {
  ends_.resize(m_.pts.size(), {kNoVertex, kNoVertex});
  m_.around(v, [&](TriangleId t) {
    queue_bad(t);
    for (int k = 0; k < 3; ++k)
      if (const Link e = link_to(t, k); m_.fixed(e) && to_split(e)) queue_split(e, false);
    return false;
  });
}

// Subsegment s, to be split for a point refused beside it (w: its ends), first cleared as Chew's
// second algorithm clears it: the free vertices (added inside the domain, on no segment) strictly
// inside its diametral circle taken out, so that points put there before the split, graded to
// a mesh without it, give way to those the split's sizes ask for. Returns s as found again.
// Only where r_.clear asks it: never in a tile, whose fence the clearing could cross.
Link Refiner::clear_circle(Link s, const Split& w) {
  if (!r_.clear || r_.conforming) return s;
  if (const auto [z1, z2] = chain(w.x, w.y); z1 != kNoVertex && (small_[z1] || small_[z2])) return s;
  const Point a = m_.pts[w.x], b = m_.pts[w.y], c{(a.x + b.x) / 2, (a.y + b.y) / 2};
  const double r2 = dist2(a, b) / 4;
  // Whether edge p-q meets the circle's inside: c's distance from it below the radius.
  auto meets = [&](const Point& p, const Point& q) {
    const double dx = q.x - p.x, dy = q.y - p.y, len2 = dx * dx + dy * dy;
    double f = len2 > 0 ? ((c.x - p.x) * dx + (c.y - p.y) * dy) / len2 : 0;
    f = std::clamp(f, 0.0, 1.0);
    return dist2(c, {p.x + f * dx, p.y + f * dy}) < r2;
  };
  std::vector<TriangleId> todo{triangle_of(s)}, seen{triangle_of(s)};
  if (const TriangleId u = m_.across(s); u != kNoTriangle) todo.push_back(u), seen.push_back(u);
  std::vector<VertexId> inside, near;
  while (!todo.empty() && seen.size() < 256) {
    const TriangleId t = todo.back();
    todo.pop_back();
    for (int k = 0; k < 3; ++k) {
      const VertexId v = m_.at(t, k);
      if (!corner(v) && ends_[v].first == kNoVertex && dot(a, b, m_.pts[v]) < 0 &&
          std::find(inside.begin(), inside.end(), v) == inside.end())
        inside.push_back(v);
      const Link e = link_to(t, k);
      const TriangleId n = m_.across(e);
      if (n == kNoTriangle || m_.fixed(e) || std::find(seen.begin(), seen.end(), n) != seen.end()) continue;
      if (meets(m_.pts[m_.at(t, k + 1)], m_.pts[m_.at(t, k + 2)])) todo.push_back(n), seen.push_back(n);
    }
  }
  if (inside.empty()) return s;
  for (const VertexId v : inside)
    m_.around(v, [&](TriangleId t) {
      for (int k = 0; k < 3; ++k) near.push_back(m_.at(t, k));
      return false;
    });
  removed_.reserve(removed_.size() + inside.size());  // (no allocation once vertices go)
  for (const VertexId v : inside)
    if (m_.remove_free(v)) removed_.push_back(v);
  std::sort(near.begin(), near.end());
  near.erase(std::unique(near.begin(), near.end()), near.end());
  for (const VertexId u : near)
    if (m_.corner[u] != kNoTriangle) added(u);
  return m_.find_edge(w.x, w.y);
}

// The queues to begin with. A conforming triangulation splits every encroached subsegment; a
// constrained one those a point to be added would encroach (improve's forced splits), those
// encroached through a triangle below the angle bound that the bound exempts (beside a small
// input angle), and those of a bad triangle the terminator leaves: a subsegment that a vertex
// encroaches is no flaw of a constrained Delaunay mesh in itself, and splitting every one
// added points that no bound asked for (18 to the 29 triangles of Triangle's example `A` at 1
// degree). Then every bad triangle, in the order of their slots. The tests are made on
// threads where they ask nothing of the caller (no test or size field of its own, no given
// mesh whose regions are looked up), the queues filled in the same order.
void Refiner::first_queues() {
  const Link slots = static_cast<Link>(3 * m_.size());
  auto split_first = [&](Link s) {
    return m_.fixed(s) &&
        (r_.longer_than == 0 ||
         dist2(m_.pts[m_.tds.tail(s)], m_.pts[m_.tds.head(s)]) > r_.longer_than * r_.longer_than) &&
        !ghost(triangle_of(s)) && to_split(s);
  };
  const bool threaded = thread_count(r_.threads) > 1 && fence_ == nullptr && !r_.unsuitable && !r_.sizes &&
      r_.given == nullptr && m_.size() >= 65536;
  if (!threaded) {
    for (Link s = 0; s < slots; ++s)
      if (split_first(s)) queue_split(s, false);
    for (std::uint32_t t = 0; t < m_.size(); ++t)
      if (!ghost(t)) queue_bad(t);
    return;
  }
  // The subsegments to split and the bad triangles (after the tiles, one triangle in two
  // hundred) found on threads, in the order of the slots; the few found weighed again here.
  for (const std::uint32_t s :
       indices_where(slots, r_.threads, [&](std::size_t s) { return split_first(static_cast<Link>(s)); }))
    queue_split(static_cast<Link>(s), false);
  auto bad = [&](std::size_t t) {
    return (r_.longer_than == 0 || longer(static_cast<TriangleId>(t))) &&
        badness(static_cast<std::uint32_t>(t)) != kGood;
  };
  for (const std::uint32_t t : indices_where(m_.size(), r_.threads, bad)) push_if_bad(t, badness(t));
}

// The warning for the triangles refinement gave up on that are still bad: below the angle
// after 64 tries (each time the subsegments its point would encroach were split, or its point
// went in beyond one, it stood again: in a wedge so thin beside one so wide that the splits
// cannot reach it before the subsegments are too short to split), or too large where its
// centroid could not go in.
std::string Refiner::left_bad() const {
  std::vector<std::uint32_t> shape, area, unsuitable;  // still bad: for the angle, the area, the caller's test
  for (const Bad& b : given_up_)
    if (const double key = alive(b) ? b.key : kGood; key != kGood)  // the same vertices, the same badness
      (key >= 0 ? shape : key <= -1 ? area : unsuitable).push_back(b.t);
  auto count = [](std::vector<std::uint32_t>& v) {
    std::sort(v.begin(), v.end());
    return static_cast<std::size_t>(std::unique(v.begin(), v.end()) - v.begin());
  };
  const std::size_t below = count(shape), above = count(area), failed = count(unsuitable);
  // A conforming triangulation promises every edge Delaunay, which an encroached subsegment too
  // short to split (two segments at a small angle split each other down to the least length)
  // breaks: said.
  std::size_t short_encroached = 0;
  if (r_.conforming)
    for (Link s = 0; static_cast<std::size_t>(s) < 3 * m_.size(); ++s)
      if (m_.fixed(s) && m_.at(triangle_of(s), 0) != kNoVertex && (boundary(s) || s < m_.tds.link_at(s)) &&
          encroached(s) && dist2(m_.pts[m_.tds.tail(s)], m_.pts[m_.tds.head(s)]) < 4 * tiny2_)
        ++short_encroached;
  std::string edges;
  if (short_encroached > 0)
    edges = std::to_string(short_encroached) + (short_encroached == 1 ? " subsegment" : " subsegments") +
        " encroached but too short to split (the triangulation may not be Delaunay there)";
  if (below + above + failed == 0) return edges.empty() ? "" : "conforming refinement left " + edges;
  auto triangles = [](std::size_t n) { return std::to_string(n) + (n == 1 ? " triangle" : " triangles"); };
  std::string w = "quality refinement left ";
  if (below > 0) w += triangles(below) + " below the minimum angle";
  if (above > 0) w += std::string(below > 0 ? " and " : "") + triangles(above) + " above the maximum area or size";
  if (failed > 0)
    w += std::string(below + above > 0 ? " and " : "") + triangles(failed) + " unsuitable by the test given";
  return w + ": the subsegments near them could not be split far enough" + (edges.empty() ? "" : "; and " + edges);
}

void Refiner::improve(const Bad& b) {
  const Point p = off_centre(b.t);
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return centroid(b);
  const Cdt::Place at = m_.locate(b.t, p, true);
  if (at.kind == Cdt::Place::Corner) return centroid(b);
  const Link e = link_to(at.t, at.k);
  // In a tile: a point on or beyond its fence, or whose cavity would reach past it, is left.
  if (at.kind != Cdt::Place::Inside && frozen(e)) return;
  // On a subsegment that may not be split (the boundary's, asked to keep no new points): left.
  if (at.kind == Cdt::Place::Edge && m_.fixed(e) && !splittable(e)) return centroid(b);
  const bool blocked = at.kind == Cdt::Place::Blocked || at.kind == Cdt::Place::Outside;
  if (blocked) hit_.assign(1, e);
  std::vector<Link>& hit = blocked ? hit_ : would_encroach(p, at);
  if (fence_ != nullptr &&
      ((!blocked && crosses_fence(p)) || std::any_of(hit.begin(), hit.end(), [&](Link s) { return frozen(s); })))
    return;
  std::erase_if(hit, [&](Link s) { return !splittable(s); });
  for (const Link s : hit)
    if (b.key >= 0 && terminated(s, b.t)) return split_own(b.t);  // never for a triangle too large
  if (blocked || !hit.empty()) {
    if (b.key >= 0 && wedged(b.t, hit)) return;
    if (b.tries >= 64) return leave(b);
    if (hit.empty()) return centroid(b);
    for (const Link s : hit) queue_split(s, true, true);
    bad_.push({b.key, b.t, {b.v[0], b.v[1], b.v[2]}, b.tries + 1, b.where});
    return;
  }
  // The triangles whose circles hold p are known (would_encroach's): replaced by a fan
  // about p where they make a cavity p sees whole, else p added with flips.
  const VertexId v = m_.insert_cavity(p);
  added(v != kNoVertex ? v : m_.insert(p, at));
  // p beyond a subsegment too short to split from t (a triangle far thinner than long): t
  // stands, tried again, then given its centroid.
  if (alive(b)) {
    if (b.tries < 64) return bad_.push({b.key, b.t, {b.v[0], b.v[1], b.v[2]}, b.tries + 1, b.where});
    leave(b);
  }
}

// A bad triangle left by the terminator: its own subsegments split where its apex encroaches
// them (as a conforming mesh would split them at once), the one way left to mend it.
void Refiner::split_own(TriangleId t) {
  for (int k = 0; k < 3; ++k)
    if (const Link e = link_to(t, k); m_.fixed(e) && encroached(e)) queue_split(e, true);
}

// Triangle b after 64 tries: one bad for its shape left, and counted for the warning; one too
// large given its centroid.
void Refiner::leave(const Bad& b) {
  if (b.key >= 0) given_up_.push_back(b);
  centroid(b);
}

// A triangle too large whose off-centre cannot go in (on a vertex, on the boundary kept whole,
// or across subsegments too short to split): its centroid, inside it, instead. A triangle bad
// only for its shape is left.
void Refiner::centroid(const Bad& b) {
  if (b.key >= 0) return;
  const Point &p = m_.pts[b.v[0]], &q = m_.pts[b.v[1]], &r = m_.pts[b.v[2]];
  const Point c{p.x / 3 + q.x / 3 + r.x / 3, p.y / 3 + q.y / 3 + r.y / 3};
  const Cdt::Place at = m_.locate(b.t, c, true);
  if (at.kind == Cdt::Place::Inside || (at.kind == Cdt::Place::Edge && !m_.fixed(link_to(at.t, at.k)))) {
    if (fenced(c, at)) return;  // a tile's: left for the whole mesh
    return added(m_.insert(c, at));
  }
  given_up_.push_back(b);  // a triangle too thin for its centroid to fall inside it: left, and said
}

}  // namespace refining

std::string refine(Cdt& m, const Refinement& r) {
  const std::size_t before = m.pts.size();
  Chains chains = refine_tiles(m, r);
  Refinement rest = r;
  rest.added_from = before;
  auto run = [&](Refinement how) {
    how.clear = true;
    refining::Refiner refiner(m, how, std::move(chains));
    std::string warning = refiner.run();
    m.compact(refiner.removed());
    return warning;
  };
  if (r.memory == 0 || m.pts.size() == before) return run(rest);
  // A memory budget given (not read from the system, which counts the tiles' points itself):
  // what the tiles' points took (as Refiner::run counts them) is spent.
  const std::size_t spent = (m.pts.size() - before) * 320 / 3 * 4;
  rest.memory = std::max<std::size_t>(r.memory > spent ? r.memory - spent : 0, 640);  // (room for a point)
  return run(rest);
}

}  // namespace ridt::detail
