// ridt's constrained Delaunay triangulation and quality mesh beside Shewchuk's Triangle (-p,
// -pq) and CGAL (Constrained_Delaunay_triangulation_2, Delaunay_mesher_2), on the same
// planar straight-line graph in the same run: generate_coastline's island of n vertices with
// lakes (holes), and, with --extra, that many uniform points around it.
//
//   ridt_bench_constrained [--task cdt|quality] [--n N] [--lakes L] [--extra M] [--angle DEG]
//                          [--area A] [--reps R] [--csv FILE] [--poly OUT.poly]
//
// Each run is a process of its own (fork), the codes in a new random order each repetition;
// a row gives the median time, the median of each repetition's ratio to ridt's one-thread run
// in it, the triangles, the smallest angle of any triangle and the peak memory the run added
// to its process (--csv: the rows also appended to FILE, a header first where it is new, for
// the performance page). ridt and Triangle remove the exterior and the lakes; CGAL's triangulation
// keeps them (its mesher meshes inside the coastline and leaves the lakes out, seeded as
// Triangle's holes are).
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "common.hpp"
#include "ridt/constrained.hpp"
#include "ridt/generate.hpp"
#include "triangle.hpp"

#ifdef RIDT_WITH_CGAL
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace {

using Clock = std::chrono::steady_clock;

struct Args {
  std::string task = "cdt";
  std::uint32_t n = 1000000, lakes = 100, extra = 0;
  double angle = 30, area = 0;
  int reps = 3;
  std::string csv;  // append the rows here
  std::string poly;  // write the graph here as Triangle's .poly instead of timing
};

// What a run gives back: its triangles' vertices as flat coordinates (x0 y0 x1 y1 x2 y2 ...)
// are not kept; only these.
struct Result {
  double seconds = 0, worst_angle = 180, added_bytes = 0;
  std::size_t triangles = 0;
};

double smallest_angle(const double* a, const double* b, const double* c) {
  double worst = 180;
  const double* p[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    const double* o = p[i];
    const double* u = p[(i + 1) % 3];
    const double* w = p[(i + 2) % 3];
    const double ux = u[0] - o[0], uy = u[1] - o[1], wx = w[0] - o[0], wy = w[1] - o[1];
    worst = std::min(worst, std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 / 3.14159265358979323846);
  }
  return worst;
}

using Code = std::function<Result(const ridt::Pslg&, const Args&)>;

Result run_ridt(const ridt::Pslg& g, const Args& a, unsigned threads) {
  ridt::Options o;
  o.method = ridt::Method::Auto;  // as the tool and Python take it: partition on more than one thread
  o.threads = threads;
  ridt::Domain d;
  d.convex_hull = false;
  d.holes = g.holes;
  ridt::Quality q;
  if (a.task == "quality") q.min_angle = a.angle, q.max_area = a.area;
  const auto t0 = Clock::now();
  const ridt::ConstrainedTriangulation t = ridt::triangulate_constrained(g.points, g.segments, o, d, q);
  Result r;
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  r.triangles = t.size();
  auto at = [&](ridt::VertexId v) { return v < g.points.size() ? &g.points[v].x : &t.steiner[v - g.points.size()].x; };
  for (std::size_t k = 0; k < t.size(); ++k)
    r.worst_angle = std::min(
        r.worst_angle, smallest_angle(at(t.triangles[3 * k]), at(t.triangles[3 * k + 1]), at(t.triangles[3 * k + 2])));
  return r;
}

#ifdef RIDT_WITH_TRIANGLE
Result run_triangle(const ridt::Pslg& g, const Args& a) {
  std::vector<double> xy, holes;
  for (const ridt::Point& p : g.points) xy.push_back(p.x), xy.push_back(p.y);
  for (const ridt::Point& p : g.holes) holes.push_back(p.x), holes.push_back(p.y);
  std::vector<int> segs(g.segments.begin(), g.segments.end());
  triangulateio in{}, out{};
  in.pointlist = xy.data();
  in.numberofpoints = static_cast<int>(g.points.size());
  in.segmentlist = segs.data();
  in.numberofsegments = static_cast<int>(segs.size() / 2);
  in.holelist = holes.data();
  in.numberofholes = static_cast<int>(g.holes.size());
  std::string sw = "pzQB";
  if (a.task == "quality") {
    sw += "q" + ridt::bench::format("%g", a.angle);
    if (a.area > 0) sw += "a" + ridt::bench::format("%.17g", a.area);
  }
  const auto t0 = Clock::now();
  triangulate(sw.data(), &in, &out, nullptr);
  Result r;
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  r.triangles = static_cast<std::size_t>(out.numberoftriangles);
  for (std::size_t k = 0; k < r.triangles; ++k)
    r.worst_angle = std::min(
        r.worst_angle,
        smallest_angle(&out.pointlist[2 * out.trianglelist[3 * k]], &out.pointlist[2 * out.trianglelist[3 * k + 1]],
                       &out.pointlist[2 * out.trianglelist[3 * k + 2]]));
  trifree(out.pointlist), trifree(out.trianglelist), trifree(out.segmentlist);
  trifree(out.pointmarkerlist), trifree(out.segmentmarkerlist);
  return r;
}
#endif

#ifdef RIDT_WITH_CGAL
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

Result run_cgal(const ridt::Pslg& g, const Args& a) {
  std::vector<K::Point_2> pts;
  for (const ridt::Point& p : g.points) pts.emplace_back(p.x, p.y);
  std::vector<std::pair<std::size_t, std::size_t>> segs;
  for (std::size_t k = 0; k < g.segments.size(); k += 2) segs.emplace_back(g.segments[k], g.segments[k + 1]);
  std::vector<K::Point_2> seeds;
  for (const ridt::Point& p : g.holes) seeds.emplace_back(p.x, p.y);
  const auto t0 = Clock::now();
  Cdt cdt;
  cdt.insert_constraints(pts.begin(), pts.end(), segs.begin(), segs.end());
  if (a.task == "quality") {
    const double s = std::sin(a.angle * 3.14159265358979323846 / 180);
    const double edge = a.area > 0 ? std::sqrt(4 * a.area / std::sqrt(3.0)) * 1.5 : 0;
    CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(),
                                 CGAL::Delaunay_mesh_size_criteria_2<Cdt>(s * s, edge));
  }
  Result r;
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (a.task == "quality" && !f->is_in_domain()) continue;
    ++r.triangles;
    double p[3][2];
    for (int i = 0; i < 3; ++i) p[i][0] = f->vertex(i)->point().x(), p[i][1] = f->vertex(i)->point().y();
    r.worst_angle = std::min(r.worst_angle, smallest_angle(p[0], p[1], p[2]));
  }
  return r;
}
#endif

