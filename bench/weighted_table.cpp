// The regular (weighted Delaunay) triangulation beside CGAL's Regular_triangulation_2 and
// beside ridt's own unweighted triangulation of the same points (the floor), in one run: the
// kernels in process, interleaved, each figure the median of --reps. Weights are uniform in
// [0, scale / n): `light` (scale 1, few points hidden) and `heavy` (scale 40, some 84 % hidden).
//
//   ridt_bench_weighted [--sizes 100000,1000000] [--reps 5] [--threads 2] [--csv FILE]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "common.hpp"
#include "ridt/regular.hpp"
#include "ridt/ridt.hpp"

#ifdef RIDT_WITH_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_2.h>
#endif

namespace {

using ridt::bench::seconds;

#ifdef RIDT_WITH_CGAL
double cgal(const std::vector<ridt::Point>& pts, const std::vector<double>& w, std::size_t& faces) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Rt = CGAL::Regular_triangulation_2<K>;
  return seconds([&] {
    std::vector<Rt::Weighted_point> in;
    in.reserve(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) in.emplace_back(K::Point_2(pts[i].x, pts[i].y), w[i]);
    Rt rt(in.begin(), in.end());
    faces = rt.number_of_faces();
  });
}
#endif

// One size and weight scale: the medians of `reps` interleaved runs of each code, as a CSV line;
// empty where CGAL's triangle count differs from ridt's.
std::string row(std::size_t n, double scale, int reps, unsigned threads) {
  std::mt19937_64 random(n);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<ridt::Point> pts(n);
  std::vector<double> w(n);
  for (std::size_t i = 0; i < n; ++i) pts[i] = {u(random), u(random)}, w[i] = u(random) * scale / double(n);
  std::vector<double> r1, rt, c, d1, dt;
  std::size_t hidden = 0, ours = 0, theirs = 0;
  for (int rep = 0; rep < reps; ++rep) {
    r1.push_back(seconds([&] {
      const ridt::RegularTriangulation t = ridt::triangulate_regular(pts, w, 1);
      hidden = t.hidden.size(), ours = t.size();
    }));
    rt.push_back(seconds([&] { ridt::triangulate_regular(pts, w, threads); }));
#ifdef RIDT_WITH_CGAL
    c.push_back(cgal(pts, w, theirs));
#endif
    ridt::Options o;
    o.threads = 1;
    d1.push_back(seconds([&] { ridt::triangulate(pts, o); }));
    o.method = ridt::Method::Auto;  // (the partition method: the plane's fastest on several threads)
    o.threads = threads;
    dt.push_back(seconds([&] { ridt::triangulate(pts, o); }));
  }
  if (theirs != 0 && theirs != ours) {
    std::fprintf(stderr, "CGAL has %zu triangles, ridt %zu\n", theirs, ours);
    return {};
  }
  using ridt::bench::median;
  const double cm = median(c);
  char buf[512];
  std::snprintf(buf, sizeof buf, "%zu,%s,%zu,%.4f,%.4f,%.4f,%.4f,%.4f,%.2f,%.2f\n", n, scale == 1 ? "light" : "heavy",
                hidden, median(r1), median(rt), cm, median(d1), median(dt), cm > 0 ? cm / median(r1) : 0.0,
                median(r1) / median(d1));
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  ridt::bench::TableArgs a;
  if (!ridt::bench::parse_table_args(argc, argv, a)) return 2;
  return ridt::bench::write_table(a,
                                  "n,weights,hidden,regular_1_s,regular_" + std::to_string(a.threads) +
                                      "_s,cgal_s,delaunay_1_s,delaunay_" + std::to_string(a.threads) +
                                      "_s,cgal_over_regular_1,regular_1_over_delaunay_1\n",
                                  [&](const auto& line) {
                                    for (const std::size_t n : a.sizes)
                                      for (const double scale : {1.0, 40.0}) {
                                        const std::string r = row(n, scale, a.reps, a.threads);
                                        if (r.empty()) return false;
                                        line(r);
                                      }
                                    return true;
                                  });
}
