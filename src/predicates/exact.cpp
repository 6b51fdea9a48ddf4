// Exact evaluation of the predicates with integers.
//
// Every double is an integer multiple of its unit in the last place; within one predicate call
// all coordinates are integer multiples of the smallest such unit U = 2^emin among them. The
// determinants are homogeneous polynomials in coordinate differences, so their sign equals the
// sign of the same polynomial evaluated on the integers x / U. Those integers have at most
// 2098 bits (2^1024 / 2^-1074), so a degree-4 polynomial fits in 140 limbs of 64 bits. In the
// common case (coordinates of similar size) the integers have one or two limbs and the
// evaluation is cheap; only wildly different magnitudes in one call make it long.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "predicates/bigint.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/power.hpp"
#include "predicates/predicates.hpp"
#include "ridt/predicates.hpp"

namespace ridt::detail {
using exact::BigInt;
using exact::min_ulp_exponent;
using exact::ulp_exponent;

namespace {

// The points of one call scaled by exact_scale_exponent (predicates/predicates.hpp), where the filter
// fails only for their size: then it decides as usual, and only true near-degeneracies reach
// the integers. False when the points are fine as they are or cannot be scaled exactly.
template <std::size_t N>
bool rescale(Point (&p)[N], double low, double high) {
  const int k = exact_scale_exponent(p, low, high);
  if (k == 0) return false;
  for (Point& q : p) q = {std::ldexp(q.x, k), std::ldexp(q.y, k)};
  return true;
}

}  // namespace

int orient2d_hard(const Point& a, const Point& b, const Point& c) {
  // Degree 2: the filter works while the differences stay within 2^+-400.
  Point s[3] = {a, b, c};
  if (rescale(s, 0x1p-400, 0x1p400)) {
    const double l = (s[0].x - s[2].x) * (s[1].y - s[2].y);
    const double r = (s[0].y - s[2].y) * (s[1].x - s[2].x);
    const double det = l - r, bound = kOrientBound * (std::fabs(l) + std::fabs(r)) + kOrientUnderflow;
    if (det > bound) return 1;
    if (det < -bound) return -1;
  }
  return orient2d_exact(a, b, c);
}

int orient2d_exact(const Point& a, const Point& b, const Point& c) {
  const int e = min_ulp_exponent({a.x, a.y, b.x, b.y, c.x, c.y});
  const BigInt cx = BigInt::from_double(c.x, e), cy = BigInt::from_double(c.y, e);
  const BigInt acx = BigInt::from_double(a.x, e) - cx, acy = BigInt::from_double(a.y, e) - cy;
  const BigInt bcx = BigInt::from_double(b.x, e) - cx, bcy = BigInt::from_double(b.y, e) - cy;
  return (acx * bcy - acy * bcx).sign();
}

int incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d) {
  const int e = min_ulp_exponent({a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y});
  const BigInt dx = BigInt::from_double(d.x, e), dy = BigInt::from_double(d.y, e);
  const BigInt adx = BigInt::from_double(a.x, e) - dx, ady = BigInt::from_double(a.y, e) - dy;
  const BigInt bdx = BigInt::from_double(b.x, e) - dx, bdy = BigInt::from_double(b.y, e) - dy;
  const BigInt cdx = BigInt::from_double(c.x, e) - dx, cdy = BigInt::from_double(c.y, e) - dy;
  const BigInt alift = adx * adx + ady * ady;
  const BigInt blift = bdx * bdx + bdy * bdy;
  const BigInt clift = cdx * cdx + cdy * cdy;
  const BigInt det =
      alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady);
  return det.sign();
}