double status_bytes(const char* key) {
  std::ifstream f("/proc/self/status");
  for (std::string line; std::getline(f, line);)
    if (line.rfind(key, 0) == 0) return std::stod(line.substr(std::strlen(key))) * 1024;
  return -1;
}

// Code c run once in a child process, which first resets its peak to what it holds.
Result isolated(const Code& c, const ridt::Pslg& g, const Args& a) {
  int fd[2];
  if (pipe(fd) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    if (FILE* f = std::fopen("/proc/self/clear_refs", "w")) std::fputs("5", f), std::fclose(f);
    const double before = status_bytes("VmRSS:");
    Result r = c(g, a);
    r.added_bytes = status_bytes("VmHWM:") - before;
    if (write(fd[1], &r, sizeof r) != sizeof r) _exit(1);
    _exit(0);
  }
  close(fd[1]);
  Result r;
  const bool got = read(fd[0], &r, sizeof r) == sizeof r;
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!got) throw std::runtime_error("a run failed");
  return r;
}

// The graph as Triangle's .poly (numbered from 1), for timing `ridt mesh` and `triangle -p`
// as whole processes on the same file.
bool write_poly(const std::string& path, const ridt::Pslg& g) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) return false;
  std::fprintf(f, "%zu 2 0 0\n", g.points.size());
  for (std::size_t i = 0; i < g.points.size(); ++i)
    std::fprintf(f, "%zu %.17g %.17g\n", i + 1, g.points[i].x, g.points[i].y);
  std::fprintf(f, "%zu 0\n", g.segments.size() / 2);
  for (std::size_t i = 0; i + 1 < g.segments.size(); i += 2)
    std::fprintf(f, "%zu %u %u\n", i / 2 + 1, g.segments[i] + 1, g.segments[i + 1] + 1);
  std::fprintf(f, "%zu\n", g.holes.size());
  for (std::size_t i = 0; i < g.holes.size(); ++i)
    std::fprintf(f, "%zu %.17g %.17g\n", i + 1, g.holes[i].x, g.holes[i].y);
  return std::fclose(f) == 0;
}

bool parse(int argc, char** argv, Args& a) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--task")
      a.task = v;
    else if (k == "--n")
      a.n = static_cast<std::uint32_t>(std::stoul(v));
    else if (k == "--lakes")
      a.lakes = static_cast<std::uint32_t>(std::stoul(v));
    else if (k == "--extra")
      a.extra = static_cast<std::uint32_t>(std::stoul(v));
    else if (k == "--angle")
      a.angle = std::stod(v);
    else if (k == "--area")
      a.area = std::stod(v);
    else if (k == "--reps")
      a.reps = std::stoi(v);
    else if (k == "--csv")
      a.csv = v;
    else if (k == "--poly")
      a.poly = v;
    else
      return false;
  }
  return argc % 2 == 1 && (a.task == "cdt" || a.task == "quality");
}

