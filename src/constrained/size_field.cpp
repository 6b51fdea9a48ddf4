// Size fields (ridt/size_field.hpp): each kind a function of many points at once.
#include "ridt/size_field.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <queue>
#include <string>
#include <utility>

#include "check/parts.hpp"
#include "predicates/predicates.hpp"
#include "ridt/interpolate.hpp"
#include "ridt/predicates.hpp"

namespace ridt {
namespace {

std::string at_point(const Point& p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }

void check_values(std::span<const double> values, const char* what) {
  for (std::size_t k = 0; k < values.size(); ++k)
    if (!(values[k] > 0) || !std::isfinite(values[k]))
      throw InputError(std::string(what) + " " + std::to_string(k) + " is " + std::to_string(values[k]) +
                       ": sizes are finite and above 0");
}

void check_gradation(double rate) {
  if (!(rate >= 0) || !std::isfinite(rate))
    throw InputError("a size field's gradation is a finite number >= 0: got " + std::to_string(rate));
}

// The values lowered where they grow faster than `rate` along the edges of a graph: each
// becomes the least, over every node j, of values[j] + rate * (the shortest path's length to
// j), for every node at once by Dijkstra's algorithm started from all of them, each at its own
// value. Then along every edge i - j, h_i <= h_j + rate * |ij|; no value rises, and the least
// stay. each_neighbour(i, f) calls f(j, |ij|) for each neighbour j of node i.
template <class EachNeighbour>
std::vector<double> limit_growth(std::span<const double> values, double rate, EachNeighbour&& each_neighbour) {
  std::vector<double> h(values.begin(), values.end());
  if (rate == 0 || h.empty()) return h;
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (std::size_t i = 0; i < h.size(); ++i) queue.emplace(h[i], i);
  while (!queue.empty()) {
    const auto [d, i] = queue.top();
    queue.pop();
    if (d > h[i]) continue;  // lowered since it was queued
    each_neighbour(i, [&, d = d](std::size_t j, double length) {
      if (const double c = d + rate * length; c < h[j]) h[j] = c, queue.emplace(c, j);
    });
  }
  return h;
}

// Grid values limited along the grid's rows, columns and diagonals.
std::vector<double> graded_grid(std::span<const double> values, std::size_t nx, std::size_t ny, double x0, double y0,
                                double x1, double y1, double rate) {
  const double sx = nx > 1 ? std::fabs(x1 - x0) / static_cast<double>(nx - 1) : 0;
  const double sy = ny > 1 ? std::fabs(y1 - y0) / static_cast<double>(ny - 1) : 0;
  const double diagonal = std::hypot(sx, sy);
  return limit_growth(values, rate, [&](std::size_t k, auto&& f) {
    const std::size_t i = k % nx, j = k / nx;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        if ((di == 0 && dj == 0) || (di < 0 && i == 0) || (dj < 0 && j == 0) || (di > 0 && i + 1 == nx) ||
            (dj > 0 && j + 1 == ny))
          continue;
        f(k + static_cast<std::size_t>(dj) * nx + static_cast<std::size_t>(di),
          di != 0 && dj != 0 ? diagonal
              : di != 0      ? sx
                             : sy);
      }
  });
}

// Mesh values limited along the mesh's edges.
std::vector<double> graded_mesh(std::span<const Point> vertices, std::span<const VertexId> triangles,
                                std::span<const double> values, double rate) {
  if (rate == 0) return {values.begin(), values.end()};
  const detail::Adjacency sides = detail::Adjacency::of_triangles(vertices.size(), triangles);
  return limit_growth(values, rate, [&](std::size_t v, auto&& f) {
    for (const VertexId w : sides[static_cast<VertexId>(v)])
      f(w, std::hypot(vertices[w].x - vertices[v].x, vertices[w].y - vertices[v].y));
  });
}

// Values on a regular grid, bilinear, clamped to the grid beyond it.
struct GridField {
  std::vector<double> h;
  std::size_t nx, ny;
  double x0, y0, x1, y1;