void barycentric_exact(const Point& a, const Point& b, const Point& c, const Point& q, double weight[3]) {
  const int e = min_ulp_exponent({a.x, a.y, b.x, b.y, c.x, c.y, q.x, q.y});
  const BigInt ax = BigInt::from_double(a.x, e), ay = BigInt::from_double(a.y, e);
  const BigInt bx = BigInt::from_double(b.x, e), by = BigInt::from_double(b.y, e);
  const BigInt cx = BigInt::from_double(c.x, e), cy = BigInt::from_double(c.y, e);
  const BigInt qx = BigInt::from_double(q.x, e), qy = BigInt::from_double(q.y, e);
  // Twice the signed areas of (q, b, c), (a, q, c), (a, b, q) and (a, b, c), in units of 2^2e.
  auto area = [](const BigInt& ux, const BigInt& uy, const BigInt& vx, const BigInt& vy, const BigInt& wx,
                 const BigInt& wy) { return (ux - wx) * (vy - wy) - (uy - wy) * (vx - wx); };
  const BigInt part[3] = {area(qx, qy, bx, by, cx, cy), area(ax, ay, qx, qy, cx, cy), area(ax, ay, bx, by, qx, qy)};
  int whole_exponent = 0;
  const double whole = area(ax, ay, bx, by, cx, cy).scaled(0, whole_exponent);
  for (int i = 0; i < 3; ++i) {
    int exponent = 0;
    const double m = part[i].scaled(0, exponent);
    weight[i] = m == 0 ? 0.0 : std::ldexp(m / whole, exponent - whole_exponent);
  }
}

// The power centre of the three with no weights (predicates/power_exact.cpp).
Point circumcentre_exact(const Point& a, const Point& b, const Point& c) {
  return power_centre_exact({a, 0}, {b, 0}, {c, 0});
}

double doubled_area_exact(const Point& a, const Point& b, const Point& c) {
  const int e = min_ulp_exponent({a.x, a.y, b.x, b.y, c.x, c.y});
  const BigInt cx = BigInt::from_double(c.x, e), cy = BigInt::from_double(c.y, e);
  const BigInt acx = BigInt::from_double(a.x, e) - cx, acy = BigInt::from_double(a.y, e) - cy;
  const BigInt bcx = BigInt::from_double(b.x, e) - cx, bcy = BigInt::from_double(b.y, e) - cy;
  int exponent = 0;
  const double m = (acx * bcy - acy * bcx).scaled(2 * e, exponent);
  return std::ldexp(m, exponent);
}

namespace {

// Where the line a-b crosses the line u-w (they cross properly): p = a + (b - a) N / D with
// N = area(u, w, a), D = N - area(u, w, b). Its coordinate `axis` (0: x, 1: y), the value v,
// compared exactly with (c1 + c2) / 2: sign(2 v - c1 - c2) = sign((2a - c1 - c2) D + 2 (b - a) N)
// times sign(D).
int compare_crossing(const Point& a, const Point& b, const Point& u, const Point& w, int axis, double c1, double c2) {
  const int e = std::min(min_ulp_exponent({a.x, a.y, b.x, b.y, u.x, u.y, w.x, w.y}), min_ulp_exponent({c1, c2}));
  auto big = [e](double x) { return BigInt::from_double(x, e); };
  auto area = [&](const Point& p, const Point& q, const Point& r) {
    return (big(p.x) - big(r.x)) * (big(q.y) - big(r.y)) - (big(p.y) - big(r.y)) * (big(q.x) - big(r.x));
  };
  const BigInt n = area(u, w, a), d = n - area(u, w, b);
  const double ac = axis == 0 ? a.x : a.y, bc = axis == 0 ? b.x : b.y;
  const BigInt diff = big(bc) - big(ac), twice_n = n + n;
  const BigInt value = (big(ac) + big(ac) - big(c1) - big(c2)) * d + diff * twice_n;
  return value.sign() * d.sign();
}

// The double nearest the crossing's coordinate `axis` (ties to even): bisection over the
// doubles between a's and b's coordinate (the crossing lies between them), in their order as
// integers, then the nearer of the two that bracket it.
double crossing_coordinate(const Point& a, const Point& b, const Point& u, const Point& w, int axis) {
  const double ac = axis == 0 ? a.x : a.y, bc = axis == 0 ? b.x : b.y;
  // Doubles mapped to integers in their order (-0 and +0 to the same place).
  auto to_int = [](double x) {
    std::int64_t i = 0;
    std::memcpy(&i, &x, sizeof i);
    return i < 0 ? -(i & 0x7fffffffffffffff) : i;
  };
  auto to_double = [](std::int64_t i) {
    const std::int64_t bits = i < 0 ? (-i) | std::int64_t(0x8000000000000000ull) : i;
    double x = 0;
    std::memcpy(&x, &bits, sizeof x);
    return x;
  };
  std::int64_t lo = to_int(std::min(ac, bc)), hi = to_int(std::max(ac, bc));  // v in [lo, hi]
  while (static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo) > 1) {
    const auto mid = static_cast<std::int64_t>(static_cast<std::uint64_t>(lo) +
                                               (static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo)) /
                                                   2);  // no overflow across zero
    const double m = to_double(mid);
    const int s = compare_crossing(a, b, u, w, axis, m, m);
    if (s == 0) return m;
    (s > 0 ? lo : hi) = mid;
  }
  const double low = to_double(lo), high = to_double(hi);
  if (compare_crossing(a, b, u, w, axis, low, low) == 0) return low;
  const int s = compare_crossing(a, b, u, w, axis, low, high);
  if (s != 0) return s < 0 ? low : high;
  return (lo & 1) == 0 ? low : high;  // a tie: the even significand
}

}  // namespace

