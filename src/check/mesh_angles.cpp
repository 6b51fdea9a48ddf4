// The angles and areas of a mesh (check/mesh_angles.hpp): its segments' chains between corners,
// the small input angles among them and their wedges, and each triangle against the bounds.
#include "check/mesh_angles.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "predicates/predicates.hpp"
#include "runtime/parallel.hpp"

namespace ridt::detail {

// How far p lies off the line a-b, in units of the coordinates' magnitudes: an error of r
// times |x| in x and r times |y| in y moves p by r of this measure at most, where |x| and |y|
// are, for a point computed from the segment's ends (`computed`: split off it, on the segment
// or its pieces, from either end), the largest of a's, b's and p's; for an input point (on
// the segment exactly, or where a crossing within a few units of its own coordinates was
// merged into it), p's own or, where larger, those a and b give by interpolation at p's place
// along a-b (on a segment from near 10^19 to (10, 0), a vertex 4 units from (10, 0) is far off
// it). Each coordinate on its own scale: a point on a long segment almost along an axis may be
// off by much along the segment, but only by the other coordinate's roundings across it. No
// scale is below `least`: where the mesher worked in coordinates scaled by a power of two, its
// roundings below the least normal double there are absolute, and `least` is that double in
// these coordinates.
double off_line(const Point& a, const Point& b, const Point& p, long double least, bool computed) {
  // The cross product from the end nearer p: from the far one, its two terms could be some
  // 10^20 times it, and long double's roundings of them as large as the measure itself.
  using L = long double;
  const L ex = L{b.x} - a.x, ey = L{b.y} - a.y;
  const L e2 = ex * ex + ey * ey;
  const L t = e2 > 0 ? std::clamp((ex * (L{p.x} - a.x) + ey * (L{p.y} - a.y)) / e2, L(0), L(1)) : L(0);
  const Point& n = t < 0.5 ? a : b;
  const L cross = ex * (L{p.y} - n.y) - ey * (L{p.x} - n.x);
  auto scale = [&](double pa, double pb, double pp) {
    const L ends = computed ? std::max(std::fabs(pa), std::fabs(pb)) : (1 - t) * std::fabs(pa) + t * std::fabs(pb);
    return std::max({ends, L(std::fabs(pp)), least});
  };
  const L sx = scale(a.x, b.x, p.x), sy = scale(a.y, b.y, p.y);
  const L bound = std::fabs(L{b.x} - a.x) * sy + std::fabs(L{b.y} - a.y) * sx;
  return cross == 0 ? 0 : static_cast<double>(std::fabs(cross) / bound);
}

namespace {

// The chains of segment edges between corners (input points, and added points where other
// than two segment edges meet or where the two turn: not found on an input segment between
// them (SegmentEdges::straight), and off the line between their other ends by more than check_chains lets
// a point on a segment lie, as a point added where segments cross): each chain's two ends, and
// per vertex the chains it lies on.
struct Chains {
  std::vector<std::pair<VertexId, VertexId>> ends;
  std::vector<std::vector<std::uint32_t>> on;
  std::vector<std::uint8_t> small;  // per vertex: a corner where two chains meet below 60 degrees
  struct Wedge {
    VertexId corner, end1, end2;  // two chains from `corner` below 60 degrees, by their other ends
  };
  std::vector<Wedge> wedges;
};

Chains chains_of(std::span<const Point> pts, const SegmentEdges& edges, std::size_t input, long double least) {
  const auto& adj = edges.adj;
  const auto& straight = edges.straight;
  Chains c;
  c.on.resize(pts.size());
  c.small.assign(pts.size(), 0);
  auto corner = [&](VertexId v) {
    if (v < input || adj[v].size() != 2) return true;
    return !straight[v] && off_line(pts[adj[v][0]], pts[adj[v][1]], pts[v], least, true) > 0x1p-40;
  };
  for (VertexId z = 0; z < pts.size(); ++z) {
    if (!corner(z)) continue;
    for (const VertexId first : adj[z]) {
      VertexId prev = z, v = first;
      std::vector<VertexId> inside;
      while (!corner(v)) inside.push_back(v), std::swap(prev, v), v = adj[prev][0] == v ? adj[prev][1] : adj[prev][0];
      if (v < z || (v == z && !inside.empty() && inside.front() > inside.back())) continue;  // walked from v's side
      const auto id = static_cast<std::uint32_t>(c.ends.size());
      c.ends.emplace_back(z, v);
      c.on[z].push_back(id);
      if (v != z) c.on[v].push_back(id);
      for (const VertexId w : inside) c.on[w].push_back(id);
    }
  }
  // The angle at each corner between the straight lines to its chains' other ends.
  for (VertexId z = 0; z < pts.size(); ++z)
    for (std::size_t i = 0; i < c.on[z].size(); ++i)
      for (std::size_t j = i + 1; j < c.on[z].size(); ++j) {
        auto other = [&](std::uint32_t k) { return c.ends[k].first == z ? c.ends[k].second : c.ends[k].first; };
        const Point &o = pts[z], &u = pts[other(c.on[z][i])], &w = pts[other(c.on[z][j])];
        const double ux = u.x - o.x, uy = u.y - o.y, wx = w.x - o.x, wy = w.y - o.y;
        if (std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) < 3.14159265358979323846 / 3) {
          c.small[z] = 1;
          c.wedges.push_back({z, other(c.on[z][i]), other(c.on[z][j])});
        }
      }
  return c;
}

// The circle through a, b and c, in long double, relative to a; `flat` where it is too large
// for long double (a, b and c in a line there), and then it meets everything.
struct Circle {
  Circle(const Point& pa, const Point& b, const Point& c) : a(pa) {
    const L bx = b.x - L(a.x), by = b.y - L(a.y), cx = c.x - L(a.x), cy = c.y - L(a.y);
    const L d = 2 * (bx * cy - by * cx), b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    ox = (cy * b2 - by * c2) / d, oy = (bx * c2 - cx * b2) / d, r2 = ox * ox + oy * oy;
    flat = !std::isfinite(r2);
  }
  // Whether it meets the segment from-to.
  bool meets(const Point& from, const Point& to) const {
    if (flat) return true;
    const L px = from.x - L(a.x), py = from.y - L(a.y), qx = to.x - L(a.x), qy = to.y - L(a.y);
    const L ex = qx - px, ey = qy - py, e2 = ex * ex + ey * ey;
    const L s = e2 > 0 ? std::clamp(((ox - px) * ex + (oy - py) * ey) / e2, L(0), L(1)) : L(0);
    const L dx = px + s * ex - ox, dy = py + s * ey - oy;
    return dx * dx + dy * dy <= r2;
  }

