// generate_coastline (ridt/generate.hpp): star-shaped polygons whose radius is a periodic
// fractal, made with +, -, *, / and sqrt only, so that every machine gets the same bits.
#include <algorithm>
#include <cmath>
#include <string>

#include "order/random.hpp"
#include "ridt/generate.hpp"

namespace ridt {
namespace {

// m values of a periodic fractal in [-1, 1]: midpoint displacement on a ring of 2^k >= m
// values, each octave's displacement 0.6 of the one before, sampled at m even steps.
std::vector<double> fractal(std::uint32_t m, detail::Rng& rng) {
  std::uint32_t size = 4;
  while (size < m) size *= 2;
  std::vector<double> h(size, 0.0);
  double amplitude = 1;
  for (std::uint32_t step = size; step > 1; step /= 2, amplitude *= 0.6)
    for (std::uint32_t i = 0; i < size; i += step)
      h[i + step / 2] = (h[i] + h[(i + step) % size]) / 2 + amplitude * (2 * rng.uniform() - 1);
  double top = 0;
  for (const double v : h) top = std::max(top, std::fabs(v));
  std::vector<double> out(m);
  for (std::uint32_t k = 0; k < m; ++k) out[k] = h[std::uint64_t{k} * size / m] / (top > 0 ? top : 1);
  return out;
}

// The unit direction at perimeter parameter s in [0, 8) of the square [-1, 1]^2, counter-
// clockwise from (1, -1): the angle grows strictly with s, so radii > 0 give a simple polygon.
Point direction(double s) {
  Point p;
  if (s < 2)
    p = {1, s - 1};
  else if (s < 4)
    p = {3 - s, 1};
  else if (s < 6)
    p = {-1, 5 - s};
  else
    p = {s - 7, -1};
  const double r = std::sqrt(p.x * p.x + p.y * p.y);
  return {p.x / r, p.y / r};
}

// A closed polygon of m vertices about `centre`, radius `radius` (1 + 0.3 fractal), appended.
void add_polygon(Pslg& g, Point centre, double radius, std::uint32_t m, detail::Rng& rng) {
  const std::vector<double> h = fractal(m, rng);
  const auto first = static_cast<VertexId>(g.points.size());
  for (std::uint32_t k = 0; k < m; ++k) {
    const Point d = direction(8.0 * k / m);
    const double r = radius * (1 + 0.3 * h[k]);
    g.points.push_back({centre.x + r * d.x, centre.y + r * d.y});
    g.segments.push_back(first + k);
    g.segments.push_back(first + (k + 1) % m);
  }
}

}  // namespace

Pslg generate_coastline(std::uint32_t n, std::uint32_t lakes, std::uint64_t seed) {
  if (n < 3 + 8ull * lakes)
    throw InputError("a coastline of " + std::to_string(lakes) + " lakes needs at least " +
                     std::to_string(3 + 8ull * lakes) + " vertices (got " + std::to_string(n) + ")");
  detail::Rng rng(seed, /*stream=*/3);
  Pslg g;
  const std::uint32_t in_lakes = lakes == 0 ? 0 : std::max(n / 2, 8 * lakes);
  add_polygon(g, {0, 0}, 1, n - in_lakes, rng);
  std::uint32_t side = 1;
  while (side * side < lakes) ++side;
  const double cell = 0.9 / side;  // the lakes' grid covers [-0.45, 0.45]^2, inside radius 0.65
  for (std::uint32_t k = 0; k < lakes; ++k) {
    const Point c{-0.45 + cell * (k % side + 0.5), -0.45 + cell * (k / side + 0.5)};
    const std::uint32_t m = in_lakes / lakes + (k < in_lakes % lakes ? 1 : 0);
    add_polygon(g, c, 0.3 * cell, m, rng);  // at most 0.39 cell from its centre
    g.holes.push_back(c);
  }
  return g;
}

}  // namespace ridt