Point crossing_rounded(const Point& a, const Point& b, const Point& u, const Point& w) {
  return {crossing_coordinate(a, b, u, w, 0), crossing_coordinate(a, b, u, w, 1)};
}

int incircle_hard(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double m = std::max({std::fabs(a.x - d.x), std::fabs(a.y - d.y), std::fabs(b.x - d.x), std::fabs(b.y - d.y),
                             std::fabs(c.x - d.x), std::fabs(c.y - d.y)});
  if (exact_in_double({a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y}, m, 0x1p12)) {
    const double det = incircle_determinant(a, b, c, d);  // every step an exact integer
    return (det > 0) - (det < 0);
  }
  // Degree 4: within 2^+-200.
  Point s[4] = {a, b, c, d};
  if (rescale(s, 0x1p-200, 0x1p200))
    if (const int sign = incircle_filter(s[0], s[1], s[2], s[3]); sign != 0) return sign;
  return incircle_exact(a, b, c, d);
}

// det[a - d; b - d; c - d] in integers of the unit 2^(3 e), e the least unit in the last place.
// Degree 3: 2098-bit integers make products of some 6300 bits, within BigInt's room.
BigInt orient3d_big(const Point3& a, const Point3& b, const Point3& c, const Point3& d, int& e) {
  e = min_ulp_exponent({a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z});
  auto big = [&](double v) { return BigInt::from_double(v, e); };
  const BigInt dx = big(d.x), dy = big(d.y), dz = big(d.z);
  const BigInt adx = big(a.x) - dx, ady = big(a.y) - dy, adz = big(a.z) - dz;
  const BigInt bdx = big(b.x) - dx, bdy = big(b.y) - dy, bdz = big(b.z) - dz;
  const BigInt cdx = big(c.x) - dx, cdy = big(c.y) - dy, cdz = big(c.z) - dz;
  return adz * (bdx * cdy - bdy * cdx) + bdz * (cdx * ady - cdy * adx) + cdz * (adx * bdy - ady * bdx);
}

int orient3d_exact(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  int e = 0;
  return orient3d_big(a, b, c, d, e).sign();
}

double orient3d_value_exact(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  int e = 0, exponent = 0;
  const double m = orient3d_big(a, b, c, d, e).scaled(3 * e, exponent);
  return std::ldexp(m, exponent);
}

