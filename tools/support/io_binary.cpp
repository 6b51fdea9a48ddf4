// Raw little-endian binary: points as float64 x, y pairs, triangles as uint32 triples.
#include <thread>

#include "io_common.hpp"

namespace ridt::io::detail {

namespace {

void check_bin_size(const std::string& path, std::size_t bytes) {
  if (bytes % 16 != 0)
    fail_file(path, "size " + std::to_string(bytes) + " bytes is not a multiple of 16 (pairs of float64 x, y)");
}

// Each point's coordinates checked, on a thread for every 16 MiB up to the machine's hardware
// threads: for a mapped file this first read is also what brings its pages in, on every thread
// at once rather than on one (10^8 points, 1.6 GB: 0.4 s on one thread).
void check_finite(const std::string& path, std::span<const Point> points) {
  const auto parts = static_cast<unsigned>(
      std::clamp<std::size_t>(points.size() >> 20, 1, std::max(1u, std::thread::hardware_concurrency())));
  std::vector<std::size_t> bad(parts, points.size());
  auto scan = [&](unsigned k) {
    for (std::size_t i = points.size() * k / parts; i < points.size() * (k + 1) / parts; ++i)
      if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y)) {
        bad[k] = i;
        return;
      }
  };
  {
    std::vector<std::jthread> helpers;
    for (unsigned k = 1; k < parts; ++k) helpers.emplace_back(scan, k);
    scan(0);
  }
  const std::size_t i = *std::min_element(bad.begin(), bad.end());
  if (i == points.size()) return;
  const double x = points[i].x, y = points[i].y;
  fail_file(path,
            "point " + std::to_string(i) + " has " + (std::isnan(x) || std::isnan(y) ? "a NaN" : "an infinite") +
                " coordinate");
}

}  // namespace

PointFile read_bin_points(const std::string& path, std::string_view data, unsigned /*threads*/) {
  check_bin_size(path, data.size());
  std::vector<Point> points(data.size() / 16);
  for (std::size_t i = 0; i < points.size(); ++i)
    points[i] = {load_f64_le(data.data() + 16 * i), load_f64_le(data.data() + 16 * i + 8)};
  check_finite(path, points);
  return PointFile(std::move(points));
}

std::optional<PointFile> map_bin_points(const std::string& path) {
  if constexpr (std::endian::native != std::endian::little) return std::nullopt;
  static_assert(sizeof(Point) == 16 && alignof(Point) <= 16);
  std::optional<Mapping> m = map_file(path);
  if (!m) return std::nullopt;
  check_bin_size(path, m->bytes.size());
  // Used where they lie; brought in by the check on threads. Where the file shrinks later, the
  // points past its end read as zeros, and the tools refuse to write what they made of them
  // (any_mapping_shrank).
  const std::span<const Point> points(reinterpret_cast<const Point*>(m->bytes.data()), m->bytes.size() / 16);
  check_finite(path, points);
  if (m->shrank()) throw shrank_error(path);
  return PointFile(std::move(m->owner), points);
}

std::vector<VertexId> read_bin_triangles(const std::string& path, std::string_view data) {
  if (data.size() % 12 != 0) {
    fail_file(
        path,
        "size " + std::to_string(data.size()) + " bytes is not a multiple of 12 (triples of uint32 vertex indices)");
  }
  std::vector<VertexId> out(data.size() / 4);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = load_u32_le(data.data() + 4 * i);
  return out;
}

void write_bin_points(Writer& out, std::span<const Point> points, int /*first_index*/, unsigned /*threads*/) {
  for (const Point& p : points) {
    out.put_f64_le(p.x);
    out.put_f64_le(p.y);
  }
}

void write_bin_triangles(Writer& out, std::span<const VertexId> triangles) {
  if constexpr (std::endian::native == std::endian::little) {  // the array as it lies: one large write
    out.put(std::string_view(reinterpret_cast<const char*>(triangles.data()), triangles.size() * sizeof(VertexId)));
  } else {
    for (const VertexId v : triangles) out.put_u32_le(v);
  }
}

void put_bin_sorted(Writer& out, std::size_t first, std::span<const VertexId> triangles) {
  const std::uint64_t at = 4 * std::uint64_t{3} * first;
  if constexpr (std::endian::native == std::endian::little) {
    out.put_at(at, std::string_view(reinterpret_cast<const char*>(triangles.data()), triangles.size_bytes()));
  } else {
    std::vector<VertexId> swapped(triangles.begin(), triangles.end());
    for (VertexId& v : swapped) v = __builtin_bswap32(v);
    out.put_at(at, std::string_view(reinterpret_cast<const char*>(swapped.data()), triangles.size_bytes()));
  }
}

}  // namespace ridt::io::detail