// The table's rows, and with --csv the same appended to that file; returns the exit status.
int print_rows(const Args& a, const std::vector<std::pair<std::string, Code>>& codes,
               const std::vector<std::vector<Result>>& runs) {
  // "ratio": the median of each repetition's ratio to the first code's run in it (the runs of
  // one repetition are next to each other in time, so a drift of the machine's speed cancels).
  std::printf("%-20s %10s %8s %12s %10s %10s\n", "code", "seconds", "ratio", "triangles", "min angle", "MB added");
  FILE* csv = a.csv.empty() ? nullptr : std::fopen(a.csv.c_str(), "a");
  if (!a.csv.empty() && csv == nullptr) {
    std::perror(a.csv.c_str());
    return 1;
  }
  if (csv != nullptr && std::fseek(csv, 0, SEEK_END) == 0 && std::ftell(csv) == 0)
    std::fprintf(csv, "task,n,lakes,extra,angle,area,reps,code,seconds,ratio,triangles,min_angle,mb_added\n");
  for (std::size_t c = 0; c < codes.size(); ++c) {
    std::vector<double> s, mem, ratio;
    for (std::size_t r = 0; r < runs[c].size(); ++r) {
      s.push_back(runs[c][r].seconds), mem.push_back(runs[c][r].added_bytes);
      ratio.push_back(runs[c][r].seconds / runs[0][r].seconds);
    }
    std::printf("%-20s %10.3f %8.2f %12zu %10.2f %10.1f\n", codes[c].first.c_str(), ridt::bench::median(s),
                ridt::bench::median(ratio), runs[c][0].triangles, runs[c][0].worst_angle,
                ridt::bench::median(mem) / 1e6);
    if (csv != nullptr)
      std::fprintf(csv, "%s,%u,%u,%u,%g,%g,%d,\"%s\",%.4f,%.3f,%zu,%.2f,%.1f\n", a.task.c_str(), a.n, a.lakes, a.extra,
                   a.task == "quality" ? a.angle : 0.0, a.task == "quality" ? a.area : 0.0, a.reps,
                   codes[c].first.c_str(), ridt::bench::median(s), ridt::bench::median(ratio), runs[c][0].triangles,
                   runs[c][0].worst_angle, ridt::bench::median(mem) / 1e6);
  }
  return csv != nullptr && std::fclose(csv) != 0 ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  Args a;
  if (!parse(argc, argv, a)) {
    std::fprintf(stderr,
                 "usage: ridt_bench_constrained [--task cdt|quality] [--n N] [--lakes L] [--extra M] "
                 "[--angle DEG] [--area A] [--reps R] [--csv FILE] [--poly OUT.poly]\n");
    return 2;
  }
  ridt::Pslg g = ridt::generate_coastline(a.n, a.lakes, 1);
  for (const ridt::Point& p : ridt::generate(ridt::Distribution::Uniform, a.extra, 2))
    g.points.push_back({2.6 * p.x - 1.3, 2.6 * p.y - 1.3});
  if (!a.poly.empty()) return write_poly(a.poly, g) ? 0 : 1;
  std::vector<std::pair<std::string, Code>> codes = {
      {"ridt, 1 thread", [](const ridt::Pslg& p, const Args& x) { return run_ridt(p, x, 1); }},
      {"ridt, all threads", [](const ridt::Pslg& p, const Args& x) { return run_ridt(p, x, 0); }}};
#ifdef RIDT_WITH_TRIANGLE
  codes.push_back({"Triangle", run_triangle});
#endif
#ifdef RIDT_WITH_CGAL
  codes.push_back({"CGAL", run_cgal});
#endif
  std::vector<std::vector<Result>> runs(codes.size());
  std::vector<std::size_t> order(codes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::mt19937 shuffle(7);
  for (int r = 0; r < a.reps; ++r) {
    std::shuffle(order.begin(), order.end(), shuffle);
    for (const std::size_t c : order) runs[c].push_back(isolated(codes[c].second, g, a));
  }
  std::printf("%s of a coastline of %u vertices, %u lakes, %u more points%s; medians of %d runs\n", a.task.c_str(), a.n,
              a.lakes, a.extra,
              a.task == "quality" ? (", min angle " + ridt::bench::format("%g", a.angle) + ", max area " +
                                     ridt::bench::format("%g", a.area))
                                        .c_str()
                                  : "",
              a.reps);
  return print_rows(a, codes, runs);
}
