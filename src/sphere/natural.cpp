// Natural-neighbour (Sibson) interpolation on the sphere (ridt/sphere.hpp): a query's weights
// are the areas its Voronoi cell on the sphere would take from its neighbours' cells, were it
// inserted.
//
// The query's point on the sphere sees (lies above the planes of) a disc of triangles, its
// cavity; their corners are its natural neighbours. Inserted, it would join each boundary edge
// (u, v) of the cavity in a new triangle (q, u, v), whose circle's centre is a vertex of its new
// cell. What neighbour a loses is the spherical polygon from the centre of (q, u, a), through the
// centres of the cavity's triangles round a (clockwise round a, from the one with edge u -> a to
// the one with edge a -> v), to the centre of (q, a, v): its area a sum of solid angles.
#include <algorithm>
#include <cmath>

#include "predicates/orient3d.hpp"
#include "ridt/sphere.hpp"
#include "runtime/parallel.hpp"
#include "sphere/geometry.hpp"
#include "tds/ids.hpp"

namespace ridt {
namespace {

using detail::next3;
using detail::prev3;
using namespace detail::sphere;

class Sibson {
 public:
  Sibson(const SphericalTriangulation& t, std::span<const Point3> points, const Point3& centre, const ConeWalk& walk)
      : t_(t), points_(points), centre_(centre), walk_(walk) {}

  /// The natural neighbours of q (a direction from the centre, in triangle f) and their
  /// weights, summing to 1; false where q has none (its point on the sphere lies on or below
  /// f's plane: within rounding of a data point or of a tiny triangle's edge; or its cavity
  /// reaches a triangle that faces the centre: beyond the points of one hemisphere).
  bool weights(const Point3& q, std::size_t f, std::vector<VertexId>& who, std::vector<double>& weight) {
    const VertexId* c = &t_.triangles[3 * f];
    double r = 0;
    for (int i = 0; i < 3; ++i) r += std::sqrt(dot(minus(points_[c[i]], centre_), minus(points_[c[i]], centre_))) / 3;
    const Point3 d = unit(minus(q, centre_));
    q_ = {centre_.x + r * d.x, centre_.y + r * d.y, centre_.z + r * d.z};
    if (!sees(f)) return false;
    if (!cavity(f)) return false;
    who.clear(), weight.clear();
    // A corner of the cavity's triangles inside it: q's point lies above that data point's
    // (within rounding of its direction, or the point lies off the sphere), and would hide it,
    // not share its cell: its value.
    for (const std::size_t g : cavity_)
      for (int i = 0; i < 3; ++i) {
        const VertexId v = t_.triangles[3 * g + i];
        if (std::none_of(ring_.begin(), ring_.end(), [&](const Edge& e) { return e.from == v; }))
          return who.assign(1, v), weight.assign(1, 1.0), true;
      }
    double total = 0;
    const std::size_t k = ring_.size();
    for (std::size_t e = 0; e < k; ++e) {
      const Edge& in = ring_[(e + k - 1) % k];  // u -> a
      const Edge& out = ring_[e];  // a -> v
      const VertexId a = out.from;
      polygon_.clear();
      polygon_.push_back(unit_normal(q_, points_[in.from], points_[a]));
      std::size_t g = in.face;
      for (std::size_t steps = 0;; ++steps) {
        polygon_.push_back(unit_normal(points_[t_.triangles[3 * g]], points_[t_.triangles[3 * g + 1]],
                                       points_[t_.triangles[3 * g + 2]]));
        if (g == out.face || steps > cavity_.size()) break;
        const int i = corner(g, a);
        g = static_cast<std::size_t>(t_.neighbors[3 * g + prev3(i)]);  // across a -> next: clockwise round a
      }
      polygon_.push_back(unit_normal(q_, points_[a], points_[out.to]));
      double area = 0;
      for (std::size_t j = 1; j + 1 < polygon_.size(); ++j)
        area += solid_angle(polygon_[0], polygon_[j], polygon_[j + 1]);
      area = std::fabs(area);
      who.push_back(a), weight.push_back(area);
      total += area;
    }
    if (!(total > 0) || !std::isfinite(total)) return false;
    for (double& w : weight) w /= total;
    return true;
  }

