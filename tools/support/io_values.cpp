// Values at points and at queries: text and .csv rows, raw float64, and a grid as a .png
// picture (libpng, where the build found it).
#include "formats.hpp"
#include "io_common.hpp"

#ifdef RIDT_HAVE_PNG
#include <png.h>
#endif

namespace ridt::io {
namespace {

// A perceptually ordered colour map, dark blue through green to yellow, at t in [0, 1].
void colour(double t, unsigned char* rgb) {
  static const double stops[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  t = std::clamp(t, 0.0, 1.0) * 4;
  const int k = std::min(static_cast<int>(t), 3);
  const double f = t - k;
  for (int c = 0; c < 3; ++c)
    rgb[c] = static_cast<unsigned char>(std::lround(stops[k][c] + f * (stops[k + 1][c] - stops[k][c])));
}

void write_png(Writer& out, const std::string& path, std::span<const double> v, std::size_t nx, std::size_t ny) {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const double x : v)
    if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
  // Row 0 of the picture is the grid's last row: y up.
  std::vector<unsigned char> rgba(4 * nx * ny, 0);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const double x = v[j * nx + i];
      unsigned char* px = &rgba[4 * ((ny - 1 - j) * nx + i)];
      if (!std::isfinite(x)) continue;  // transparent
      colour(hi > lo ? (x - lo) / (hi - lo) : 0.5, px);
      px[3] = 255;
    }
  out.put(detail::png_bytes(path, rgba.data(), nx, ny, 4));
}

}  // namespace

std::string detail::png_bytes(const std::string& path, const unsigned char* pixels, std::size_t nx, std::size_t ny,
                              int channels) {
#ifdef RIDT_HAVE_PNG
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(nx);
  image.height = static_cast<png_uint_32>(ny);
  image.format = channels == 4 ? PNG_FORMAT_RGBA : PNG_FORMAT_GA;
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&image, nullptr, &size, 0, pixels, 0, nullptr))
    detail::fail_file(path, std::string("cannot encode the picture: ") + image.message);
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&image, bytes.data(), &size, 0, pixels, 0, nullptr))
    detail::fail_file(path, std::string("cannot encode the picture: ") + image.message);
  png_image_free(&image);
  bytes.resize(size);
  return bytes;
#else
  (void)pixels, (void)nx, (void)ny, (void)channels;
  detail::fail_file(path, "this build writes no .png (it was built without libpng: apt-get install libpng-dev)");
#endif
}

namespace {

// Calls row(numbers) for each row of `components` numbers in `data`, the bytes of `path`, as
// read_values reads them (setting `components` where it is 0).
template <class Row>
void for_each_row(std::string_view data, const std::string& path, std::size_t& components, Row&& row) {
  std::vector<double> r;
  if (detail::extension_of(path) == ".bin") {
    if (components == 0) components = 1;
    if (data.size() % (8 * components) != 0)
      detail::fail_file(path,
                        "size " + std::to_string(data.size()) + " bytes is not a multiple of " +
                            std::to_string(8 * components) + " (rows of float64)");
    r.resize(components);
    for (std::size_t at = 0; at < data.size(); at += 8 * components) {
      for (std::size_t k = 0; k < components; ++k) r[k] = detail::load_f64_le(data.data() + at + 8 * k);
      row(r.data());
    }
    return;
  }
  detail::for_each_line(data, [&](std::size_t line_no, std::string_view line) {
    detail::Fields f{line, true};
    r.clear();
    for (std::string_view field; f.next(field);) {
      double v = 0;
      if (detail::parse_double(field, v) != detail::Parse::Ok)
        detail::fail_line(path, line_no, "value " + detail::quoted(field) + " is not a number");
      r.push_back(v);
    }
    if (f.bad) detail::fail_line(path, line_no, "a misplaced comma in " + detail::quoted(line));
    if (components == 0) components = r.size();
    if (r.size() != components)
      detail::fail_line(path, line_no,
                        "expected " + std::to_string(components) + " values, got " + std::to_string(r.size()));
    row(r.data());
  });
  if (components == 0) components = 1;
}

// The rows `data` may hold: exactly those of a .bin; for text at most its lines, and at most
// one in six bytes (the shortest row: "0 0 0\n").
std::size_t rows_in(std::string_view data, const std::string& path, std::size_t components) {
  if (detail::extension_of(path) == ".bin") return data.size() / (8 * std::max<std::size_t>(components, 1));
  return std::min(static_cast<std::size_t>(std::count(data.begin(), data.end(), '\n')) + 1, data.size() / 6 + 1);
}

}  // namespace

// (The file mapped, not copied: a copy of 10^6 rows of three numbers is 24 MB of fresh pages.)
std::vector<double> read_values(const std::string& path, std::size_t& components) {
  return detail::FileText(path).parse([&](std::string_view data) {
    std::vector<double> out;
    if (detail::extension_of(path) == ".bin") out.reserve(data.size() / 8);
    for_each_row(data, path, components, [&](const double* r) { out.insert(out.end(), r, r + components); });
    return out;
  });
}

void read_weighted(const std::string& path, std::vector<Point>& points, std::vector<double>& weights) {
  std::size_t components = 3;
  detail::FileText(path).parse([&](std::string_view data) {
    const std::size_t most = rows_in(data, path, components);
    points.clear(), weights.clear();
    points.reserve(most), weights.reserve(most);
    for_each_row(data, path, components, [&](const double* r) {
      points.push_back({r[0], r[1]}), weights.push_back(r[2]);
    });
    return 0;
  });
}

namespace detail {

void write_values_png(Writer& out, const ValuesOut& v) {
  if (v.nx == 0 || v.ny == 0 || v.components != 1)
    fail_file(v.path, "a .png picture needs a grid (--grid) and one value a point");
  write_png(out, v.path, v.values, v.nx, v.ny);
}

void write_values_bin(Writer& out, const ValuesOut& v) {
  for (const double x : v.values) out.put_value_f64_le(x);
}

void write_values_csv(Writer& out, const ValuesOut& v) {
  out.put("x,y");
  for (std::size_t k = 0; k < v.components; ++k) out.put(",v"), out.put_int(static_cast<std::int64_t>(k));
  out.put('\n');
  for (std::size_t i = 0; i < v.queries.size(); ++i) {
    out.put_double(v.queries[i].x), out.put(','), out.put_double(v.queries[i].y);
    for (std::size_t k = 0; k < v.components; ++k) out.put(','), out.put_value(v.values[i * v.components + k]);
    out.put('\n');
  }
}

}  // namespace detail

}  // namespace ridt::io
