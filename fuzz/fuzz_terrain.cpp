// Fuzz target: the terrain readers (LAS and tables), and a DEM of what they read.
//
// The first byte picks the reader (even: LAS, odd: a table, its bit 1 the extension .csv or
// .txt) and, for LAS, a filter; the rest is the file. A reader must either throw IoError or
// return finite points with one finite height each (a LAS file no more points than its header
// counts); then, from three points on, the DEM of a small raster over them must hold, in every
// cell, nodata or a height within the heights' range (linear interpolation never leaves it).
// Any other exception, a crash or a sanitizer report is a finding.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "ridt/terrain.hpp"
#include "terrain_io.hpp"

namespace {

namespace io = ridt::io;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_terrain: %s\n", what.c_str());
  std::abort();
}

void dem_of(const io::Terrain& t) {
  if (t.points.size() < 3 || t.points.size() > 5000) return;
  const ridt::Triangulation tri = ridt::triangulate(t.points);
  if (tri.size() == 0) return;
  std::vector<double> z = t.z;
  ridt::merge_heights(tri, z, ridt::Merge::Mean);
  double lo = HUGE_VAL, hi = -HUGE_VAL, x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  for (std::size_t i = 0; i < z.size(); ++i) {
    lo = std::min(lo, z[i]), hi = std::max(hi, z[i]);
    x0 = std::min(x0, t.points[i].x), x1 = std::max(x1, t.points[i].x);
    y0 = std::min(y0, t.points[i].y), y1 = std::max(y1, t.points[i].y);
  }
  const double cell = std::max(x1 - x0, y1 - y0) / 40;
  if (!(cell > 0) || !std::isfinite(cell) || !std::isfinite((x1 - x0) / cell) || !std::isfinite((y1 - y0) / cell))
    return;
  ridt::RasterGrid g;
  try {
    g = ridt::RasterGrid::around(x0, y0, x1, y1, cell);
  } catch (const ridt::InputError&) {
    return;
  }
  if (g.size() > 10000) return;
  const std::vector<double> v = ridt::Dem(t.points, tri, z, g).all();
  // The barycentric weights are within 2^-44 of the exact ones: the value within a few 2^-44 of
  // the largest height's size.
  const double slack = 1e-12 * (std::abs(lo) + std::abs(hi)) + 1e-300;
  for (const double h : v)
    if (!std::isnan(h) && (h < lo - slack || h > hi + slack)) finding("a linear DEM cell outside the heights' range");
}

void check(const io::Terrain& t) {
  if (t.z.size() != t.points.size()) finding("heights and points differ in number");
  for (std::size_t i = 0; i < t.points.size(); ++i)
    if (!std::isfinite(t.points[i].x) || !std::isfinite(t.points[i].y) || !std::isfinite(t.z[i]))
      finding("a coordinate is not finite");
  dem_of(t);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view data(reinterpret_cast<const char*>(bytes) + 1, size - 1);
  try {
    if (bytes[0] % 2 == 0) {
      io::PointFilter filter;
      filter.returns = static_cast<ridt::Returns>((bytes[0] >> 1) % 4);
      if (bytes[0] & 8) filter.classes = {2};
      filter.withheld = (bytes[0] & 16) != 0;
      const io::LasHeader h = io::parse_las_header(data, "in.las");
      const io::Terrain t = io::parse_las(data, "in.las", filter);
      if (t.points.size() > h.count) finding("more points than the header counts");
      check(t);
    } else {
      check(io::parse_table(data, (bytes[0] & 2) ? "in.csv" : "in.txt"));
    }
  } catch (const io::IoError&) {}
  return 0;
}
