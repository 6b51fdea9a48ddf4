// The power test's exact evaluation and its perturbation, and the power centre computed
// exactly (predicates/power.hpp), in the integers of predicates/bigint.hpp.
#include <algorithm>
#include <cmath>
#include <limits>

#include "predicates/bigint.hpp"
#include "predicates/power.hpp"
#include "predicates/predicates.hpp"

namespace ridt::detail {

using exact::BigInt;
using exact::min_ulp_exponent;
using exact::ulp_exponent;

namespace {

// The unit of a power test's integers: coordinates in units of 2^e, weights (of degree 2) in
// units of 2^(2 e), e the least unit in the last place of a coordinate and half a weight's.
int power_unit(std::initializer_list<const Weighted*> points) {
  int e = 1 << 20;
  for (const Weighted* p : points) {
    e = std::min(e, min_ulp_exponent({p->p.x, p->p.y}));
    if (p->w != 0) e = std::min(e, static_cast<int>(std::floor(ulp_exponent(p->w) / 2.0)));
  }
  return e;
}

}  // namespace

int power_exact(const Weighted& a, const Weighted& b, const Weighted& c, const Weighted& d) {
  const int e = power_unit({&a, &b, &c, &d});
  auto big = [e](double v) { return BigInt::from_double(v, e); };
  auto weight = [e](double w) { return BigInt::from_double(w, 2 * e); };
  const BigInt dx = big(d.p.x), dy = big(d.p.y), dw = weight(d.w);
  const BigInt adx = big(a.p.x) - dx, ady = big(a.p.y) - dy, bdx = big(b.p.x) - dx, bdy = big(b.p.y) - dy;
  const BigInt cdx = big(c.p.x) - dx, cdy = big(c.p.y) - dy;
  const BigInt alift = adx * adx + ady * ady - (weight(a.w) - dw);
  const BigInt blift = bdx * bdx + bdy * bdy - (weight(b.w) - dw);
  const BigInt clift = cdx * cdx + cdy * cdy - (weight(c.w) - dw);
  return (alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady)).sign();
}

int power_tie(const Weighted& a, const Weighted& b, const Weighted& c, const Weighted& d) {
  // The cofactors of the lift in rows a, b, c, d (incircle_tie's), the greatest point first.
  const Weighted* p[4] = {&a, &b, &c, &d};
  int order[4] = {0, 1, 2, 3};
  std::sort(order, order + 4, [&](int i, int j) { return weighted_less(*p[j], *p[i]); });
  for (const int i : order) {
    const int f = i == 0 ? orient2d(b.p, c.p, d.p)
        : i == 1         ? -orient2d(a.p, c.p, d.p)
        : i == 2         ? orient2d(a.p, b.p, d.p)
                         : -orient2d(a.p, b.p, c.p);
    if (f != 0) return f;
  }
  return 0;  // only for a degenerate (a, b, c), which callers never pass
}

Point power_centre_exact(const Weighted& a, const Weighted& b, const Weighted& c) {
  const int e = power_unit({&a, &b, &c});
  auto big = [e](double v) { return BigInt::from_double(v, e); };
  auto weight = [e](double w) { return BigInt::from_double(w, 2 * e); };
  const BigInt ax = big(a.p.x), ay = big(a.p.y), aw = weight(a.w);
  const BigInt bx = big(b.p.x) - ax, by = big(b.p.y) - ay, cx = big(c.p.x) - ax, cy = big(c.p.y) - ay;
  const BigInt b2 = bx * bx + by * by - (weight(b.w) - aw), c2 = cx * cx + cy * cy - (weight(c.w) - aw);
  const BigInt half = bx * cy - by * cx, d = half + half;
  // Each coordinate (a d + n) / d, in units of 2^e: the quotient of the two rounded.
  int de = 0;
  const double dm = d.scaled(0, de);
  if (dm == 0) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  auto quotient = [&](const BigInt& n) {
    int ne = 0;
    const double nm = n.scaled(0, ne);
    return nm == 0 ? 0.0 : std::ldexp(nm / dm, ne - de + e);
  };
  return {quotient(ax * d + cy * b2 - by * c2), quotient(ay * d + bx * c2 - cx * b2)};
}

}  // namespace ridt::detail