int orient3d_tie(const Point3* const p[4], const std::uint32_t rank[4]) {
  // The perturbed determinant of rows (x, y, z, 1) is a polynomial in eps; the coefficient of
  // the product of the moves of entries S (at most one a row and a column) is the determinant
  // with S's rows replaced by unit rows, and its exponent is the sum of S's 2^(3r + j), so
  // the sets in the order of those sums as binary numbers come in the order of their terms.
  static const std::vector<std::uint16_t> sets = [] {
    std::vector<std::uint16_t> out;
    for (unsigned m = 1; m < 4096; ++m) {
      unsigned ranks = 0, columns = 0;
      bool ok = true;
      for (unsigned bit = 0; bit < 12 && ok; ++bit)
        if (m >> bit & 1) {
          ok = !(ranks >> (bit / 3) & 1) && !(columns >> (bit % 3) & 1);
          ranks |= 1u << (bit / 3), columns |= 1u << (bit % 3);
        }
      if (ok) out.push_back(static_cast<std::uint16_t>(m));
    }
    return out;
  }();
  int row_of_rank[4];
  for (int i = 0; i < 4; ++i) {
    int r = 0;
    for (int k = 0; k < 4; ++k) r += rank[k] < rank[i];
    row_of_rank[r] = i;
  }
  auto coordinate = [&](int row, int j) { return j == 0 ? p[row]->x : j == 1 ? p[row]->y : p[row]->z; };
  for (const std::uint16_t m : sets) {
    int column_of_row[4] = {-1, -1, -1, -1};
    bool used[4] = {false, false, false, true};  // the column of ones is never replaced
    for (unsigned bit = 0; bit < 12; ++bit)
      if (m >> bit & 1) column_of_row[row_of_rank[bit / 3]] = static_cast<int>(bit % 3), used[bit % 3] = true;
    int rows[4], columns[4], k = 0, c = 0;
    for (int i = 0; i < 4; ++i)
      if (column_of_row[i] < 0) rows[k++] = i;
    for (int j = 0; j < 4; ++j)
      if (!used[j] || j == 3) columns[c++] = j;
    // The minor of the rows left and the columns left (the column of ones last).
    int minor = 1;
    if (k == 3) {
      auto at = [&](int row) { return Point{coordinate(row, columns[0]), coordinate(row, columns[1])}; };
      minor = orient2d(at(rows[0]), at(rows[1]), at(rows[2]));
    } else if (k == 2) {
      const double u = coordinate(rows[0], columns[0]), w = coordinate(rows[1], columns[0]);
      minor = (u > w) - (u < w);
    }
    if (minor == 0) continue;
    // The sign of the permutation taking the rows left to the columns left in order, and each
    // replaced row to its column: the determinant is that sign times the minor.
    int sigma[4];
    for (int i = 0, left = 0; i < 4; ++i) sigma[i] = column_of_row[i] >= 0 ? column_of_row[i] : columns[left++];
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += sigma[i] > sigma[j];
    return inversions % 2 == 0 ? minor : -minor;
  }
  return 0;  // unreachable: three replaced rows leave the column of ones, whose minor is 1
}

int incircle_sos_hard(const Point& a, const Point& b, const Point& c, const Point& d) {
  const int s = incircle_hard(a, b, c, d);
  return s != 0 ? s : incircle_tie(a, b, c, d);
}

bool on_small_lattice(const Point* points, std::uint32_t n) {
  if (n == 0) return false;
  double x0 = points[0].x, x1 = x0, y0 = points[0].y, y1 = y0;
  for (std::uint32_t i = 0; i < n; ++i) {
    const Point& p = points[i];
    if (!small_integer(p.x) || !small_integer(p.y)) return false;
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    if (x1 - x0 > 0x1p12 || y1 - y0 > 0x1p12) return false;
  }
  return true;
}

int incircle_tie(const Point& a, const Point& b, const Point& c, const Point& d) {
  // Cofactors of the lifted coordinate in rows a, b, c, d of det[x y z 1].
  struct Row {
    const Point* p;
    int which;
  };
  Row rows[4] = {{&a, 0}, {&b, 1}, {&c, 2}, {&d, 3}};
  auto cofactor = [&](int which) {
    switch (which) {
      case 0:
        return orient2d(b, c, d);
      case 1:
        return -orient2d(a, c, d);
      case 2:
        return orient2d(a, b, d);
      default:
        return -orient2d(a, b, c);
    }
  };
  // The largest point's cofactor is 0 only when the other three are collinear, so it nearly
  // always decides alone (a grid's cocircular squares come here at every other test): the
  // full order only when it does not.
  int largest = 0;
  for (int i = 1; i < 4; ++i)
    if (lex_less(*rows[largest].p, *rows[i].p)) largest = i;
  if (const int first = cofactor(largest); first != 0) return first;
  std::sort(rows, rows + 4, [](const Row& l, const Row& r) { return lex_less(*r.p, *l.p); });
  for (const Row& row : rows)
    if (const int f = cofactor(row.which); f != 0) return f;
  return 0;  // only for a degenerate (a, b, c), which callers never pass
}

}  // namespace ridt::detail

namespace ridt {

int orientation(const Point& a, const Point& b, const Point& c) { return detail::orient2d(a, b, c); }

int in_circle(const Point& a, const Point& b, const Point& c, const Point& d) { return detail::incircle(a, b, c, d); }

int orientation(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  return detail::orient3d(a, b, c, d);
}

}  // namespace ridt
