#include "order.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "random.hpp"

namespace ridt::detail {

std::vector<std::uint32_t> random_permutation(std::uint32_t n, std::uint64_t seed) {
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  Rng rng(seed, /*stream=*/1);
  for (std::uint32_t i = n; i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
  return order;
}

std::uint32_t hilbert_key(std::uint32_t x, std::uint32_t y) {
  // From the coarsest level down: the quadrant of (x, y) gives two bits of the key; then the
  // coordinates are mapped into that quadrant's frame (a reflection and a swap), so that the
  // curve inside each quadrant is again the standard one.
  std::uint32_t key = 0;
  for (std::uint32_t half = 1u << 15; half != 0; half >>= 1) {
    const std::uint32_t right = (x & half) ? 1 : 0, up = (y & half) ? 1 : 0;
    key += half * half * ((3 * right) ^ up);  // quadrants in curve order: 0 (0,0), 1 (0,1), 2 (1,1), 3 (1,0)
    if (up == 0) {
      if (right == 1) {  // lower right: reflect across the anti-diagonal
        x = ~x & 0xffffu;
        y = ~y & 0xffffu;
      }
      std::swap(x, y);  // lower quadrants: transpose
    }
  }
  return key;
}

std::vector<std::uint32_t> hilbert_order(const Point* points, std::uint32_t n) {
  std::vector<std::uint32_t> order(n);
  if (n == 0) return order;
  double x0 = points[0].x, x1 = x0, y0 = points[0].y, y1 = y0;
  for (std::uint32_t i = 1; i < n; ++i) {
    x0 = std::min(x0, points[i].x), x1 = std::max(x1, points[i].x);
    y0 = std::min(y0, points[i].y), y1 = std::max(y1, points[i].y);
  }
  // One scale for both axes keeps the curve's cells square. Halving first keeps x1 - x0
  // finite for coordinates near the largest double.
  const double extent = std::max(x1 / 2 - x0 / 2, y1 / 2 - y0 / 2);
  const double scale = extent > 0 ? 32767.0 / extent : 0.0;  // 65535 / (2 * extent)
  std::vector<std::uint32_t> key(n), key2(n), order2(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const auto cell = [&](double v, double lo) {
      return static_cast<std::uint32_t>(std::clamp((v / 2 - lo / 2) * scale, 0.0, 65535.0));
    };
    key[i] = hilbert_key(cell(points[i].x, x0), cell(points[i].y, y0));
    order[i] = i;
  }
  // Least significant digit first, 11 bits a pass: three stable counting passes.
  constexpr int kBits = 11;
  std::vector<std::uint32_t> count(std::size_t{1} << kBits);
  for (int shift = 0; shift < 32; shift += kBits) {
    std::fill(count.begin(), count.end(), 0u);
    for (std::uint32_t i = 0; i < n; ++i) ++count[(key[i] >> shift) & ((1u << kBits) - 1)];
    std::uint32_t sum = 0;
    for (std::uint32_t& c : count) sum += std::exchange(c, sum);
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t at = count[(key[i] >> shift) & ((1u << kBits) - 1)]++;
      key2[at] = key[i];
      order2[at] = order[i];
    }
    key.swap(key2);
    order.swap(order2);
  }
  return order;
}

}  // namespace ridt::detail