  // The node coordinate and the weight of the next node along one axis, clamped to the grid.
  static std::pair<std::size_t, double> along(double v, double from, double to, std::size_t n) {
    if (n == 1) return {0, 0};
    const double u = std::clamp((v - from) / (to - from) * static_cast<double>(n - 1), 0.0,
                                static_cast<double>(n - 1));  // NaN for a NaN point: caught by the check after
    const auto i = std::min(static_cast<std::size_t>(u), n - 2);
    return {i, u - static_cast<double>(i)};
  }
  void operator()(std::span<const Point> points, std::span<double> out) const {
    for (std::size_t k = 0; k < points.size(); ++k) {
      const auto [i, fx] = along(points[k].x, x0, x1, nx);
      const auto [j, fy] = along(points[k].y, y0, y1, ny);
      auto value = [&, i = i, j = j](std::size_t di, std::size_t dj) {  // (bindings captured by copy: clang 14)
        return h[std::min(j + dj, ny - 1) * nx + std::min(i + di, nx - 1)];
      };
      const double low = value(0, 0) + fx * (value(1, 0) - value(0, 0));
      const double high = value(0, 1) + fx * (value(1, 1) - value(0, 1));
      out[k] = low + fy * (high - low);
    }
  }
};

// Values at a background mesh's vertices, linear within its triangles: the triangles listed in
// the cells of a uniform grid over their box that their own boxes meet, a point tested exactly
// against those of its cell; beyond them, the nearest vertex's value (a walk on the vertices'
// Delaunay triangulation).
class MeshField {
 public:
  MeshField(std::span<const Point> vertices, std::span<const VertexId> triangles, std::span<const double> values)
      : v_(vertices.begin(), vertices.end()), t_(triangles.begin(), triangles.end()), h_(values.begin(), values.end()) {
    for (std::size_t k = 0; k + 2 < t_.size(); k += 3)
      if (orientation(v_[t_[k]], v_[t_[k + 1]], v_[t_[k + 2]]) < 0) std::swap(t_[k + 1], t_[k + 2]);
    for (const Point& p : v_) box_.add(p);
    const double w = std::max(box_.x1 - box_.x0, 0x1p-1000), hgt = std::max(box_.y1 - box_.y0, 0x1p-1000);
    const double cells = std::max(1.0, static_cast<double>(t_.size() / 3));
    cols_ = std::clamp<std::size_t>(static_cast<std::size_t>(std::sqrt(cells * w / hgt)), 1, 4096);
    rows_ = std::clamp<std::size_t>(static_cast<std::size_t>(cells / static_cast<double>(cols_)), 1, 4096);
    sx_ = static_cast<double>(cols_) / w, sy_ = static_cast<double>(rows_) / hgt;
    list_triangles();
    Options o;
    o.threads = 1;
    delaunay_ = triangulate(v_, o);
  }

  void operator()(std::span<const Point> points, std::span<double> out) const {
    std::vector<Point> beyond;
    std::vector<std::size_t> which;
    for (std::size_t k = 0; k < points.size(); ++k)
      if (!inside(points[k], out[k])) beyond.push_back(points[k]), which.push_back(k);
    if (beyond.empty()) return;
    const std::vector<std::int32_t> near = nearest_vertex(v_, delaunay_, beyond);
    for (std::size_t q = 0; q < beyond.size(); ++q)
      out[which[q]] = h_[near[q] >= 0 ? static_cast<std::size_t>(near[q]) : nearest(beyond[q])];
  }

 private:
  struct Cells {
    std::size_t c0, r0, c1, r1;
  };
  std::size_t col(double x) const {
    const double c = (x - box_.x0) * sx_;
    return c > 0 ? std::min(static_cast<std::size_t>(c), cols_ - 1) : 0;
  }
  std::size_t row(double y) const {
    const double r = (y - box_.y0) * sy_;
    return r > 0 ? std::min(static_cast<std::size_t>(r), rows_ - 1) : 0;
  }
  Cells cells_of(std::size_t k) const {
    const Point &a = v_[t_[k]], &b = v_[t_[k + 1]], &c = v_[t_[k + 2]];
    return {col(std::min({a.x, b.x, c.x})), row(std::min({a.y, b.y, c.y})), col(std::max({a.x, b.x, c.x})),
            row(std::max({a.y, b.y, c.y}))};
  }
  // Counted per cell, then placed (two passes, no list in between).
  void list_triangles() {
    start_.assign(cols_ * rows_ + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<std::uint32_t> next;
      if (pass == 1) {
        for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
        listed_.resize(start_.back());
        next.assign(start_.begin(), start_.end() - 1);
      }
      for (std::size_t k = 0; k + 2 < t_.size(); k += 3) {
        const Cells b = cells_of(k);
        for (std::size_t r = b.r0; r <= b.r1; ++r)
          for (std::size_t c = b.c0; c <= b.c1; ++c)
            if (pass == 0)
              ++start_[r * cols_ + c + 1];
            else
              listed_[next[r * cols_ + c]++] = static_cast<std::uint32_t>(k);
      }
    }
  }
  // The nearest vertex by a look at each: where they have no Delaunay triangle (fewer than three
  // distinct, or all on a line).
  std::size_t nearest(const Point& p) const {
    std::size_t best = 0;
    auto d2 = [&](const Point& v) { return (v.x - p.x) * (v.x - p.x) + (v.y - p.y) * (v.y - p.y); };
    for (std::size_t k = 1; k < v_.size(); ++k)
      if (d2(v_[k]) < d2(v_[best])) best = k;
    return best;
  }
  // Whether a triangle holds p (exactly), and then its value there.
  bool inside(const Point& p, double& value) const {
    if (!(p.x >= box_.x0 && p.x <= box_.x1 && p.y >= box_.y0 && p.y <= box_.y1)) return false;
    const std::size_t cell = row(p.y) * cols_ + col(p.x);
    for (std::uint32_t i = start_[cell]; i < start_[cell + 1]; ++i) {
      const std::uint32_t k = listed_[i];
      const Point &a = v_[t_[k]], &b = v_[t_[k + 1]], &c = v_[t_[k + 2]];
      if (orientation(a, b, p) < 0 || orientation(b, c, p) < 0 || orientation(c, a, p) < 0) continue;
      if (orientation(a, b, c) == 0) continue;  // a triangle without area holds no point of its own
      const std::array<double, 3> w = barycentric(a, b, c, p);
      value = w[0] * h_[t_[k]] + w[1] * h_[t_[k + 1]] + w[2] * h_[t_[k + 2]];
      return true;
    }
    return false;
  }