 private:
  struct Edge {
    VertexId from, to;
    std::size_t face;
  };

  bool sees(std::size_t g) const {
    const VertexId* c = &t_.triangles[3 * g];
    return detail::orient3d(points_[c[0]], points_[c[1]], points_[c[2]], q_) < 0;
  }
  int corner(std::size_t g, VertexId a) const {
    return t_.triangles[3 * g] == a ? 0 : t_.triangles[3 * g + 1] == a ? 1 : 2;
  }

  // The triangles q_ sees, grown from f (which it does; a triangle joins when one of the cavity
  // first meets it, an edge to one it does not see is the boundary's), and their boundary as a
  // ring of edges counter-clockwise seen from outside; false where one faces the centre or the
  // boundary is not one ring.
  bool cavity(std::size_t f) {
    cavity_.assign(1, f);
    edges_.clear();
    for (std::size_t k = 0; k < cavity_.size(); ++k) {
      const std::size_t g = cavity_[k];
      if (!walk_.away(g)) return false;
      for (int j = 0; j < 3; ++j) {
        const auto h = static_cast<std::size_t>(t_.neighbors[3 * g + j]);
        if (std::find(cavity_.begin(), cavity_.end(), h) != cavity_.end()) continue;
        if (sees(h)) {
          cavity_.push_back(h);
          continue;
        }
        edges_.push_back({t_.triangles[3 * g + next3(j)], t_.triangles[3 * g + prev3(j)], g});
      }
    }
    ring_.clear();
    if (edges_.empty()) return false;
    ring_.push_back(edges_[0]);
    while (ring_.size() <= edges_.size()) {
      const VertexId at = ring_.back().to;
      const auto next = std::find_if(edges_.begin(), edges_.end(), [&](const Edge& e) { return e.from == at; });
      if (next == edges_.end()) return false;
      if (next->from == ring_[0].from) break;
      ring_.push_back(*next);
    }
    return ring_.size() == edges_.size();
  }

  const SphericalTriangulation& t_;
  std::span<const Point3> points_;
  Point3 centre_, q_;
  const ConeWalk& walk_;
  std::vector<std::size_t> cavity_;
  std::vector<Edge> edges_, ring_;
  std::vector<Point3> polygon_;
};

}  // namespace

std::vector<double> interpolate_sphere_natural(const SphericalTriangulation& t, std::span<const Point3> points,
                                               std::span<const double> values, std::size_t k,
                                               std::span<const Point3> queries, const Point3& centre, double fill,
                                               unsigned threads) {
  if (k == 0 || values.size() != points.size() * k) throw InputError("interpolate_sphere_natural: k values a point");
  for (const VertexId v : t.triangles)
    if (v >= points.size()) throw InputError("interpolate_sphere_natural: a corner is not a point");
  std::vector<double> out(queries.size() * k, fill);
  if (t.size() == 0) return out;
  const ConeWalk walk(t, points, centre);
  detail::parallel_for(queries.size(), threads, 256, [&](std::size_t from, std::size_t to) {
    Sibson sibson(t, points, centre, walk);
    std::vector<VertexId> who;
    std::vector<double> weight;
    std::size_t f = 0;
    for (std::size_t i = from; i < to; ++i) {
      const Point3& q = queries[i];
      if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) || q == centre) continue;
      if (!walk.locate(q, f)) continue;
      if (!sibson.weights(q, f, who, weight)) {
        // No cavity: the linear weights of f.
        const VertexId* c = &t.triangles[3 * f];
        double w[3];
        if (!linear_weights(points[c[0]], points[c[1]], points[c[2]], q, centre, w)) continue;
        who.assign(c, c + 3), weight.assign(w, w + 3);
      }
      for (std::size_t j = 0; j < k; ++j) {
        double v = 0;
        for (std::size_t n = 0; n < who.size(); ++n) v += weight[n] * values[who[n] * k + j];
        out[i * k + j] = v;
      }
    }
  });
  return out;
}

}  // namespace ridt
