// The shifted predicates' filters and exact forms (predicates/shifted.hpp).
//
// The filter: each moved coordinate is rounded twice (the shift's product, then the sum), so it
// lies within delta = kEps (|shift| + |moved|) of the truth, plus what an underflow loses. The
// determinants are then evaluated on the rounded points, and their value moves by at most the
// sum over the coordinate differences of (the derivative's bound) x (each difference's error:
// 2 delta from the points, kEps of itself from its subtraction), with room for the terms of
// second order, plus the evaluation's own rounding. Differences (D below) are kept between
// 2^-240 and 2^240, so that no power of them up to the fourth overflows or underflows into
// the bound; anything else, and any value within its bound, goes to the exact integers.
#include "predicates/shifted.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "predicates/bigint.hpp"

namespace ridt::detail {

using exact::BigInt;

namespace {

constexpr double kLost = 0x1p-1068;  // what an underflowing step may lose, with room

// A moved point rounded, and the bound on each coordinate's error.
struct Near {
  double x, y, err;
};

Near near(const Shifted& s, const Periods& l) {
  const double sx = s.dx * l.width, sy = s.dy * l.height;
  const double x = s.p.x + sx, y = s.p.y + sy;
  const double err = 1.01 * kEps * (std::max(std::fabs(sx) + std::fabs(x), std::fabs(sy) + std::fabs(y))) + kLost;
  return {x, y, err};
}

// Whether D (the largest difference, errors included) keeps every power up to the fourth and
// every bound normal and finite.
bool in_range(double d) { return d >= 0x1p-240 && d <= 0x1p240; }

// k * w, exactly, by doubling.
BigInt times(std::int32_t k, const BigInt& w) {
  BigInt r, m = w;
  for (auto u = static_cast<std::uint32_t>(std::abs(static_cast<std::int64_t>(k))); u != 0; u >>= 1) {
    if (u & 1) r = r + m;
    m = m + m;
  }
  return k < 0 ? BigInt() - r : r;
}

struct BigPoint {
  BigInt x, y;
};

// The exact moved points of up to four shifted points, in units of 2^e where e is the least
// unit in the last place of their coordinates and the periods.
class Exact {
 public:
  Exact(std::initializer_list<const Shifted*> s, const Periods& l) {
    e_ = exact::min_ulp_exponent({l.width, l.height});
    for (const Shifted* p : s) e_ = std::min(e_, exact::min_ulp_exponent({p->p.x, p->p.y}));
    w_ = BigInt::from_double(l.width, e_), h_ = BigInt::from_double(l.height, e_);
  }
  BigPoint operator()(const Shifted& s) const {
    return {BigInt::from_double(s.p.x, e_) + times(s.dx, w_), BigInt::from_double(s.p.y, e_) + times(s.dy, h_)};
  }

 private:
  int e_ = 0;
  BigInt w_, h_;
};

int orient_big(const BigPoint& a, const BigPoint& b, const BigPoint& c) {
  return ((a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x)).sign();
}

bool lex_less_big(const BigPoint& a, const BigPoint& b) {
  const int s = (a.x - b.x).sign();
  return s != 0 ? s < 0 : (a.y - b.y).sign() < 0;
}

int incircle_big(const BigPoint& a, const BigPoint& b, const BigPoint& c, const BigPoint& d) {
  const BigInt adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y, cdx = c.x - d.x, cdy = c.y - d.y;
  return ((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
          (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady))
      .sign();
}

// incircle_tie's rule on exact points: the cofactor of the lift of the greatest point (in
// lexicographic order) whose cofactor is not 0.
int incircle_tie_big(const BigPoint& a, const BigPoint& b, const BigPoint& c, const BigPoint& d) {
  const BigPoint* p[4] = {&a, &b, &c, &d};
  int order[4] = {0, 1, 2, 3};
  std::sort(order, order + 4, [&](int i, int j) { return lex_less_big(*p[j], *p[i]); });
  for (const int i : order) {
    const int f = i == 0 ? orient_big(b, c, d)
        : i == 1         ? -orient_big(a, c, d)
        : i == 2         ? orient_big(a, b, d)
                         : -orient_big(a, b, c);
    if (f != 0) return f;
  }
  return 0;  // only for a degenerate (a, b, c), which callers never pass
}

}  // namespace

int orient_shifted_mixed(const Shifted& a, const Shifted& b, const Shifted& c, const Periods& l) {
  const Near na = near(a, l), nb = near(b, l), nc = near(c, l);
  const double delta = std::max({na.err, nb.err, nc.err});
  const double adx = na.x - nc.x, ady = na.y - nc.y, bdx = nb.x - nc.x, bdy = nb.y - nc.y;
  const double d = std::max({std::fabs(adx), std::fabs(ady), std::fabs(bdx), std::fabs(bdy)}) + 2 * delta;
  const double det = adx * bdy - ady * bdx;
  const double bound = 9 * d * delta + 16 * kEps * d * d + 16 * delta * delta;
  if (in_range(d) && std::isfinite(det) && std::fabs(det) > bound) return det > 0 ? 1 : -1;
  const Exact big({&a, &b, &c}, l);
  return orient_big(big(a), big(b), big(c));
}

int incircle_shifted_mixed(const Shifted& a, const Shifted& b, const Shifted& c, const Shifted& d, const Periods& l) {
  const Near na = near(a, l), nb = near(b, l), nc = near(c, l), nd = near(d, l);
  const double delta = std::max({na.err, nb.err, nc.err, nd.err});
  const double adx = na.x - nd.x, ady = na.y - nd.y, bdx = nb.x - nd.x, bdy = nb.y - nd.y;
  const double cdx = nc.x - nd.x, cdy = nc.y - nd.y;
  const double D =
      std::max({std::fabs(adx), std::fabs(ady), std::fabs(bdx), std::fabs(bdy), std::fabs(cdx), std::fabs(cdy)}) +
      2 * delta;
  const double det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
      (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
  // Each difference's error eta: from the points and from its own subtraction.
  const double eta = 2 * delta + kEps * D;
  const double bound = 128 * D * D * D * delta + 320 * kEps * D * D * D * D + 512 * D * D * eta * eta;
  if (in_range(D) && std::isfinite(det) && std::fabs(det) > bound) return det > 0 ? 1 : -1;
  const Exact big({&a, &b, &c, &d}, l);
  const BigPoint ea = big(a), eb = big(b), ec = big(c), ed = big(d);
  const int s = incircle_big(ea, eb, ec, ed);
  return s != 0 ? s : incircle_tie_big(ea, eb, ec, ed);
}

bool lex_less_shifted_mixed(const Shifted& a, const Shifted& b, const Periods& l) {
  const Near na = near(a, l), nb = near(b, l);
  const double room = na.err + nb.err;
  if (na.x - nb.x < -2 * room) return true;
  if (na.x - nb.x > 2 * room) return false;
  const Exact big({&a, &b}, l);
  return lex_less_big(big(a), big(b));
}

}  // namespace ridt::detail