  using L = long double;
  Point a;
  L ox = 0, oy = 0, r2 = 0;
  bool flat = false;
};

// Whether triangle a-b-c lies in a wedge (in the closed triangle of its corner and its chains'
// other ends) and its circle meets both chains (as the straight lines from the corner to those
// ends): the triangle is squeezed between them, and its point would split one of them.
bool squeezed(std::span<const Point> pts, const Point& a, const Point& b, const Point& c, const Chains::Wedge& w) {
  const Point &z = pts[w.corner], &e1 = pts[w.end1], &e2 = pts[w.end2];
  for (const Point* v : {&a, &b, &c}) {
    const int o1 = orient2d(z, e1, *v), o2 = orient2d(e1, e2, *v), o3 = orient2d(e2, z, *v);
    if (!((o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0))) return false;
  }
  const Circle circle(a, b, c);
  return circle.meets(z, e1) && circle.meets(z, e2);
}

// The wedges by where they lie, for squeezed(): a grid over their triangles' boxes, each wedge
// listed in the cells its box covers, or, where that is more than 64, in a list every query
// reads.
class Wedges {
 public:
  Wedges(std::span<const Point> pts, const std::vector<Chains::Wedge>& wedges) : pts_(pts), wedges_(wedges) {
    if (wedges.empty()) return;
    auto box = [&](const Chains::Wedge& w) {
      const Point &z = pts[w.corner], &p = pts[w.end1], &q = pts[w.end2];
      return std::array<double, 4>{std::min({z.x, p.x, q.x}), std::min({z.y, p.y, q.y}), std::max({z.x, p.x, q.x}),
                                   std::max({z.y, p.y, q.y})};
    };
    x0_ = y0_ = INFINITY, x1_ = y1_ = -INFINITY;
    for (const Chains::Wedge& w : wedges) {
      const auto b = box(w);
      x0_ = std::min(x0_, b[0]), y0_ = std::min(y0_, b[1]), x1_ = std::max(x1_, b[2]), y1_ = std::max(y1_, b[3]);
    }
    size_ = static_cast<int>(std::clamp(std::sqrt(static_cast<double>(wedges.size())), 1.0, 512.0));
    cells_.resize(static_cast<std::size_t>(size_) * size_);
    for (std::uint32_t k = 0; k < wedges.size(); ++k) {
      const auto b = box(wedges[k]);
      const int i0 = cell(b[0], x0_, x1_), i1 = cell(b[2], x0_, x1_), j0 = cell(b[1], y0_, y1_),
                j1 = cell(b[3], y0_, y1_);
      if ((i1 - i0 + 1) * (j1 - j0 + 1) > 64) {
        wide_.push_back(k);
        continue;
      }
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) cells_[static_cast<std::size_t>(j) * size_ + i].push_back(k);
    }
  }

