// TINs and DEMs out (terrain_io.hpp): PLY and OBJ with heights and the hillshade PNG here,
// GDAL's formats in io_gdal.cpp, each found in the registry (formats.cpp).
#include "formats.hpp"
#include "terrain_io.hpp"

namespace ridt::io {
namespace {

using detail::fail_file;
using detail::format_of;

void check_tin(const std::string& path, const Terrain& terrain, const Triangulation& t) {
  if (terrain.z.size() != terrain.points.size())
    fail_file(path,
              std::to_string(terrain.z.size()) + " heights for " + std::to_string(terrain.points.size()) + " points");
  detail::check_indices(path, std::span(t.triangles).first(3 * t.size()), terrain.points.size(), "a triangle");
}

}  // namespace

void detail::write_tin_ply(const std::string& path, const Terrain& terrain, const Triangulation& t) {
  Writer out(path);
  out.put("ply\nformat binary_little_endian 1.0\ncomment ridt: a TIN\nelement vertex ");
  out.put_int(static_cast<std::int64_t>(terrain.points.size()));
  out.put("\nproperty double x\nproperty double y\nproperty double z\nelement face ");
  out.put_int(static_cast<std::int64_t>(t.size()));
  out.put("\nproperty list uchar uint vertex_indices\nend_header\n");
  for (std::size_t i = 0; i < terrain.points.size(); ++i)
    out.put_f64_le(terrain.points[i].x), out.put_f64_le(terrain.points[i].y), out.put_f64_le(terrain.z[i]);
  for (std::size_t k = 0; k < 3 * t.size(); k += 3) {
    out.put('\3');
    for (int i = 0; i < 3; ++i) out.put_u32_le(t.triangles[k + i]);
  }
  out.commit();
}

void detail::write_tin_obj(const std::string& path, const Terrain& terrain, const Triangulation& t) {
  Writer out(path);
  out.put("# ridt: a TIN\n");
  for (std::size_t i = 0; i < terrain.points.size(); ++i) {
    out.put("v ");
    out.put_double(terrain.points[i].x);
    out.put(' ');
    out.put_double(terrain.points[i].y);
    out.put(' ');
    out.put_double(terrain.z[i]);
    out.put('\n');
  }
  for (std::size_t k = 0; k < 3 * t.size(); k += 3) {
    out.put('f');
    for (int i = 0; i < 3; ++i) out.put(' '), out.put_int(static_cast<std::int64_t>(t.triangles[k + i]) + 1);
    out.put('\n');
  }
  out.commit();
}

// The DEM's hillshade as a grey picture, transparent where there is no shade.
void detail::write_dem_png(const std::string& path, const Dem& dem, const DemFile& /*file*/) {
  const RasterGrid& g = dem.grid();
  if (g.nx > 65535 || g.ny > 65535) fail_file(path, "a hillshade .png is at most 65535 cells a side");
  const std::vector<std::uint8_t> shade = hillshade(dem.all(), g.nx, g.ny, g.cell, dem.options().nodata);
  std::vector<unsigned char> ga(2 * shade.size());
  for (std::size_t k = 0; k < shade.size(); ++k) ga[2 * k] = shade[k], ga[2 * k + 1] = shade[k] == 0 ? 0 : 255;
  Writer out(path);
  out.put(detail::png_bytes(path, ga.data(), g.nx, g.ny, 2));
  out.commit();
}

void write_tin(const std::string& path, const Terrain& terrain, const Triangulation& t) {
  check_tin(path, terrain, t);
  format_of(path, detail::kTinOut).tin_out.fn(path, terrain, t);
}

void write_hillshade(const std::string& path, const Dem& dem) {
  if (detail::extension_of(path) != ".png")
    fail_file(path, "a hillshade is a .png picture (the DEM itself: .tif or .img)");
  detail::write_dem_png(path, dem, {});
}

void write_dem(const std::string& path, const Dem& dem, const DemFile& file) {
  format_of(path, detail::kDemOut).dem_out.fn(path, dem, file);
}

Terrain read_terrain(const std::string& path, const PointFilter& filter, const Columns& columns) {
  return format_of(path, detail::kTerrainIn).terrain_in.fn(path, filter, columns);
}

std::string terrain_formats() { return detail::extensions_with(detail::kTerrainIn); }
std::string tin_formats() { return detail::extensions_with(detail::kTinOut); }
std::string dem_formats() { return detail::extensions_with(detail::kDemOut); }

}  // namespace ridt::io
