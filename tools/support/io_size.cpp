// Size fields from files (`ridt mesh --size FILE`, the registry's "size in" role): scattered
// points (a .node's first attribute), a background mesh (a .ele and the .node beside it), a grid
// (an ESRI ASCII grid here, GDAL's rasters through its module).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "formats.hpp"
#include "io.hpp"
#include "io_common.hpp"
#include "terrain_io.hpp"

namespace ridt::io::detail {
namespace {

// The first attribute of each of g's points: the size there.
std::vector<double> first_attribute(const Pslg& g, const std::string& path) {
  if (g.vertex_attributes == 0) fail_file(path, "has no attribute: a size field's size is its points' first attribute");
  std::vector<double> h(g.points.size());
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = g.point_attributes[k * g.vertex_attributes];
  return h;
}

// A field's values refused (InputError) named with the file's path.
template <class F>
SizeField made(const std::string& path, F&& make) {
  try {
    return make();
  } catch (const InputError& e) {
    fail_file(path, e.what());
  }
}

// The number of a header line "key value" of an ESRI ASCII grid.
double header_value(const std::string& path, std::size_t line, std::string_view field) {
  double v = 0;
  if (parse_double(field, v) != Parse::Ok || !std::isfinite(v))
    fail_line(path, line, quoted(field) + " is not a number");
  return v;
}

}  // namespace

SizeField read_size_node(const std::string& path, unsigned threads, double gradation) {
  const Pslg g = read_pslg(path, threads);
  const std::vector<double> h = first_attribute(g, path);
  return made(path, [&] { return SizeField::on_points(g.points, h, gradation); });
}

SizeField read_size_mesh(const std::string& path, unsigned threads, double gradation) {
  const std::string node = path.substr(0, path.size() - 4) + ".node";
  const Pslg g = read_pslg(node, threads);
  const std::vector<double> h = first_attribute(g, node);
  std::vector<double> attributes;
  std::vector<VertexId> middles;
  const std::vector<VertexId> t = read_elements(path, g.first_index, attributes, middles, threads);
  return made(path, [&] { return SizeField::on_mesh(g.points, t, h, gradation); });
}

// Header lines `ncols`, `nrows`, `xllcorner` or `xllcenter`, `yllcorner` or `yllcenter`,
// `cellsize`, optionally `nodata_value`, in any order; then the rows, the top one first.
SizeField read_size_ascii_grid(const std::string& path, unsigned /*threads*/, double gradation) {
  const std::string text = read_file_whole(path);
  std::string_view rest = without_bom(text);
  double ncols = -1, nrows = -1, x = NAN, y = NAN, cell = NAN, nodata = NAN;
  bool centre_x = false, centre_y = false;
  std::size_t line = 0;
  while (!rest.empty()) {
    const std::size_t end = std::min(rest.find('\n'), rest.size());
    const std::string_view l = rest.substr(0, end);
    Fields f{l, false};
    std::string_view key, value;
    if (!f.next(key) || !(std::isalpha(static_cast<unsigned char>(key[0])))) break;  // the values begin
    ++line;
    if (!f.next(value) || f.count_rest() != 0) fail_line(path, line, "expected `key value`, got " + quoted(l));
    const std::string k = lower_case(key);
    const double v = header_value(path, line, value);
    if (k == "ncols")
      ncols = v;
    else if (k == "nrows")
      nrows = v;
    else if (k == "xllcorner" || k == "xllcenter")
      x = v, centre_x = k == "xllcenter";
    else if (k == "yllcorner" || k == "yllcenter")
      y = v, centre_y = k == "yllcenter";
    else if (k == "cellsize")
      cell = v;
    else if (k == "nodata_value")
      nodata = v;
    else
      fail_line(path, line, "unknown key " + quoted(key) + " of an ESRI ASCII grid");
    rest.remove_prefix(std::min(end + 1, rest.size()));
  }
  constexpr double kMost = 0x1p31;  // cells a side, as GDAL's rasters
  if (!(ncols >= 1 && nrows >= 1 && ncols <= kMost && nrows <= kMost && ncols == std::floor(ncols) &&
        nrows == std::floor(nrows)) ||
      std::isnan(x) || std::isnan(y) || !(cell > 0))
    fail_file(path, "an ESRI ASCII grid's header gives ncols, nrows, xllcorner, yllcorner and cellsize > 0");
  const auto nx = static_cast<std::size_t>(ncols), ny = static_cast<std::size_t>(nrows);
  std::vector<double> h;
  h.reserve(std::min(nx * ny, rest.size() / 2 + 1));  // a value and a space at least
  for_each_line(rest, [&](std::size_t, std::string_view l) {
    Fields f{l, false};
    std::string_view field;
    while (f.next(field)) {
      double v = 0;
      if (parse_double(field, v) != Parse::Ok) fail_file(path, "value " + quoted(field) + " is not a number");
      if (v == nodata)
        fail_file(path, "has no value (nodata) at cell " + std::to_string(h.size()) + ": a size is needed everywhere");
      h.push_back(v);
    }
  });
  if (h.size() != nx * ny)
    fail_file(path,
              "has " + std::to_string(h.size()) + " values for " + std::to_string(nx) + " by " + std::to_string(ny) +
                  " cells");
  // Cell centres: the first column's, the top row's, and the last of each.
  const double x0 = centre_x ? x : x + cell / 2, y_bottom = centre_y ? y : y + cell / 2;
  const double x1 = x0 + cell * static_cast<double>(nx - 1), y_top = y_bottom + cell * static_cast<double>(ny - 1);
  return made(path, [&] { return SizeField::on_grid(h, nx, ny, x0, y_top, x1, y_bottom, gradation); });
}

SizeField read_size_gdal(const std::string& path, unsigned /*threads*/, double gradation) {
  RasterIn r;
  if (std::error_code ec; !fs::exists(path, ec)) throw IoError("cannot read " + path + ": " + errno_text(ENOENT));
  gdal_module(path).read_raster(path, r);
  return made(path, [&] { return SizeField::on_grid(r.values, r.nx, r.ny, r.x0, r.y0, r.x1, r.y1, gradation); });
}

}  // namespace ridt::io::detail

namespace ridt::io {

SizeField read_size_field(const std::string& path, unsigned threads, double gradation) {
  return detail::format_of(path, detail::kSizeIn).size_in.fn(path, threads, gradation);
}

std::string size_formats() { return detail::extensions_with(detail::kSizeIn); }

}  // namespace ridt::io