  // Whether a-b-c is squeezed in any wedge.
  bool hold(const Point& a, const Point& b, const Point& c) const {
    if (wedges_.empty()) return false;
    const long double mx = (a.x + static_cast<long double>(b.x) + c.x) / 3,
                      my = (a.y + static_cast<long double>(b.y) + c.y) / 3;
    if (mx < x0_ || mx > x1_ || my < y0_ || my > y1_) return false;  // in no wedge's box
    auto any = [&](const std::vector<std::uint32_t>& list) {
      return std::any_of(list.begin(), list.end(),
                         [&](std::uint32_t k) { return squeezed(pts_, a, b, c, wedges_[k]); });
    };
    const std::size_t at = static_cast<std::size_t>(cell(my, y0_, y1_)) * size_ + cell(mx, x0_, x1_);
    return any(cells_[at]) || any(wide_);
  }

 private:
  int cell(long double v, long double lo, long double hi) const {
    const long double f = hi > lo ? (v - lo) / (hi - lo) : 0;
    return static_cast<int>(std::clamp<long double>(std::floor(f * size_), 0, size_ - 1));
  }

  std::span<const Point> pts_;
  const std::vector<Chains::Wedge>& wedges_;
  double x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0;
  int size_ = 1;
  std::vector<std::vector<std::uint32_t>> cells_;
  std::vector<std::uint32_t> wide_;
};

// Angles and areas: a triangle below the angle is excused where one of its vertices lies on a
// chain of segment edges that ends at an input angle below 60 degrees (refinement stops short
// of those, as its concentric shells reach them), where its circle meets both chains of such an
// angle (it lies in a wedge thinner than the bound can fill: the area bound or the wedge's far
// end put points there, and splitting it would cut the chains down to the gap between them),
// where its shortest edge is below 2^-39 of the points' extent (refinement splits no
// subsegment that short), or where its circle meets a segment edge that short.
class ShapeCheck {
 public:
  ShapeCheck(std::span<const Point> pts, std::span<const Point> scaled, std::span<const VertexId> tris,
             const MeshSpec& spec, const Chains& chains)
      : pts_(pts), scaled_(scaled), tris_(tris), spec_(spec), chains_(chains), wedges_(scaled, chains.wedges) {
    const Extent box = extent_of(pts);
    const long double w = box.x1 - (long double)box.x0, h = box.y1 - (long double)box.y0;
    tiny2_ = (w * w + h * h) * 0x1p-78L;
    // The segment edges refinement never splits (below 2^-39 of the extent, with a margin).
    for (std::size_t k = 0; k + 1 < spec.edges.size(); k += 2)
      if (length2(spec.edges[k], spec.edges[k + 1]) < 2 * tiny2_)
        short_edges_.emplace_back(spec.edges[k], spec.edges[k + 1]);
  }

  // Every triangle, on threads; the problems reported in the triangles' order.
  MeshShape all(Report& report) const {
    struct Part {
      MeshShape shape;
      Report report;
    };
    InOrder<Part> parts;
    parallel_for(tris_.size() / 3, 0, 1 << 14, [&](std::size_t first, std::size_t last) {
      Part part;
      for (std::size_t t = first; t < last; ++t) measure(t, part.shape, part.report);
      parts.put(first, std::move(part));
    });
    MeshShape shape;
    for (const Part& part : parts.take()) {
      shape.smallest = std::min(shape.smallest, part.shape.smallest);
      shape.largest_area = std::max(shape.largest_area, part.shape.largest_area);
      shape.excused += part.shape.excused;
      report.merge(part.report);
    }
    return shape;
  }

