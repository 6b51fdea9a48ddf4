// A partition thread's region (methods/partition.cpp), as ranges: in the first pass the vertices whose
// Hilbert keys lie in one interval round the circle of 32-bit keys, tested by vertex id alone;
// in the second, cells of a grid turned against the curve's squares.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>

#include "ridt/ridt.hpp"

#include "order/order.hpp"

namespace ridt::detail {

/// The vertices v < n whose keys key[v] lie in [lo, lo + len) round the circle of 32-bit keys
/// (len up to 2^32: the whole circle). The vertices come in BRIO rounds (round_end), each
/// sorted by key, so a round's vertices in the region are one interval of its ids, or, where
/// the region wraps past key 0, its first ids and its last: one interval round the circle of
/// 32-bit ids. holds() reads that round's entry, which stays in cache, and not the vertex's
/// key, which would be a miss of its own. Made before any thread reads it.
struct KeyRange {
  // Read only: a region that changes is made again (the ids follow from these).
  std::uint32_t lo = 0;
  std::uint64_t len = 0;
  struct Ids {
    std::uint32_t first = 0, count = 0;  // ids [first, first + count) round the circle of ids
  };
  std::array<Ids, 32> ids{};  // by round_of(); past the last round: none

  KeyRange() = default;
  KeyRange(const std::uint32_t* key, std::uint32_t n, std::uint32_t lo_key, std::uint64_t length)
      : lo(lo_key), len(length) {
    constexpr std::uint64_t kCircle = std::uint64_t{1} << 32;
    for (std::uint32_t b = 0; b < n; b = round_end(b)) {
      const std::uint32_t e = std::min(round_end(b), n);
      // The round's first id whose key is at least k (e for 2^32).
      auto at = [&](std::uint64_t k) {
        if (k >= kCircle) return e;
        return static_cast<std::uint32_t>(std::lower_bound(key + b, key + e, static_cast<std::uint32_t>(k)) - key);
      };
      Ids& r = ids[round_of(b)];
      if (len >= kCircle) {
        r = {b, e - b};
      } else if (lo + len <= kCircle) {
        const std::uint32_t first = at(lo);
        r = {first, at(lo + len) - first};
      } else {  // keys [lo, 2^32) and [0, lo + len - 2^32): ids [first, e) and [b, end)
        const std::uint32_t end = at(lo + len - kCircle), first = at(lo);
        r = end == first ? Ids{b, e - b} : Ids{first, end - first};  // end - first wraps round
      }
    }
  }

  /// Vertex v's entry: b's for every v of the round that starts at b. kFirstRound - 1 | v is
  /// never 0, so the count of leading zeros needs no test.
  static unsigned round_of(std::uint32_t v) {
    static_assert(std::has_single_bit(kFirstRound));
    return 31 - static_cast<unsigned>(std::countl_zero(v | (kFirstRound - 1)));
  }
  /// Whether vertex v < n is in the region (for an id past the points, the answer means nothing).
  bool holds(std::uint32_t v) const {
    const Ids& r = ids[round_of(v)];
    return static_cast<std::uint32_t>(v - r.first) < r.count;
  }
};

/// A region of the partition method's second pass: the vertices v < n whose cell, in a grid of
/// kSide by kSide cells turned by atan(1/2) against the axes, has `id` in `owner`. The first
/// pass's borders follow the Hilbert curve's squares, along the axes, and the points it put off
/// lie along them; this grid's lines cross them at single places, where an interval of the
/// curve cut elsewhere would share whole sides of its squares with them.
struct CellRange {
  static constexpr int kSide = 128;
  static constexpr double kCos = 0.89442719099991588, kSin = 0.44721359549995794;  // 2 and 1 over sqrt(5)

  /// The grid over `put_off` (items whose `p` is a vertex id): its box in the turned axes cut
  /// into kSide by kSide cells; vertices outside it fall in the cells at its edges.
  template <class PutOffs>
  static CellRange grid(const Point* points, std::uint32_t n, const PutOffs& put_off) {
    double u_lo = HUGE_VAL, u_hi = -HUGE_VAL, w_lo = HUGE_VAL, w_hi = -HUGE_VAL;
    for (const auto& x : put_off) {
      const auto [u, w] = turned(points[x.p]);
      u_lo = std::min(u_lo, u), u_hi = std::max(u_hi, u), w_lo = std::min(w_lo, w), w_hi = std::max(w_hi, w);
    }
    CellRange r;
    r.points = points, r.n = n;
    r.u0 = u_lo, r.w0 = w_lo;
    // One column (or row) where the points lie on a line across it, or where the box's width
    // overflows.
    const double du = u_hi - u_lo, dw = w_hi - w_lo;
    r.su = du > 0 && du < HUGE_VAL ? kSide / du : 0;
    r.sw = dw > 0 && dw < HUGE_VAL ? kSide / dw : 0;
    return r;
  }

  /// Point q's coordinates (u, w) on the turned axes.
  static std::pair<double, double> turned(Point q) { return {q.x * kCos + q.y * kSin, q.y * kCos - q.x * kSin}; }
  /// The cell of point q: kSide * row + column, the coordinates clamped into the grid.
  int cell(Point q) const {
    const auto [u, w] = turned(q);
    return kSide * index((w - w0) * sw) + index((u - u0) * su);
  }
  /// t clamped to [0, kSide - 1] and rounded down (NaN: 0).
  static int index(double t) { return static_cast<int>(std::min<double>(kSide - 1, std::max(0.0, t))); }
  /// Whether vertex v is in the region (v past the points: no, and no read past them).
  bool holds(std::uint32_t v) const { return (v < n) & (owner[cell(points[std::min(v, n - 1)])] == id); }

  const Point* points = nullptr;
  const std::uint16_t* owner = nullptr;  // kSide * kSide cells' regions
  double u0 = 0, w0 = 0, su = 0, sw = 0;
  std::uint32_t n = 0;
  std::uint16_t id = 0;
};

}  // namespace ridt::detail
