// Heights of points that share x and y (merge_heights), and a shaded relief of a raster
// (hillshade): ridt/terrain.hpp.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "ridt/terrain.hpp"

namespace ridt {

void merge_heights(const Triangulation& t, std::span<double> z, Merge how) {
  std::size_t n = 0;
  for (const Duplicate& d : t.duplicates) n = std::max<std::size_t>(n, std::max(d.dropped, d.kept) + 1);
  if (n > z.size())
    throw InputError("merge_heights: " + std::to_string(z.size()) + " heights for a triangulation of at least " +
                     std::to_string(n) + " points");
  if (how == Merge::First || t.duplicates.empty()) return;  // the kept point is the first one
  // Groups of equal points: the kept one and its dropped ones, in input order.
  std::vector<Duplicate> pairs = t.duplicates;
  std::stable_sort(pairs.begin(), pairs.end(), [](const Duplicate& a, const Duplicate& b) { return a.kept < b.kept; });
  for (std::size_t g = 0; g < pairs.size();) {
    const VertexId kept = pairs[g].kept;
    double value = z[kept], sum = z[kept];
    std::size_t members = 1;
    for (; g < pairs.size() && pairs[g].kept == kept; ++g, ++members) {
      const double h = z[pairs[g].dropped];
      sum += h;
      switch (how) {
        case Merge::Last:
          value = h;
          break;
        case Merge::Lowest:
          value = std::min(value, h);
          break;
        case Merge::Highest:
          value = std::max(value, h);
          break;
        default:
          break;
      }
    }
    z[kept] = how == Merge::Mean ? sum / static_cast<double>(members) : value;
  }
}

std::vector<std::uint8_t> hillshade(std::span<const double> dem, std::size_t nx, std::size_t ny, double cell,
                                    double nodata, double azimuth, double altitude, double z_factor) {
  if (dem.size() != nx * ny)
    throw InputError("hillshade: " + std::to_string(dem.size()) + " cells for " + std::to_string(nx) + " by " +
                     std::to_string(ny));
  if (!(cell > 0)) throw InputError("hillshade: the cell size must be positive");
  constexpr double kDegree = std::numbers::pi / 180;
  const double zenith = (90 - altitude) * kDegree;
  const double sun = (360 - azimuth + 90) * kDegree;  // counter-clockwise from east
  auto missing = [&](double v) { return std::isnan(nodata) ? std::isnan(v) : v == nodata || std::isnan(v); };
  std::vector<std::uint8_t> shade(nx * ny, 0);
  for (std::size_t j = 1; j + 1 < ny; ++j)
    for (std::size_t i = 1; i + 1 < nx; ++i) {
      double w[9];  // the 3 by 3 window, row by row from the north-west
      bool hole = false;
      for (int k = 0; k < 9; ++k) {
        w[k] = dem[(j + k / 3 - 1) * nx + i + k % 3 - 1];
        hole = hole || missing(w[k]);
      }
      if (hole) continue;
      // Horn's slopes: east minus west, south minus north, each weighted 1, 2, 1.
      const double dx = ((w[2] + 2 * w[5] + w[8]) - (w[0] + 2 * w[3] + w[6])) / (8 * cell) * z_factor;
      const double dy = ((w[6] + 2 * w[7] + w[8]) - (w[0] + 2 * w[1] + w[2])) / (8 * cell) * z_factor;
      const double slope = std::atan(std::hypot(dx, dy)), aspect = std::atan2(dy, -dx);
      const double light =
          std::cos(zenith) * std::cos(slope) + std::sin(zenith) * std::sin(slope) * std::cos(sun - aspect);
      shade[j * nx + i] = static_cast<std::uint8_t>(1 + std::lround(254 * std::max(0.0, light)));
    }
  return shade;
}

}  // namespace ridt