 private:
  long double length2(VertexId a, VertexId b) const {
    const long double dx = pts_[a].x - (long double)pts_[b].x, dy = pts_[a].y - (long double)pts_[b].y;
    return dx * dx + dy * dy;
  }

  // A triangle's smallest angle, in degrees: the one across its shortest side (within the
  // lengths' roundings, which the bound's relative tolerance covers where two are nearly equal).
  long double smallest_angle(const VertexId* v) const {
    int i = 0;
    long double shortest = length2(v[1], v[2]);
    for (int k = 1; k < 3; ++k)
      if (const long double l = length2(v[(k + 1) % 3], v[(k + 2) % 3]); l < shortest) shortest = l, i = k;
    const Point &o = pts_[v[i]], &u = pts_[v[(i + 1) % 3]], &w = pts_[v[(i + 2) % 3]];
    const long double ux = u.x - (long double)o.x, uy = u.y - (long double)o.y;
    const long double wx = w.x - (long double)o.x, wy = w.y - (long double)o.y;
    const long double pi = 3.14159265358979323846264338327950288L;
    return std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 / pi;
  }

  // A vertex on a chain that ends at a corner with a small angle: refinement stops there.
  bool beside_small_angle(VertexId v) const {
    for (const std::uint32_t k : chains_.on[v])
      if (chains_.small[chains_.ends[k].first] || chains_.small[chains_.ends[k].second]) return true;
    return false;
  }

  // A triangle below the angle that refinement leaves so (above).
  bool excused(const VertexId* v) const {
    const long double shortest = std::min({length2(v[0], v[1]), length2(v[1], v[2]), length2(v[2], v[0])});
    auto at_a_short_one = [&] {  // its circle meets a segment edge too short to split
      if (short_edges_.empty()) return false;
      const Circle circle(scaled_[v[0]], scaled_[v[1]], scaled_[v[2]]);
      return std::any_of(short_edges_.begin(), short_edges_.end(),
                         [&](const Edge& e) { return circle.meets(scaled_[e.first], scaled_[e.second]); });
    };
    return beside_small_angle(v[0]) || beside_small_angle(v[1]) || beside_small_angle(v[2]) || shortest < tiny2_ ||
        wedges_.hold(scaled_[v[0]], scaled_[v[1]], scaled_[v[2]]) || at_a_short_one();
  }

  // Triangle t's angle and area against the bounds.
  void measure(std::size_t t, MeshShape& shape, Report& report) const {
    const VertexId* v = &tris_[3 * t];
    const long double worst = smallest_angle(v);
    const Point &a = pts_[v[0]], &b = pts_[v[1]], &c = pts_[v[2]];
    const long double area = std::fabs((b.x - (long double)a.x) * (c.y - (long double)a.y) -
                                       (b.y - (long double)a.y) * (c.x - (long double)a.x)) /
        2;
    shape.smallest = std::min(shape.smallest, worst);
    shape.largest_area = std::max(shape.largest_area, area);
    if (spec_.max_area > 0 && area > spec_.max_area * (1 + 1e-9L))
      report.problem("triangle ", t, " has area ", static_cast<double>(area), ", above ", spec_.max_area);
    if (!(spec_.min_angle > 0 && worst < spec_.min_angle * (1 - 1e-9L))) return;
    if (excused(v))
      ++shape.excused;
    else
      report.problem("triangle ", t, " has an angle of ", static_cast<double>(worst), " degrees, below ",
                     spec_.min_angle, ", and no small input angle beside it");
  }

  std::span<const Point> pts_, scaled_;
  std::span<const VertexId> tris_;
  const MeshSpec& spec_;
  const Chains& chains_;
  const Wedges wedges_;  // in the predicates' coordinates
  long double tiny2_ = 0;
  std::vector<Edge> short_edges_;
};

}  // namespace

MeshShape check_mesh_shape(std::span<const Point> input, std::span<const Point> pts, std::span<const VertexId> tris,
                           const MeshSpec& spec, std::size_t input_points, long double least, const SegmentEdges& edges,
                           Report& report) {
  const Chains chains = chains_of(pts, edges, input_points, least);
  return ShapeCheck(input, pts, tris, spec, chains).all(report);
}

}  // namespace ridt::detail
