// ridt sphere: the Delaunay triangulation on the sphere (ridt/sphere.hpp) of points read as
// longitude and latitude in degrees or as x, y, z, with its Voronoi cells and their areas.
#include <charconv>
#include <cmath>
#include <fstream>

#include "command.hpp"
#include "ridt/sphere.hpp"
#include "writer.hpp"

namespace ridt::tool {
namespace {

// The points of a text file: each line that is neither empty nor a comment ('#') holds two
// numbers (longitude, latitude in degrees: points of the unit sphere) or three (x, y, z),
// apart by spaces, tabs or commas; every line the same count. `degrees` says which.
std::vector<Point3> read_sphere_points(const std::string& path, bool& degrees) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot read " + path);
  std::vector<Point3> out;
  std::string line;
  int columns = 0;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    double v[4];
    int k = 0;
    const char *p = line.data(), *end = line.data() + line.size();
    auto where = [&] { return path + ":" + std::to_string(number) + ": "; };
    while (true) {
      while (p < end && (*p == ' ' || *p == '\t' || *p == ',' || *p == '\r')) ++p;
      if (p == end) break;
      if (k == 4) throw IoError(where() + "more than three numbers");
      if (*p == '+') ++p;
      const auto [next, ec] = std::from_chars(p, end, v[k]);
      if (ec != std::errc() || (next < end && *next != ' ' && *next != '\t' && *next != ',' && *next != '\r'))
        throw IoError(where() + "not a number: '" +
                      std::string(p, std::find_if(p, end, [](char c) { return c == ' ' || c == '\t' || c == ','; })) +
                      "'");
      if (!std::isfinite(v[k])) throw IoError(where() + "a number that is not finite");
      p = next, ++k;
    }
    if (k == 0) continue;
    if (k == 1 || k == 4) throw IoError(where() + "a point needs two numbers (longitude, latitude) or three (x, y, z)");
    if (columns == 0) columns = k;
    if (k != columns)
      throw IoError(where() + std::to_string(k) + " numbers where the lines before have " + std::to_string(columns));
    if (k == 3) {
      out.push_back({v[0], v[1], v[2]});
      continue;
    }
    if (std::fabs(v[1]) > 90) throw IoError(where() + "a latitude beyond 90 degrees");
    const double lon = v[0] * (3.14159265358979323846 / 180), lat = v[1] * (3.14159265358979323846 / 180);
    out.push_back({std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)});
  }
  if (in.bad()) throw IoError("cannot read " + path);
  degrees = columns == 2;
  return out;
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

void put_point(io::Writer& out, const Point3& p) {
  out.put_double(p.x);
  out.put(' ');
  out.put_double(p.y);
  out.put(' ');
  out.put_double(p.z);
  out.put('\n');
}

// The triangles: OUT.off with the points, else three indices a line.
void write_triangles(const std::string& path, std::span<const Point3> pts, const SphericalTriangulation& t) {
  io::Writer out(path);
  const bool off = ends_with(path, ".off");
  if (off) {
    out.put("OFF\n" + std::to_string(pts.size()) + " " + std::to_string(t.size()) + " 0\n");
    for (const Point3& p : pts) put_point(out, p);
  }
  for (std::size_t f = 0; f < t.size(); ++f) {
    if (off) out.put("3 ");
    for (int i = 0; i < 3; ++i) {
      out.put_int(t.triangles[3 * f + i]);
      out.put(i < 2 ? ' ' : '\n');
    }
  }
  out.commit();
}

// The cells as an .off: the Voronoi vertices, a polygon a point that has a cell.
void write_cells(const std::string& path, const SphericalVoronoi& v, std::size_t n) {
  io::Writer out(path);
  std::size_t cells = 0;
  for (std::size_t g = 0; g < n; ++g) cells += v.region_start[g + 1] > v.region_start[g];
  out.put("OFF\n" + std::to_string(v.vertices.size()) + " " + std::to_string(cells) + " 0\n");
  for (const Point3& p : v.vertices) put_point(out, p);
  for (std::size_t g = 0; g < n; ++g) {
    const std::uint32_t from = v.region_start[g], to = v.region_start[g + 1];
    if (from == to) continue;
    out.put_int(to - from);
    for (std::uint32_t k = from; k < to; ++k) {
      out.put(' ');
      out.put_int(v.regions[k]);
    }
    out.put('\n');
  }
  out.commit();
}