  std::vector<Point> v_;
  std::vector<VertexId> t_;
  std::vector<double> h_;
  detail::Extent box_{};
  std::size_t cols_ = 1, rows_ = 1;
  double sx_ = 0, sy_ = 0;
  std::vector<std::uint32_t> start_, listed_;
  Triangulation delaunay_;
};

}  // namespace

SizeField SizeField::uniform(double h) {
  if (!(h > 0)) throw InputError("a size is above 0: got " + std::to_string(h));
  return SizeField([h](std::span<const Point>, std::span<double> out) { std::fill(out.begin(), out.end(), h); });
}

SizeField SizeField::on_grid(std::span<const double> values, std::size_t nx, std::size_t ny, double x0, double y0,
                             double x1, double y1, double gradation) {
  if (nx == 0 || ny == 0 || values.size() != nx * ny)
    throw InputError("a size grid of " + std::to_string(nx) + " by " + std::to_string(ny) + " nodes has " +
                     std::to_string(values.size()) + " values");
  for (const double c : {x0, y0, x1, y1})
    if (!std::isfinite(c)) throw InputError("a size grid's extent is finite");
  if ((nx > 1 && x0 == x1) || (ny > 1 && y0 == y1)) throw InputError("a size grid's extent is not empty");
  check_values(values, "size grid value");
  check_gradation(gradation);
  auto g = std::make_shared<const GridField>(
      GridField{graded_grid(values, nx, ny, x0, y0, x1, y1, gradation), nx, ny, x0, y0, x1, y1});
  return SizeField([g](std::span<const Point> p, std::span<double> out) { (*g)(p, out); });
}

SizeField SizeField::on_mesh(std::span<const Point> vertices, std::span<const VertexId> triangles,
                             std::span<const double> values, double gradation) {
  if (values.size() != vertices.size())
    throw InputError("a size mesh has " + std::to_string(vertices.size()) + " vertices and " +
                     std::to_string(values.size()) + " values");
  if (vertices.empty()) throw InputError("a size mesh has no vertex");
  if (triangles.size() % 3 != 0) throw InputError("a size mesh's triangles are 3 indices each");
  for (const VertexId v : triangles)
    if (v >= vertices.size()) throw InputError("a size mesh's triangle names vertex " + std::to_string(v));
  for (const Point& p : vertices)
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw InputError("a size mesh's vertex is not finite");
  check_values(values, "size mesh value");
  check_gradation(gradation);
  auto m = std::make_shared<const MeshField>(vertices, triangles, graded_mesh(vertices, triangles, values, gradation));
  return SizeField([m](std::span<const Point> p, std::span<double> out) { (*m)(p, out); });
}

SizeField SizeField::on_points(std::span<const Point> points, std::span<const double> values, double gradation) {
  if (values.size() != points.size())
    throw InputError("size points: " + std::to_string(points.size()) + " points and " + std::to_string(values.size()) +
                     " values");
  Options o;
  o.threads = 1;
  const Triangulation t = points.empty() ? Triangulation{} : triangulate(points, o);
  return on_mesh(points, t.triangles, values, gradation);
}

SizeField SizeField::of(Function f) {
  if (!f) throw InputError("a size function is empty");
  return SizeField(std::move(f));
}

void SizeField::sizes(std::span<const Point> points, std::span<double> out) const {
  if (out.size() != points.size()) throw InputError("sizes: one a point");
  if (!f_) return std::fill(out.begin(), out.end(), std::numeric_limits<double>::infinity());
  f_(points, out);
  for (std::size_t k = 0; k < out.size(); ++k)
    if (!(out[k] > 0))
      throw InputError("the size field gave " + std::to_string(out[k]) + " at " + at_point(points[k]) +
                       ": sizes are above 0");
}

std::vector<double> SizeField::sizes(std::span<const Point> points) const {
  std::vector<double> out(points.size());
  sizes(points, out);
  return out;
}

}  // namespace ridt
