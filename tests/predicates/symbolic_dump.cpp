// Prints the kernel's decisions for predicates that involve the symbolic bounding vertices,
// for all small integer points; symbolic_rules.py checks each line against a concrete
// far-away placement of the bounding vertices evaluated with exact integers. Each decision is
// also asked of the walking kernel's forms (the point passed, the bounding vertices' points
// NaN), on these lattice points and on the same points moved off the lattice by 1/2, which
// changes no sign; it aborts where any form disagrees.
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "dag/kernel.hpp"

using ridt::Point;
using ridt::VertexId;

int main() {
  std::vector<Point> pts;
  for (int x = -2; x <= 2; ++x)
    for (int y = -2; y <= 2; ++y) pts.push_back({double(x), double(y)});
  const auto n = static_cast<VertexId>(pts.size());
  using ridt::detail::Vertices;
  auto buffer = ridt::detail::allocate_huge<Point>(n + 3);
  std::vector<Point> moved(n + 3, Vertices::kBoundingNaN);
  for (VertexId v = 0; v < n; ++v) buffer[v] = pts[v], moved[v] = {pts[v].x + 0.5, pts[v].y + 0.5};
  for (VertexId v = n; v < n + 3; ++v) buffer[v] = Vertices::kBoundingNaN;
  const ridt::detail::Kernel kernel(std::move(buffer), n, /*symbolic=*/true);
  const Vertices lattice(&kernel.point(0), n, true), general(moved.data(), n, true);
  if (!lattice.lattice() || general.lattice()) {
    std::fprintf(stderr, "the test's point sets are not what they should be\n");
    return 1;
  }
  auto agree = [](bool same, const char* what, VertexId a, VertexId b, VertexId c, VertexId d) {
    if (same) return;
    std::fprintf(stderr, "%s(%u, %u, %u, %u): the walking kernel's forms disagree\n", what, a, b, c, d);
    std::abort();
  };
  // The kernel's decision, and the same from every form that can take it (c finite).
  struct {
    const ridt::detail::Kernel& kernel;
    const Vertices &lattice, &general;
    decltype(agree) check;
    int orient(VertexId a, VertexId b, VertexId c) const {
      const int s = kernel.orient(a, b, c);
      check(general.orient(a, b, c) == s, "orient", a, b, c, 0);
      if (c < lattice.n())
        check(lattice.orient<true>(a, b, c, lattice[c]) == s && lattice.orient<false>(a, b, c, lattice[c]) == s &&
                  general.orient<false>(a, b, c, general[c]) == s,
              "orient", a, b, c, 0);
      return s;
    }
    int incircle(VertexId a, VertexId b, VertexId c, VertexId d) const {
      const int s = kernel.incircle(a, b, c, d);
      check(general.incircle(a, b, c, d) == s && lattice.incircle<true>(a, b, c, d, lattice[d]) == s &&
                lattice.incircle<false>(a, b, c, d, lattice[d]) == s &&
                general.incircle<false>(a, b, c, d, general[d]) == s,
            "incircle", a, b, c, d);
      return s;
    }
  } k{kernel, lattice, general, agree};
  auto at = [&](VertexId v) { return pts[v]; };
  for (VertexId p = 0; p < n; ++p)
    for (VertexId q = 0; q < n; ++q) {
      if (p == q) continue;
      for (VertexId b = n; b < n + 3; ++b) {
        // orient with one bounding vertex, in each of its three positions
        std::printf("O %g %g %g %g B%u %d %d %d\n", at(p).x, at(p).y, at(q).x, at(q).y, b - n, k.orient(p, q, b),
                    k.orient(q, b, p), k.orient(b, p, q));
        // incircle of the triangle (p, q, b) made counter-clockwise, against every other point
        const bool ccw = k.orient(p, q, b) > 0;
        const VertexId a = ccw ? p : q, c = ccw ? q : p;
        for (VertexId d = 0; d < n; ++d)
          if (d != p && d != q)
            std::printf("C1 %g %g %g %g B%u %g %g %d %d\n", at(a).x, at(a).y, at(c).x, at(c).y, b - n, at(d).x, at(d).y,
                        k.incircle(a, c, b, d), k.incircle(b, a, c, d));
      }
    }
  for (VertexId a = 0; a < n; ++a)
    for (VertexId i = 0; i < 3; ++i) {
      const VertexId bi = n + i, bj = n + (i + 1) % 3;
      std::printf("O2 %g %g B%u B%u %d %d\n", at(a).x, at(a).y, i, (i + 1) % 3, k.orient(a, bi, bj),
                  k.orient(a, bj, bi));
      for (VertexId d = 0; d < n; ++d)
        if (d != a)
          std::printf("C2 %g %g B%u B%u %g %g %d %d\n", at(a).x, at(a).y, i, (i + 1) % 3, at(d).x, at(d).y,
                      k.incircle(a, bi, bj, d), k.incircle(bj, a, bi, d));
    }
  std::printf("O3 %d %d\n", k.orient(n, n + 1, n + 2), k.orient(n, n + 2, n + 1));
  return 0;
}
