// The on-disk cells of the out-of-core triangulation (cells.hpp): three passes over the input,
// read a block at a time (a mapping would count the file's pages in the process's memory): the
// extent, the finite check and a sample; the count of each cell; the records, written through
// a small buffer a cell at the place the counts give them.
#include "regions/cells.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <memory>

#include "regions/files.hpp"

namespace ridt::detail {
namespace {

constexpr std::size_t kBlock = std::size_t{1} << 20;  // points read at a time (16 MiB)
constexpr std::size_t kSample = 65536;  // points sampled for the cuts

struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

// Calls visit(first index, points) for each block of the .bin file at `path`, in order.
template <class Visit>
void each_block(const std::string& path, Visit&& visit) {
  static_assert(std::endian::native == std::endian::little, "the .bin format is little-endian");
  const Fd in{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (in.fd < 0) throw IoError("cannot read " + path + ": " + errno_text(errno));
  const off_t bytes = ::lseek(in.fd, 0, SEEK_END);
  if (bytes < 0) throw IoError("cannot read " + path + ": " + errno_text(errno));
  if (bytes % 16 != 0)
    throw InputError(path + ": size " + std::to_string(bytes) +
                     " bytes is not a multiple of 16 (pairs of float64 x, y)");
  const std::unique_ptr<Point[]> block(new Point[kBlock]);
  const auto n = static_cast<std::uint64_t>(bytes) / 16;
  for (std::uint64_t first = 0; first < n; first += kBlock) {
    const std::size_t count = static_cast<std::size_t>(std::min<std::uint64_t>(kBlock, n - first));
    auto* to = reinterpret_cast<char*>(block.get());
    for (std::size_t done = 0; done < count * 16;) {
      const ssize_t got = ::pread(in.fd, to + done, count * 16 - done, static_cast<off_t>(first * 16 + done));
      if (got <= 0) throw IoError("cannot read " + path + ": " + (got == 0 ? "it shrank" : errno_text(errno)));
      done += static_cast<std::size_t>(got);
    }
    visit(first, std::span<const Point>(block.get(), count));
  }
}

// `count` - 1 cuts at the quantiles of `values` (sorted here).
std::vector<double> quantiles(std::vector<double>& values, std::size_t count) {
  std::sort(values.begin(), values.end());
  std::vector<double> cuts;
  for (std::size_t k = 1; k < count && !values.empty(); ++k) cuts.push_back(values[k * values.size() / count]);
  return cuts;
}

}  // namespace

Cuts::Cuts(std::vector<double> cuts, double lo, double hi) : cut_(std::move(cuts)), lo_(lo / 2) {
  const std::size_t bins = 8 * cut_.size() + 1;
  scale_ = hi / 2 > lo_ ? static_cast<double>(bins) / (hi / 2 - lo_) : 0;
  first_.resize(bins);
  for (std::size_t b = 0, i = 0; b < bins; ++b) {
    const double start = b == 0 ? -INFINITY : 2 * (lo_ + static_cast<double>(b) / scale_);
    while (i < cut_.size() && cut_[i] <= start) ++i;
    first_[b] = static_cast<std::uint32_t>(i);
  }
}

CellStore::CellStore(const std::string& input, const std::string& scratch, std::uint64_t column_points,
                     std::size_t buffer_bytes, const std::function<void(double)>& progress)
    : scratch_(scratch) {
  cut(input, column_points);
  count(input);
  fd_ = ::open(scratch.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd_ < 0) throw IoError("cannot write " + scratch + ": " + errno_text(errno));
  ::unlink(scratch.c_str());  // the open descriptor keeps it until the store goes
  write(input, buffer_bytes, progress);
  hulls();
}

CellStore::~CellStore() {
  if (fd_ >= 0) ::close(fd_);
}

// The extent, the check that every coordinate is finite, and the cuts from a sample: columns of
// about `column_points` points (at most 4096), and rows of some 64 points a cell, at most 65,536
// cells in all, so that the write's buffers and the tables stay small.
void CellStore::cut(const std::string& input, std::uint64_t column_points) {
  std::vector<double> xs, ys;
  std::uint64_t stride = 1;  // the sample: every stride-th point, stride doubled as it fills
  extent_ = {INFINITY, INFINITY, -INFINITY, -INFINITY};
  each_block(input, [&](std::uint64_t at, std::span<const Point> block) {
    for (std::size_t i = 0; i < block.size(); ++i) {
      const Point& p = block[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw InputError(input + ": point " + std::to_string(at + i) + " has " +
                         (std::isnan(p.x) || std::isnan(p.y) ? "a NaN" : "an infinite") + " coordinate");
      extent_ = {std::min(extent_.x0, p.x), std::min(extent_.y0, p.y), std::max(extent_.x1, p.x),
                 std::max(extent_.y1, p.y)};
      if ((at + i) % stride == 0) {
        xs.push_back(p.x), ys.push_back(p.y);
        if (xs.size() == 2 * kSample) {  // keep every other one, and take half as many from now
          for (std::size_t k = 0; k < kSample; ++k) xs[k] = xs[2 * k], ys[k] = ys[2 * k];
          xs.resize(kSample), ys.resize(kSample), stride *= 2;
        }
      }
    }
    points_ = at + block.size();
  });
  const auto columns = static_cast<std::size_t>(
      std::clamp<std::uint64_t>((points_ + column_points - 1) / std::max<std::uint64_t>(column_points, 1), 1, 4096));
  const std::uint64_t per_column = points_ / columns;
  const auto rows = static_cast<std::size_t>(std::clamp<std::uint64_t>(per_column / 64, 1, 65536 / columns));
  xcut_ = Cuts(quantiles(xs, columns), extent_.x0, extent_.x1);
  ycut_ = Cuts(quantiles(ys, rows), extent_.y0, extent_.y1);
}

std::size_t CellStore::column_of(double x) const { return xcut_.stretch(x); }
std::size_t CellStore::row_of(double y) const { return ycut_.stretch(y); }

double CellStore::left(std::size_t c) const { return c == 0 ? -INFINITY : c > xcut_.size() ? INFINITY : xcut_[c - 1]; }

Box CellStore::cell_box(std::size_t c, std::size_t r) const {
  return {c == 0 ? extent_.x0 : xcut_[c - 1], r == 0 ? extent_.y0 : ycut_[r - 1],
          c == xcut_.size() ? extent_.x1 : xcut_[c], r == ycut_.size() ? extent_.y1 : ycut_[r]};
}

void CellStore::count(const std::string& input) {
  start_.assign(columns() * rows() + 1, 0);
  each_block(input, [&](std::uint64_t, std::span<const Point> block) {
    for (const Point& p : block) ++start_[column_of(p.x) * rows() + row_of(p.y) + 1];
  });
  for (std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
}

void CellStore::write(const std::string& input, std::size_t buffer_bytes, const std::function<void(double)>& progress) {
  const std::size_t cells = columns() * rows();
  const std::size_t room = std::clamp<std::size_t>(buffer_bytes / (cells * sizeof(Site)), 1, 1024);
  std::vector<Site> buffer(cells * room);
  std::vector<std::size_t> held(cells, 0);
  std::vector<std::uint64_t> next(start_.begin(), start_.end() - 1);
  auto flush = [&](std::size_t cell) {
    const char* from = reinterpret_cast<const char*>(&buffer[cell * room]);
    const std::size_t bytes = held[cell] * sizeof(Site);
    for (std::size_t done = 0; done < bytes;) {
      const ssize_t put =
          ::pwrite(fd_, from + done, bytes - done, static_cast<off_t>(next[cell] * sizeof(Site) + done));
      if (put <= 0) throw IoError("cannot write " + scratch_ + ": " + errno_text(put == 0 ? ENOSPC : errno));
      done += static_cast<std::size_t>(put);
    }
    next[cell] += held[cell];
    held[cell] = 0;
  };
  each_block(input, [&](std::uint64_t at, std::span<const Point> block) {
    for (std::size_t i = 0; i < block.size(); ++i) {
      const std::size_t cell = column_of(block[i].x) * rows() + row_of(block[i].y);
      buffer[cell * room + held[cell]++] = {block[i].x, block[i].y, at + i};
      if (held[cell] == room) flush(cell);
    }
    if (progress) progress(static_cast<double>(at + block.size()) / static_cast<double>(points_));
  });
  for (std::size_t cell = 0; cell < cells; ++cell) flush(cell);
}

// Each cell's hull, a column at a time, and each column's from its cells' hulls.
void CellStore::hulls() {
  hull_.assign(columns() * rows(), {});
  column_hull_.assign(columns(), {});
  std::vector<Site> column, corners;
  for (std::size_t c = 0; c < columns(); ++c) {
    column.clear();
    read_column(c, column);
    corners.clear();
    for (std::size_t r = 0, at = 0; r < rows(); at += cell_size(c, r), ++r) {
      const auto first = column.begin() + static_cast<std::ptrdiff_t>(at);
      std::vector<Site> cell(first, first + static_cast<std::ptrdiff_t>(cell_size(c, r)));
      std::sort(cell.begin(), cell.end(), by_place);
      hull_[c * rows() + r] = hull_of_sorted(cell);
      corners.insert(corners.end(), hull_[c * rows() + r].begin(), hull_[c * rows() + r].end());
    }
    std::sort(corners.begin(), corners.end(), by_place);
    column_hull_[c] = hull_of_sorted(corners);
  }
  corners.clear();
  for (const std::vector<Site>& h : column_hull_) corners.insert(corners.end(), h.begin(), h.end());
  std::sort(corners.begin(), corners.end(), by_place);
  hull_all_ = hull_of_sorted(corners);
}

void CellStore::read(std::uint64_t first, std::uint64_t count, std::vector<Site>& out) const {
  const std::size_t at = out.size();
  out.resize(at + count);
  auto* to = reinterpret_cast<char*>(out.data() + at);
  for (std::size_t done = 0; done < count * sizeof(Site);) {
    const ssize_t got =
        ::pread(fd_, to + done, count * sizeof(Site) - done, static_cast<off_t>(first * sizeof(Site) + done));
    if (got <= 0) throw IoError("cannot read " + scratch_ + ": " + (got == 0 ? "it shrank" : errno_text(errno)));
    done += static_cast<std::size_t>(got);
  }
}

}  // namespace ridt::detail
