// The periodic Delaunay triangulation beside CGAL's Periodic_2_Delaunay_triangulation_2 and
// beside ridt's own triangulation of the same points in the plane (the floor), in one run: the
// kernels in process, interleaved, each figure the median of --reps. Uniform points in the unit
// square, the domain (CGAL's takes a square).
//
//   ridt_bench_periodic [--sizes 100000,1000000] [--reps 5] [--threads 2] [--csv FILE]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "common.hpp"
#include "ridt/periodic.hpp"
#include "ridt/ridt.hpp"

#ifdef RIDT_WITH_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#endif

namespace {

using ridt::bench::seconds;

#ifdef RIDT_WITH_CGAL
// CGAL's own fastest way in: all points at once (spatially sorted, the 9-sheeted cover left as
// soon as it can be).
double cgal(const std::vector<ridt::Point>& pts, std::size_t& faces) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Gt = CGAL::Periodic_2_Delaunay_triangulation_traits_2<K>;
  using P2dt = CGAL::Periodic_2_Delaunay_triangulation_2<Gt>;
  return seconds([&] {
    std::vector<K::Point_2> in;
    in.reserve(pts.size());
    for (const ridt::Point& p : pts) in.emplace_back(p.x, p.y);
    P2dt t(in.begin(), in.end(), P2dt::Iso_rectangle(0, 0, 1, 1));
    faces = t.number_of_faces();
  });
}
#endif

// One size: the medians of `reps` interleaved runs of each code, as a CSV line; empty where
// CGAL's triangle count differs from ridt's.
std::string row(std::size_t n, int reps, unsigned threads) {
  std::mt19937_64 random(n);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<ridt::Point> pts(n);
  for (ridt::Point& p : pts) p = {u(random), u(random)};
  std::vector<double> p1, pt, c, d1, dt;
  std::size_t ours = 0, theirs = 0;
  for (int rep = 0; rep < reps; ++rep) {
    p1.push_back(seconds([&] { ours = ridt::triangulate_periodic(pts, {}, 1).size(); }));
    pt.push_back(seconds([&] { ridt::triangulate_periodic(pts, {}, threads); }));
#ifdef RIDT_WITH_CGAL
    c.push_back(cgal(pts, theirs));
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
  std::snprintf(buf, sizeof buf, "%zu,%.4f,%.4f,%.4f,%.4f,%.4f,%.2f,%.2f\n", n, median(p1), median(pt), cm, median(d1),
                median(dt), cm > 0 ? cm / median(p1) : 0.0, median(p1) / median(d1));
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  ridt::bench::TableArgs a;
  if (!ridt::bench::parse_table_args(argc, argv, a)) return 2;
  return ridt::bench::write_table(a,
                                  "n,periodic_1_s,periodic_" + std::to_string(a.threads) +
                                      "_s,cgal_s,delaunay_1_s,delaunay_" + std::to_string(a.threads) +
                                      "_s,cgal_over_periodic_1,periodic_1_over_delaunay_1\n",
                                  [&](const auto& line) {
                                    for (const std::size_t n : a.sizes) {
                                      const std::string r = row(n, a.reps, a.threads);
                                      if (r.empty()) return false;
                                      line(r);
                                    }
                                    return true;
                                  });
}
