// A raster of heights from a triangulated terrain (ridt/terrain.hpp), band by band: the
// triangles are bucketed once by the bands of rows they reach, then each band is answered by
// the triangles over it with the grid machinery of the interpolation calls (queries/field.hpp),
// so a band costs its own triangles and cells, and the raster never lies in memory whole.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "queries/arrays.hpp"
#include "queries/field.hpp"
#include "queries/sibson.hpp"
#include "ridt/terrain.hpp"
#include "runtime/parallel.hpp"
#include "tds/ids.hpp"

namespace ridt {
namespace {

using detail::Field;
using detail::kNoVertex;
using detail::next3;
using detail::parallel_for;
using detail::prev3;
using detail::thread_count;

// Rows a band by default: a multiple of 64 that fills some 64 MiB of doubles (at least 64 rows:
// 51 MB of a 10^5-cell-wide raster). A band of 64 rows of a raster at the points' spacing holds
// some 128 times as many triangles as it has columns, so the triangles that reach two bands
// (and are listed twice) are a few per cent.
constexpr std::size_t kBandRows = 64;
constexpr std::size_t kBandBytes = std::size_t{64} << 20;

std::size_t default_band_rows(std::size_t nx) {
  return kBandRows * std::max<std::size_t>(1, kBandBytes / (8 * std::max<std::size_t>(nx, 1)) / kBandRows);
}
constexpr double kMaxCells = 1099511627776.0;  // 2^40

double squared(double x) { return x * x; }

double distance2(const Point& a, const Point& b) { return squared(a.x - b.x) + squared(a.y - b.y); }

// The rows whose centres might lie within [lo, hi] in y, one row of slack each way.
std::pair<std::size_t, std::size_t> rows_within(const RasterGrid& g, double lo, double hi) {
  const double top = std::floor((g.y1 - hi) / g.cell - 0.5) - 1, bottom = std::ceil((g.y1 - lo) / g.cell - 0.5) + 1;
  const double last = static_cast<double>(g.ny) - 1;
  return {static_cast<std::size_t>(std::clamp(top, 0.0, last)),
          static_cast<std::size_t>(std::clamp(bottom, 0.0, last))};
}

// InputError unless the cells' centres are distinct doubles, in order: where a cell is no more
// than a few units in the last place of the coordinates (a fine cell far from the origin), two
// centres would round to one.
void check_centres(const RasterGrid& g) {
  const double far = std::max({std::fabs(g.x(0)), std::fabs(g.x(g.nx)), std::fabs(g.y(0)), std::fabs(g.y(g.ny))});
  if (!(g.cell > 4 * (std::nextafter(far, HUGE_VAL) - far)))
    throw InputError("raster: cells " + std::to_string(g.cell) + " wide are too small for coordinates as large as " +
                     std::to_string(far) + " (their centres would not be distinct numbers); choose a larger cell");
}

}  // namespace

RasterGrid RasterGrid::around(double x0, double y0, double x1, double y1, double cell) {
  if (!(std::isfinite(cell) && cell > 0))
    throw InputError("raster: the cell size must be positive and finite, not " + std::to_string(cell));
  if (!(std::isfinite(x0) && std::isfinite(y0) && std::isfinite(x1) && std::isfinite(y1)) || x1 < x0 || y1 < y0)
    throw InputError("raster: the extent must be finite, with x0 <= x1 and y0 <= y1");
  const double left = std::floor(x0 / cell) * cell, right = std::ceil(x1 / cell) * cell;
  const double bottom = std::floor(y0 / cell) * cell, top = std::ceil(y1 / cell) * cell;
  const double nx = std::max(1.0, std::round((right - left) / cell));
  const double ny = std::max(1.0, std::round((top - bottom) / cell));
  if (!(nx * ny <= kMaxCells))
    throw InputError("raster: " + std::to_string(nx) + " by " + std::to_string(ny) +
                     " cells is more than 2^40; choose a larger cell");
  const RasterGrid g{left, top, cell, static_cast<std::size_t>(nx), static_cast<std::size_t>(ny)};
  check_centres(g);
  return g;
}

Dem::Dem(std::span<const Point> points, const Triangulation& t, std::span<const double> z, const RasterGrid& grid,
         const DemOptions& options)
    : neighbors_(t.neighbors),
      grid_(grid),
      options_(options),
      band_rows_(options.band_rows > 0 ? options.band_rows : default_band_rows(grid.nx)) {
  detail::check_arrays("dem", points.size(), t.triangles, t.neighbors);
  if (z.size() != points.size())
    throw InputError("dem: " + std::to_string(z.size()) + " heights for " + std::to_string(points.size()) + " points");
  if (!(options.max_edge > 0)) throw InputError("dem: the largest edge must be positive");
  if (grid.nx == 0 || grid.ny == 0 || !(grid.cell > 0)) throw InputError("dem: an empty raster");
  check_centres(grid);
  options_.threads = thread_count(options.threads);
  renumber(points, t.triangles, z);
  bucket();
  if (options.method == Surface::Nearest) {
    vertex_triangle_.assign(points_.size(), -1);
    for (std::size_t k = 0; k < triangles_.size(); ++k)
      vertex_triangle_[triangles_[k]] = static_cast<std::int32_t>(k / 3);
  }
}

// The points (and heights) that the triangles use, numbered in the order the triangles first
// meet them. The triangles lie in memory in an order near in the plane, the points in the
// input's, often a random one: every later pass then reads corners near in memory instead of
// missing the cache at each one, which pays for this one pass that does.
void Dem::renumber(std::span<const Point> points, std::span<const VertexId> triangles, std::span<const double> z) {
  std::vector<VertexId> id(points.size(), kNoVertex), old;
  old.reserve(points.size());
  triangles_.resize(triangles.size());
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    VertexId& v = id[triangles[k]];
    if (v == kNoVertex) v = static_cast<VertexId>(old.size()), old.push_back(triangles[k]);
    triangles_[k] = v;
  }
  points_.resize(old.size());
  z_.resize(old.size());
  parallel_for(old.size(), options_.threads, 1 << 16, [&](std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) points_[k] = points[old[k]], z_[k] = z[old[k]];
  });
}