void write_areas(const std::string& path, const SphericalVoronoi& v) {
  io::Writer out(path);
  for (const double area : v.areas) {
    out.put_double(area);
    out.put('\n');
  }
  out.commit();
}

struct SphereArgs {
  std::string input, output, voronoi, areas, center;
  double radius = 0;
  bool check = false;
  unsigned threads = 0;
};

// The run: read, triangulate, say what was dropped, check, write.
int run_sphere(const SphereArgs& a) {
  refuse_overwriting({a.input}, {a.output, a.voronoi, a.areas});
  bool degrees = false;
  const std::vector<Point3> pts = read_sphere_points(a.input, degrees);
  Point3 c{};
  if (!a.center.empty()) {
    const std::vector<double> v = numbers(a.center, "--center");
    if (v.size() != 3) throw InputError("--center takes three numbers x,y,z");
    c = {v[0], v[1], v[2]};
  }
  const unsigned threads = thread_count(a.threads);
  const SphericalTriangulation t = triangulate_sphere(pts, threads);
  if (!t.duplicates.empty())
    std::fprintf(stderr, "ridt: %zu duplicate point%s dropped (the first of equal points stands for them)\n",
                 t.duplicates.size(), t.duplicates.size() == 1 ? "" : "s");
  if (!t.hidden.empty())
    std::fprintf(stderr, "ridt: %zu point%s inside the hull of the others (no cell), the first %u\n", t.hidden.size(),
                 t.hidden.size() == 1 ? " lies" : "s lie", t.hidden[0]);
  int status = 0;
  if (a.check) {
    const CheckResult r = check_sphere(pts, t.triangles);
    std::fprintf(stderr, "ridt: %s\n", r.message.c_str());
    if (!r.valid) status = kExitInvalid;
  }
  write_triangles(a.output, pts, t);
  if (a.voronoi.empty() && a.areas.empty()) return status;
  double radius = a.radius != 0 ? a.radius : degrees ? 1 : 0;
  if (radius == 0) {
    for (const Point3& p : pts) radius += std::hypot(p.x - c.x, p.y - c.y, p.z - c.z);
    radius /= static_cast<double>(pts.size());
  }
  const SphericalVoronoi v = spherical_voronoi(t, pts, c, radius, !a.areas.empty(), threads);
  if (!a.voronoi.empty()) write_cells(a.voronoi, v, pts.size());
  if (!a.areas.empty()) write_areas(a.areas, v);
  return status;
}

}  // namespace

Command add_sphere(CLI::App& app) {
  auto a = std::make_shared<SphereArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sphere",
      "the Delaunay triangulation on the sphere (the points' exact convex hull), its Voronoi cells and areas");
  cmd->add_option("input", a->input,
                  "points, one a line: longitude latitude (degrees, on the unit sphere) or x y z; apart by spaces or "
                  "commas, '#' comments")
      ->required();
  cmd->add_option("-o,--output", a->output,
                  "the triangles: OUT.off (a mesh of the points as x y z) or text, one triangle a line (three input "
                  "indices from 0, counter-clockwise seen from outside)")
      ->required();
  cmd->add_option("--voronoi", a->voronoi,
                  "the Voronoi cells as OUT.off: a polygon a point (copies and points inside "
                  "the hull have none), its vertices on the sphere");
  cmd->add_option("--areas", a->areas,
                  "each point's cell area, one a line in input order (0 for copies and points "
                  "inside the hull)");
  cmd->add_option("--center", a->center, "the sphere's centre x,y,z for the cells (default: the origin)");
  cmd->add_option("--radius", a->radius,
                  "the sphere's radius for the cells (default: 1 for longitudes and latitudes, "
                  "else the points' mean distance from the centre)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--check", a->check, "check the triangulation with the exact validator (exit 1 if invalid)");
  cmd->add_option("--threads", a->threads, "threads (0, the default: all hardware threads)");
  return {cmd, [a] { return run_sphere(*a); }};
}

}  // namespace ridt::tool
