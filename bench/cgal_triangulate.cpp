// CGAL's Delaunay_triangulation_2 as a whole process, for benchmarks that time `ridt
// triangulate` from outside: reads a .bin point file (little-endian float64 x, y pairs),
// inserts the points with CGAL's range insert (which sorts them along a curve first) and
// prints the number of finite faces.
//
//   ridt_cgal_triangulate POINTS.bin
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdio>
#include <fstream>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s POINTS.bin\n", argv[0]);
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  std::vector<double> xy;
  if (in) {
    in.seekg(0, std::ios::end);
    xy.resize(static_cast<std::size_t>(in.tellg()) / sizeof(double));
    in.seekg(0);
    in.read(reinterpret_cast<char*>(xy.data()), static_cast<std::streamsize>(xy.size() * sizeof(double)));
  }
  if (!in || xy.size() % 2 != 0) {
    std::fprintf(stderr, "%s: cannot read %s as float64 x, y pairs\n", argv[0], argv[1]);
    return 1;
  }
  std::vector<K::Point_2> points;
  points.reserve(xy.size() / 2);
  for (std::size_t i = 0; i < xy.size(); i += 2) points.emplace_back(xy[i], xy[i + 1]);
  std::vector<double>().swap(xy);
  CGAL::Delaunay_triangulation_2<K> dt;
  dt.insert(points.begin(), points.end());
  std::printf("%zu\n", static_cast<std::size_t>(dt.number_of_faces()));
  return 0;
}