// The triangles of each band. A first pass over the triangles (reading their corners, in no
// order in memory) notes each one's first band and how many follow, counted in fixed chunks; a
// second pass over those notes (in order) lists each triangle in its bands, so that a band lists
// its triangles in increasing order for any thread count.
void Dem::bucket() {
  const std::size_t count = triangles_.size() / 3, nb = (grid_.ny + band_rows_ - 1) / band_rows_;
  if (nb == 1) {  // one band: every triangle, in order
    members_.resize(count);
    std::iota(members_.begin(), members_.end(), 0u);
    bands_ = {0, count};
    return;
  }
  const std::size_t chunks = std::min<std::size_t>(count / 4096 + 1, 4 * options_.threads);
  std::vector<std::uint64_t> counts(chunks * (nb + 1), 0);
  std::vector<std::uint32_t> first(count);
  std::vector<std::uint8_t> more(count);  // bands after the first; 255: count them again
  auto bands_of = [&](std::size_t tri) {
    const double a = points_[triangles_[3 * tri]].y, b = points_[triangles_[3 * tri + 1]].y,
                 d = points_[triangles_[3 * tri + 2]].y;
    const auto [r0, r1] = rows_within(grid_, std::min({a, b, d}), std::max({a, b, d}));
    return std::pair(r0 / band_rows_, r1 / band_rows_);
  };
  parallel_for(chunks, options_.threads, 1, [&](std::size_t c0, std::size_t c1) {
    for (std::size_t c = c0; c < c1; ++c)
      for (std::size_t tri = count * c / chunks; tri < count * (c + 1) / chunks; ++tri) {
        const auto [b0, b1] = bands_of(tri);
        first[tri] = static_cast<std::uint32_t>(b0);
        more[tri] = static_cast<std::uint8_t>(std::min<std::size_t>(b1 - b0, 255));
        for (std::size_t band = b0; band <= b1; ++band) ++counts[c * (nb + 1) + band];
      }
  });
  bands_.assign(nb + 1, 0);
  std::uint64_t total = 0;  // offsets: band by band, chunk by chunk within a band
  for (std::size_t band = 0; band < nb; ++band) {
    bands_[band] = total;
    for (std::size_t c = 0; c < chunks; ++c) {
      const std::uint64_t here = counts[c * (nb + 1) + band];
      counts[c * (nb + 1) + band] = total;  // from now on: where chunk c's next one goes
      total += here;
    }
  }
  bands_[nb] = total;
  members_.resize(total);
  parallel_for(chunks, options_.threads, 1, [&](std::size_t c0, std::size_t c1) {
    for (std::size_t c = c0; c < c1; ++c)
      for (std::size_t tri = count * c / chunks; tri < count * (c + 1) / chunks; ++tri) {
        const std::size_t last = more[tri] == 255 ? bands_of(tri).second : first[tri] + more[tri];
        for (std::size_t band = first[tri]; band <= last; ++band)
          members_[counts[c * (nb + 1) + band]++] = static_cast<std::uint32_t>(tri);
      }
  });
}

