// A .bin point file bucketed on disk into cells, for the out-of-core triangulation
// (ridt/out_of_core.hpp): columns of about equal counts, each cut into rows, every cell's points in
// input order, one file of (x, y, input index) records laid out column by column.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ridt/regions.hpp"

namespace ridt::detail {

using regions::Box;
using regions::by_place;
using regions::hull_of_sorted;
using regions::Site;

// Cuts of a line, and which stretch between them a value falls in: the number of cuts at or
// below it, found through a table of equal bins (each the count of cuts at its start) and a
// search among the bin's own cuts, most often none: a binary search over all of them missed its
// branches at every point of the input.
class Cuts {
 public:
  Cuts() = default;
  Cuts(std::vector<double> cuts, double lo, double hi);
  std::size_t size() const { return cut_.size(); }
  double operator[](std::size_t i) const { return cut_[i]; }
  std::size_t stretch(double v) const {
    const double f = (v / 2 - lo_) * scale_;
    const std::size_t b = !(f > 0)                    ? 0
        : f >= static_cast<double>(first_.size() - 1) ? first_.size() - 1
                                                      : static_cast<std::size_t>(f);
    std::size_t from = first_[b], to = b + 1 < first_.size() ? first_[b + 1] : cut_.size();
    // Rounding may put v a bin off: then the search takes every cut.
    if (from > 0 && cut_[from - 1] > v) from = 0;
    if (to < cut_.size() && cut_[to] <= v) to = cut_.size();
    return static_cast<std::size_t>(std::upper_bound(cut_.begin() + from, cut_.begin() + to, v) - cut_.begin());
  }

 private:
  std::vector<double> cut_;
  double lo_ = 0, scale_ = 0;  // halved: the extent may span more than the largest double
  std::vector<std::uint32_t> first_;
};

class CellStore {
 public:
  /// Reads `input` (a .bin file, checked: whole pairs, finite coordinates) twice and writes its
  /// points into a file that `scratch` names, removed when the store goes (and at once from the
  /// directory: nothing is left behind by a crash). `column_points`: about how many points a
  /// column holds; `buffer_bytes`: what the writes may buffer. progress(fraction) as it goes.
  CellStore(const std::string& input, const std::string& scratch, std::uint64_t column_points, std::size_t buffer_bytes,
            const std::function<void(double)>& progress);
  ~CellStore();
  CellStore(const CellStore&) = delete;
  CellStore& operator=(const CellStore&) = delete;

  std::uint64_t points() const { return points_; }
  std::size_t columns() const { return xcut_.size() + 1; }
  std::size_t rows() const { return ycut_.size() + 1; }
  /// Points in column c, and in cell (c, r).
  std::uint64_t column_size(std::size_t c) const { return start_[(c + 1) * rows()] - start_[c * rows()]; }
  std::uint64_t cell_size(std::size_t c, std::size_t r) const {
    return start_[c * rows() + r + 1] - start_[c * rows() + r];
  }
  /// The column and the row of a point.
  std::size_t column_of(double x) const;
  std::size_t row_of(double y) const;
  /// Column c holds the points with left(c) <= x < left(c + 1) (left(0) is -infinity and
  /// left(columns()) +infinity); rows alike in y.
  double left(std::size_t c) const;
  /// A box that holds every point of cell (c, r) (the points' extent closes the outer cells).
  Box cell_box(std::size_t c, std::size_t r) const;
  /// The convex hull of cell (c, r)'s points and of column c's, counter-clockwise (each point
  /// strictly beyond a line has a hull corner beyond it too), kept in memory: a few dozen
  /// points a cell.
  const std::vector<Site>& cell_hull(std::size_t c, std::size_t r) const { return hull_[c * rows() + r]; }
  const std::vector<Site>& column_hull(std::size_t c) const { return column_hull_[c]; }
  /// The convex hull of all the points.
  const std::vector<Site>& hull() const { return hull_all_; }
  /// Appends column c's points, cell after cell, to `out`.
  void read_column(std::size_t c, std::vector<Site>& out) const { read(start_[c * rows()], column_size(c), out); }
  /// Appends cell (c, r)'s points to `out`.
  void read_cell(std::size_t c, std::size_t r, std::vector<Site>& out) const {
    read(start_[c * rows() + r], cell_size(c, r), out);
  }

 private:
  void read(std::uint64_t first, std::uint64_t count, std::vector<Site>& out) const;
  void cut(const std::string& input, std::uint64_t column_points);
  void count(const std::string& input);
  void write(const std::string& input, std::size_t buffer_bytes, const std::function<void(double)>& progress);
  void hulls();

  std::uint64_t points_ = 0;
  Box extent_{};
  Cuts xcut_, ycut_;  // interior cuts: column c is [xcut[c - 1], xcut[c])
  std::vector<std::uint64_t> start_;  // start_[c * rows + r]: the first record of cell (c, r)
  std::vector<std::vector<Site>> hull_, column_hull_;
  std::vector<Site> hull_all_;
  std::string scratch_;
  int fd_ = -1;
};

}  // namespace ridt::detail
