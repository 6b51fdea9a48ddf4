// Refinement near small input angles (constrained/refiner.hpp): the corners where two segments
// meet below 60 degrees, Shewchuk's terminator, and thin wedges, meshed as ladders whose rungs
// join points at one distance from the corner.
#include "constrained/refiner.hpp"

namespace ridt::detail::refining {

// Triangle t, bad for its shape, in a thin wedge (thin_apex) whose point would split `hit`, one
// of them a subsegment of the wedge's chains: t is left where its shortest edge is seditious,
// else mended by partnered(); true where either.
bool Refiner::wedged(TriangleId t, const std::vector<Link>& hit) {
  const VertexId v[3] = {m_.at(t, 0), m_.at(t, 1), m_.at(t, 2)};
  auto on_its_chain = [&](VertexId u) {
    return std::any_of(hit.begin(), hit.end(),
                       [&](Link s) { return ordered(chain(m_.tds.tail(s), m_.tds.head(s))) == chain_of(u); });
  };
  bool wedge = false;
  for (int k = 0; k < 3 && !wedge; ++k) {
    const VertexId u = v[(k + 1) % 3], w = v[(k + 2) % 3];
    wedge = thin_apex(u, w) != kNoVertex && (on_its_chain(u) || on_its_chain(w));
  }
  if (!wedge) return false;
  const Point &a = m_.pts[v[0]], &b = m_.pts[v[1]], &c = m_.pts[v[2]];
  const int s = shortest({dist2(b, c), dist2(c, a), dist2(a, b)});
  return seditious(v[(s + 1) % 3], v[(s + 2) % 3]) || partnered(t);
}

// Triangle t, bad for its shape, with an edge u-w across the angle between two chains from a
// small corner z: a point put on one chain at the other's vertex's distance from z (the edge
// between them then seditious), on a subsegment at w (or u) that spans that distance, instead
// of t's off-centre, which would split the chains, each where it stands, and so on down to the
// gap between them. Its edges are tried from the shortest. False where none has such a place.
bool Refiner::partnered(std::uint32_t t) {
  const VertexId v[3] = {m_.at(t, 0), m_.at(t, 1), m_.at(t, 2)};
  const double l[3] = {dist2(m_.pts[v[1]], m_.pts[v[2]]), dist2(m_.pts[v[2]], m_.pts[v[0]]),
                       dist2(m_.pts[v[0]], m_.pts[v[1]])};
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return l[i] < l[j]; });
  for (const int k : order) {
    const VertexId u = v[(k + 1) % 3], w = v[(k + 2) % 3], z = thin_apex(u, w);
    if (z != kNoVertex && !seditious(u, w) && (partner(u, w, z) || partner(w, u, z))) return true;
  }
  return false;
}

// A point on y's chain at x's distance from z, on one of the subsegments at y where that
// distance falls inside it (not at one distance with its ends); false where it does not.
bool Refiner::partner(VertexId x, VertexId y, VertexId z) {
  const Point& pz = m_.pts[z];
  const double dx = dist2(pz, m_.pts[x]), dy = dist2(pz, m_.pts[y]);
  const std::pair<VertexId, VertexId> chain = chain_of(y);
  Link slot = kNoLink;
  m_.around(y, [&](TriangleId f) {
    const int i = m_.corner_of(f, y);
    for (int j = 1; j <= 2; ++j) {
      const Link e = link_to(f, (i + j) % 3);  // the edge from y to n
      const VertexId n = m_.at(f, i + 3 - j);
      if (!m_.fixed(e) || !(n == chain.first || n == chain.second || (!corner(n) && chain_of(n) == chain))) continue;
      const double dn = dist2(pz, m_.pts[n]), lo = std::min(dn, dy), hi = std::max(dn, dy);
      if (dx > lo * (1 + kOneDistance) && dx < hi * (1 - kOneDistance) && splittable(e)) slot = e;
    }
    return slot != kNoLink;
  });
  if (slot == kNoLink) return false;
  // Along the chain's segment, from z towards its other end.
  const Point& po = m_.pts[chain.first == z ? chain.second : chain.first];
  const double f = std::sqrt(dx / dist2(pz, po));
  const VertexId p = split_at(slot, {pz.x + (po.x - pz.x) * f, pz.y + (po.y - pz.y) * f});
  deferred_ = false;  // (a tile's fence: the triangle is mended otherwise, or left)
  if (p == kNoVertex) return false;
  ends_.resize(m_.pts.size(), {kNoVertex, kNoVertex});
  ends_[p] = chain;
  added(p);
  return true;
}

// Each corner's sectors: the angles the domain's triangles make at it between two fixed
// edges; a corner with one below 60 degrees is the apex of a cluster of segments. (Each corner
// apart: on threads for the whole mesh.)
void Refiner::find_small_angles() {
  small_.assign(r_.corners, 0);
  parallel_for(r_.corners, fence_ == nullptr ? r_.threads : 1, 65536, [&](std::size_t from, std::size_t to) {
    for (auto z = static_cast<VertexId>(from); z < to; ++z) find_small_angle(z);
  });
}

void Refiner::find_small_angle(VertexId z) {
  if (m_.corner[z] == kNoTriangle) return;
  auto angle = [&](std::uint32_t t, int i) {
    return turn(m_.pts[m_.at(t, i)], m_.pts[m_.at(t, i + 1)], m_.pts[m_.at(t, i + 2)]);
  };
  // From each triangle whose edge (z, u) is fixed, counter-clockwise across the edges (w, z)
  // that are not, to the next fixed one.
  m_.around(z, [&](TriangleId first) {
    if (!m_.fixed(link_to(first, prev3(m_.corner_of(first, z))))) return false;
    double sector = 0;
    for (TriangleId t = first;;) {
      const int i = m_.corner_of(t, z);
      sector += angle(t, i);
      if (m_.fixed(link_to(t, next3(i)))) break;
      t = m_.across(link_to(t, next3(i)));
    }
    if (sector < 3.14159265358979323846 / 3) small_[z] = 1;
    return small_[z] != 0;
  });
}

// Shewchuk's terminator, simplified: triangle t, with a vertex on a chain that ends at a
// small angle, is left as it is where its point would have subsegment s, there, split closer
// to one of its ends than t's shortest edge is long (t's small angle then comes from the
// input's, and splitting on would only cut the shells finer).
bool Refiner::terminated(Link s, TriangleId t) const {
  const VertexId x = m_.tds.tail(s), y = m_.tds.head(s);
  const auto [z1, z2] = chain(x, y);
  if (z1 == kNoVertex || !(small_[z1] || small_[z2])) return false;
  auto beside = [&](VertexId v) {
    if (corner(v)) return small_[v] != 0;
    return ends_[v].first != kNoVertex && (small_[ends_[v].first] || small_[ends_[v].second]);
  };
  if (!beside(m_.at(t, 0)) && !beside(m_.at(t, 1)) && !beside(m_.at(t, 2))) return false;
  const Point p = split_point(x, y);
  const double radius = std::min(dist2(p, m_.pts[x]), dist2(p, m_.pts[y]));
  const Point &a = m_.pts[m_.at(t, 0)], &b = m_.pts[m_.at(t, 1)], &c = m_.pts[m_.at(t, 2)];
  return radius < std::min({dist2(a, b), dist2(b, c), dist2(c, a)});
}

}  // namespace ridt::detail::refining