// Greedy steps on the Delaunay graph from a corner of the triangle that holds q: each step
// goes to a neighbour nearer q, and a vertex none of whose neighbours is nearer is a nearest
// point (the Delaunay graph's property that greedy routing relies on).
VertexId Dem::nearest(std::size_t tri, const Point& q) const {
  VertexId v = triangles_[3 * tri];
  for (int i = 1; i < 3; ++i)
    if (distance2(points_[triangles_[3 * tri + i]], q) < distance2(points_[v], q)) v = triangles_[3 * tri + i];
  for (bool moved = true; moved;) {
    moved = false;
    double best = distance2(points_[v], q);
    VertexId next = v;
    // Around v: counter-clockwise from one of its triangles, then clockwise where the hull stops it.
    const auto start = static_cast<std::size_t>(vertex_triangle_[v]);
    for (int turn = 0; turn < 2; ++turn) {
      std::size_t at = start;
      for (std::size_t steps = 0; steps < triangles_.size() / 3; ++steps) {
        const int i = triangles_[3 * at] == v ? 0 : triangles_[3 * at + 1] == v ? 1 : 2;
        for (const int k : {next3(i), prev3(i)}) {
          const VertexId w = triangles_[3 * at + k];
          if (const double d = distance2(points_[w], q); d < best) best = d, next = w;
        }
        const std::int32_t u = neighbors_[3 * at + (turn == 0 ? prev3(i) : next3(i))];
        if (u < 0 || static_cast<std::size_t>(u) == start) break;
        at = static_cast<std::size_t>(u);
      }
    }
    moved = next != v;
    v = next;
  }
  return v;
}

void Dem::band(std::size_t b, std::span<double> out) const {
  const std::size_t r0 = b * band_rows_, r1 = std::min(grid_.ny, r0 + band_rows_), nx = grid_.nx;
  if (b >= bands() || out.size() != (r1 - r0) * nx)
    throw InputError("dem: band " + std::to_string(b) + " of " + std::to_string(bands()) + " with room for " +
                     std::to_string(out.size()) + " cells");
  std::vector<double> xs(nx), ys(r1 - r0);
  for (std::size_t i = 0; i < nx; ++i) xs[i] = grid_.x(i);
  for (std::size_t j = r0; j < r1; ++j) ys[j - r0] = grid_.y(j);
  const detail::Axis ax("dem", "x", xs), ay("dem", "y", ys);
  const Grid grid{xs, ys, false};
  const Field field{points_, triangles_, neighbors_, Values{z_, 1}};
  std::fill(out.begin(), out.end(), options_.nodata);
  const double longest2 = squared(options_.max_edge);
  const std::span<const std::uint32_t> tris(members_.data() + bands_[b], bands_[b + 1] - bands_[b]);
  parallel_for(tris.size(), options_.threads, detail::kGrain / 4, [&](std::size_t first, std::size_t last) {
    detail::Natural natural(field);
    // A triangle with a side over max_edge answers nowhere; a node on its side or corner goes to
    // a neighbour that does.
    auto short_enough = [&](std::size_t tri) {
      const Point &a = field.corner(tri, 0), &c = field.corner(tri, 1), &d = field.corner(tri, 2);
      return distance2(a, c) <= longest2 && distance2(c, d) <= longest2 && distance2(d, a) <= longest2;
    };
    auto take = [&](std::size_t tri, std::size_t node, const Point& p, const double* w, int from) {
      switch (options_.method) {
        case Surface::Linear:
          field.linear(tri, p, &out[node], w, from);
          break;
        case Surface::Natural:
          natural(tri, p, &out[node]);
          break;
        case Surface::Nearest:
          out[node] = z_[nearest(tri, p)];
          break;
      }
    };
    for (std::size_t k = first; k < last; ++k) detail::cover_triangle(field, ax, ay, grid, tris[k], take, short_enough);
  });
}

void Dem::all(std::span<double> out) const {
  if (out.size() != grid_.size())
    throw InputError("dem: room for " + std::to_string(out.size()) + " cells, not " + std::to_string(grid_.size()));
  for (std::size_t b = 0; b < bands(); ++b) {
    const std::size_t r0 = b * band_rows_, r1 = std::min(grid_.ny, r0 + band_rows_);
    band(b, out.subspan(r0 * grid_.nx, (r1 - r0) * grid_.nx));
  }
}

std::vector<double> Dem::all() const {
  std::vector<double> out(grid_.size());
  all(out);
  return out;
}

}  // namespace ridt
