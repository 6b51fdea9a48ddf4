// Prints the kernel's decisions for predicates that involve the symbolic bounding vertices,
// for all small integer points; symbolic_rules.py checks each line against a concrete
// far-away placement of the bounding vertices evaluated with exact integers.
#include <cstdio>
#include <vector>

#include "kernel.hpp"

using ridt::Point;
using ridt::VertexId;

int main() {
  std::vector<Point> pts;
  for (int x = -2; x <= 2; ++x)
    for (int y = -2; y <= 2; ++y) pts.push_back({double(x), double(y)});
  const auto n = static_cast<VertexId>(pts.size());
  auto buffer = ridt::detail::allocate_huge<Point>(n + 3);
  for (VertexId v = 0; v < n; ++v) buffer[v] = pts[v];
  const ridt::detail::Kernel k(std::move(buffer), n, /*symbolic=*/true);
  auto at = [&](VertexId v) { return pts[v]; };
  for (VertexId p = 0; p < n; ++p)
    for (VertexId q = 0; q < n; ++q) {
      if (p == q) continue;
      for (VertexId b = n; b < n + 3; ++b) {
        // orient with one bounding vertex, in each of its three positions
        std::printf("O %g %g %g %g B%u %d %d %d\n", at(p).x, at(p).y, at(q).x, at(q).y, b - n,
                    k.orient(p, q, b), k.orient(q, b, p), k.orient(b, p, q));
        // incircle of the triangle (p, q, b) made counter-clockwise, against every other point
        const bool ccw = k.orient(p, q, b) > 0;
        const VertexId a = ccw ? p : q, c = ccw ? q : p;
        for (VertexId d = 0; d < n; ++d)
          if (d != p && d != q)
            std::printf("C1 %g %g %g %g B%u %g %g %d %d\n", at(a).x, at(a).y, at(c).x, at(c).y,
                        b - n, at(d).x, at(d).y, k.incircle(a, c, b, d), k.incircle(b, a, c, d));
      }
    }
  for (VertexId a = 0; a < n; ++a)
    for (VertexId i = 0; i < 3; ++i) {
      const VertexId bi = n + i, bj = n + (i + 1) % 3;
      std::printf("O2 %g %g B%u B%u %d %d\n", at(a).x, at(a).y, i, (i + 1) % 3,
                  k.orient(a, bi, bj), k.orient(a, bj, bi));
      for (VertexId d = 0; d < n; ++d)
        if (d != a)
          std::printf("C2 %g %g B%u B%u %g %g %d %d\n", at(a).x, at(a).y, i, (i + 1) % 3,
                      at(d).x, at(d).y, k.incircle(a, bi, bj, d), k.incircle(bj, a, bi, d));
    }
  std::printf("O3 %d %d\n", k.orient(n, n + 1, n + 2), k.orient(n, n + 2, n + 1));
  return 0;
}
