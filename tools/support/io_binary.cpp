// Raw little-endian binary: points as float64 x, y pairs, triangles as uint32 triples.
#include "io_common.hpp"

namespace ridt::io::detail {

namespace {

void check_bin_size(const std::string& path, std::size_t bytes) {
  if (bytes % 16 != 0)
    fail_file(path, "size " + std::to_string(bytes) + " bytes is not a multiple of 16 (pairs of float64 x, y)");
}

void check_finite(const std::string& path, std::span<const Point> points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double x = points[i].x, y = points[i].y;
    if (std::isfinite(x) && std::isfinite(y)) continue;
    fail_file(path,
              "point " + std::to_string(i) + " has " + (std::isnan(x) || std::isnan(y) ? "a NaN" : "an infinite") +
                  " coordinate");
  }
}

}  // namespace

PointFile read_bin_points(const std::string& path, std::string_view data) {
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
  struct File {
    int fd;
    ~File() {
      if (fd >= 0) ::close(fd);
    }
  };
  // A pipe or a device is read, not mapped; asked before opening it, which would take the
  // writer's end of a pipe from the reader that follows.
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  errno = 0;
  const File file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) throw IoError("cannot read " + path + ": " + errno_text(errno));
  if (::fstat(file.fd, &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  const auto bytes = static_cast<std::size_t>(st.st_size);
  check_bin_size(path, bytes);
  if (bytes == 0) return PointFile();
  // All pages at once; they are the page cache's own, shared, never copied.
  void* at = ::mmap(nullptr, bytes, PROT_READ, MAP_PRIVATE | MAP_POPULATE, file.fd, 0);
  if (at == MAP_FAILED) return std::nullopt;
  std::shared_ptr<const void> owner(at, [bytes](const void* p) { ::munmap(const_cast<void*>(p), bytes); });
  const std::span<const Point> points(static_cast<const Point*>(at), bytes / 16);
  check_finite(path, points);
  return PointFile(std::move(owner), points);
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

void write_bin_points(Writer& out, std::span<const Point> points, int /*first_index*/) {
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

}  // namespace ridt::io::detail
