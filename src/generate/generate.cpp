#include "ridt/generate.hpp"

#include <cmath>

#include "order/random.hpp"

namespace ridt {
namespace {

// Natural logarithm from basic operations only, so that every machine gets the same bits
// (libm's log may differ in the last place). x = m 2^e with m in [sqrt(1/2), sqrt(2));
// log m = 2 atanh(z), z = (m - 1) / (m + 1), |z| < 0.172, and 14 terms of the series
// z + z^3/3 + ... leave an error far below one unit in the last place.
double portable_log(double x) {
  int e = 0;
  double m = std::frexp(x, &e);
  if (m < 0.70710678118654752440) m *= 2, e -= 1;
  const double z = (m - 1) / (m + 1), z2 = z * z;
  double sum = 0;
  for (int k = 27; k >= 1; k -= 2) sum = sum * z2 + 1.0 / k;
  return 2 * z * sum + e * 0.69314718055994530942;
}

// Marsaglia's polar method: a pair of independent standard normals.
Point normal_pair(detail::Rng& rng) {
  for (;;) {
    const double u = 2 * rng.uniform() - 1, v = 2 * rng.uniform() - 1;
    const double s = u * u + v * v;
    if (s >= 1 || s == 0) continue;
    const double f = std::sqrt(-2 * portable_log(s) / s);
    return {u * f, v * f};
  }
}

}  // namespace

std::vector<Point> generate(Distribution d, std::uint32_t n, std::uint64_t seed) {
  std::vector<Point> pts(n);
  detail::Rng rng(seed, /*stream=*/2);
  switch (d) {
    case Distribution::Uniform:
      for (Point& p : pts) p.x = rng.uniform(), p.y = rng.uniform();
      break;
    case Distribution::Normal:
      for (Point& p : pts) p = normal_pair(rng);
      break;
    case Distribution::Grid: {
      auto side = static_cast<std::uint32_t>(std::sqrt(static_cast<double>(n)));
      while (std::uint64_t{side} * side < n) ++side;
      for (std::uint32_t i = 0; i < n; ++i) pts[i] = {double(i % side), double(i / side)};
      break;
    }
    case Distribution::Clusters: {
      constexpr int kClusters = 10;
      constexpr double kSpread = 0.01;
      Point centre[kClusters];
      for (Point& c : centre) c.x = rng.uniform(), c.y = rng.uniform();
      for (Point& p : pts) {
        const Point& c = centre[rng.below(kClusters)];
        const Point off = normal_pair(rng);
        p = {c.x + kSpread * off.x, c.y + kSpread * off.y};
      }
      break;
    }
  }
  return pts;
}

}  // namespace ridt
