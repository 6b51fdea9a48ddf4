// Fuzz target: the point, triangle and graph readers, every format.
//
// The first byte picks the format (0xff: a .poly, then triangulated with its segments; 0xfe: an
// ESRI ASCII grid of sizes, then a square meshed to it), the rest is the file's content. A reader must either
// throw IoError or return what it promises: finite points that survive writing and reading
// back bit for bit in every point format, and whole triangles, which the exact validator then
// judges against a small point set without failing. Any other exception, a crash or a
// sanitizer report is a finding.
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numeric>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io.hpp"
#include "ridt/check.hpp"
#include "ridt/constrained.hpp"

namespace {

using ridt::Point;
using ridt::VertexId;
namespace io = ridt::io;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_readers: %s\n", what.c_str());
  std::abort();
}

bool same_bits(const Point& a, const Point& b) {
  return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
      std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y);
}

// A private folder for the round trips, removed at exit.
const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir = [] {
    std::filesystem::path d =
        std::filesystem::temp_directory_path() / ("ridt-fuzz-readers-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(scratch_dir(), ec);
    });
    return d;
  }();
  return dir;
}

void points(std::string_view data, const char* name) {
  io::PointFile file;
  try {
    file = io::parse_points(data, name);
  } catch (const io::IoError&) {
    return;
  }
  if (file.first_index != 0 && file.first_index != 1) finding("first index not 0 or 1");
  for (const Point& p : file.points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) finding("a coordinate is not finite");
  for (const char* format : {"round.txt", "round.node", "round.bin"}) {
    const std::string path = (scratch_dir() / format).string();
    io::write_points(path, file.points);
    const io::PointFile back = io::read_points(path);
    if (back.points.size() != file.points.size())
      finding(std::string("round trip through ") + format + " changed the count");
    for (std::size_t i = 0; i < back.points.size(); ++i)
      if (!same_bits(back.points[i], file.points[i]))
        finding(std::string("round trip through ") + format + " changed point " + std::to_string(i));
  }
}

// The same .ele read as ridt check and ridt mesh -r read it: refused where read_triangles
// refuses it but for six nodes a triangle, else the same corners, three middles a triangle or
// none, one attribute a triangle or none.
void elements(std::string_view data, int first_index) {
  const std::string path = (scratch_dir() / "in.ele").string();
  if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data.data(), 1, data.size(), f);
    std::fclose(f);
  }
  std::vector<VertexId> corners, tris, middles;
  std::vector<double> attributes;
  bool plain = true, read = true;
  try {
    corners = io::parse_triangles(data, "in.ele", first_index);
  } catch (const io::IoError&) {
    plain = false;
  }
  try {
    tris = io::read_elements(path, first_index, attributes, middles);
  } catch (const io::IoError&) {
    read = false;
  }
  if (plain && !read) finding("read_elements refused a .ele that read_triangles took");
  if (!read) return;
  // (A file of no triangles says six nodes in its header alone: it has no middles to show.)
  if (!plain && middles.empty() && !tris.empty())
    finding("read_elements took a three-node .ele that read_triangles refused");
  if (plain && tris != corners) finding("read_elements read other corners than read_triangles");
  if (!attributes.empty() && attributes.size() != tris.size() / 3)
    finding("read_elements: not an attribute a triangle");
  if (!middles.empty() && middles.size() != tris.size()) finding("read_elements: not three middles a triangle");
}

void triangles(std::string_view data, const char* name, int first_index) {
  if (std::string_view(name).ends_with(".ele")) elements(data, first_index);
  std::vector<VertexId> tris;
  try {
    tris = io::parse_triangles(data, name, first_index);
  } catch (const io::IoError&) {
    return;
  }
  if (tris.size() % 3 != 0) finding("a triangle file gave a partial triangle");
  // The validator takes any triangle list: out-of-range indices, repeated and flipped
  // triangles, against points with a duplicate and three on a line.
  static const std::vector<Point> points = {{0, 0}, {1, 0}, {0, 1}, {1, 1},      {0.5, 0.5},
                                            {2, 2}, {0, 0}, {3, 0}, {0.25, 0.75}};
  const ridt::CheckResult verdict = ridt::check(points, tris);
  if (verdict.valid != (verdict.problems == 0) || verdict.message.empty())
    finding("the validator's verdict does not add up: " + verdict.message);
  // refine_mesh takes them as a mesh (flipped to constrained Delaunay), one the validator finds
  // sound with its fixed edges as segments, or refuses them by name.
  try {
    const ridt::ConstrainedTriangulation r = ridt::refine_mesh(points, tris, {}, {});
    if (r.size() != tris.size() / 3 || !r.steiner.empty()) finding("refine_mesh with no bound changed the count");
    ridt::MeshSpec spec;
    spec.edges = r.edges;
    if (const ridt::CheckResult c = ridt::check_mesh(points, r.triangles, spec); !c.valid)
      finding("refine_mesh took a mesh the validator refuses: " + c.message);
  } catch (const ridt::InputError&) {}
}

// Its six-node triangles: a node an edge (Euler's count), each the rounded middle of its ends,
// each triangle's the middles of the edges across from its corners.
void six_nodes(const std::vector<Point>& all, const ridt::Triangulation& t) {
  ridt::SecondOrder s;
  try {
    s = ridt::second_order(all, t);
  } catch (const ridt::InputError& e) {  // a mesh whose links it cannot follow: not the caller's input
    finding(std::string("six-node triangles of a mesh refused: ") + e.what());
  }
  std::size_t boundary = 0;
  for (const std::int32_t n : t.neighbors) boundary += n < 0;
  if (s.nodes.size() != (t.triangles.size() + boundary) / 2) finding("six-node triangles: not a node an edge");
  for (std::size_t k = 0; k < t.triangles.size() / 3; ++k)
    for (int i = 0; i < 3; ++i) {
      const VertexId a = t.triangles[3 * k + (i + 1) % 3], b = t.triangles[3 * k + (i + 2) % 3];
      const std::size_t q = s.triangles[6 * k + 3 + i] - all.size();
      const Point want{std::midpoint(all[a].x, all[b].x), std::midpoint(all[a].y, all[b].y)};
      if (q >= s.nodes.size() || s.nodes[q].x != want.x || s.nodes[q].y != want.y ||
          std::minmax(s.ends[2 * q], s.ends[2 * q + 1]) != std::minmax(a, b))
        finding("six-node triangles: a node is not the middle of the edge across from its corner");
    }
  std::vector<Point> nodes = all;
  nodes.insert(nodes.end(), s.nodes.begin(), s.nodes.end());
  std::vector<VertexId> corners, middles;
  for (auto six = s.triangles.begin(); six != s.triangles.end(); six += 6) {
    corners.insert(corners.end(), six, six + 3);
    middles.insert(middles.end(), six + 3, six + 6);
  }
  if (const ridt::CheckResult r = ridt::check_second_order(nodes, corners, middles); !r.valid)
    finding("check_second_order rejects second_order's nodes: " + r.message);
}

// A constrained triangulation or mesh through the exact validator of meshes, and its six-node
// triangles.
void validate(const io::Pslg& g, const ridt::ConstrainedTriangulation& t, const ridt::Domain& d,
              const ridt::Quality& q) {
  std::vector<Point> all = g.points;
  all.insert(all.end(), t.steiner.begin(), t.steiner.end());
  ridt::MeshSpec spec;
  spec.edges = t.edges;
  spec.segments = g.segments;
  spec.input_points = g.points.size();
  spec.holes = d.holes;
  spec.min_angle = q.min_angle;
  spec.max_area = q.max_area;
  const ridt::CheckResult verdict = ridt::check_mesh(all, t.triangles, spec);
  if (!verdict.valid) finding("a mesh the validator rejects: " + verdict.message);
  six_nodes(all, t);
}

// The quality a .poly is meshed to, picked by a hash of its bytes (the same file, the same
// mesh): no angle or 20 to 33 degrees, no area bound or a fiftieth or a five-hundredth of its
// box's, points on the boundary or not (-Y), on any segment or not (-YY), conforming or not
// (-D), a size of the caller's that grows away from the box's corner or none (-u); its regions'
// own bounds.
ridt::Quality quality_for(std::string_view data, const io::Pslg& g) {
  std::uint64_t h = 1469598103934665603u;
  for (const char c : data) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211u;
  constexpr double kAngles[] = {0, 20, 25, 30, 33};
  ridt::Quality q;
  q.min_angle = kAngles[h % 5];
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (const Point& p : g.points)
    x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  const double box = (x1 - x0) * (y1 - y0), share = (h >> 3) % 3 == 0 ? 0 : (h >> 3) % 3 == 1 ? 50 : 500;
  if (share > 0 && std::isfinite(box) && box > 0) q.max_area = box / share;
  q.split_boundary = ((h >> 5) & 3) != 0;
  q.conforming = ((h >> 7) & 3) == 0;
  q.split_segments = q.conforming || ((h >> 9) & 7) != 0;
  if (((h >> 12) & 3) == 0 && std::isfinite(box) && box > 0)
    q.unsuitable = [x0, y0, box](const Point& a, const Point& b, const Point& c, double area) {
      const double x = (a.x + b.x + c.x) / 3 - x0, y = (a.y + b.y + c.y) / 3 - y0;
      return area > box / 400 + (x * x + y * y) / 20;
    };
  if (!q.enabled()) q.min_angle = 25;
  q.max_steiner = 5000;
  return q;
}

// The carved triangulation refined afterwards (refine_mesh, Triangle's -r) to the same quality
// (at most 1000 points added), its triangles alternately bounded to half the area: the
// validator accepts it, its segments as the chains of the carved one's edges.
void refine_again(const io::Pslg& g, const ridt::ConstrainedTriangulation& carved, ridt::Quality q) {
  if (carved.size() == 0) return;
  q.max_steiner = 1000;  // a third refinement of the input: kept shorter, lest it time out
  std::vector<Point> all = g.points;
  all.insert(all.end(), carved.steiner.begin(), carved.steiner.end());
  std::vector<double> bounds(carved.size(), 0.0);
  for (std::size_t k = 0; k < bounds.size() && q.max_area > 0; k += 2) bounds[k] = q.max_area / 2;
  ridt::ConstrainedTriangulation r;
  try {
    r = ridt::refine_mesh(all, carved.triangles, carved.edges, q, bounds);
  } catch (const ridt::InputError& e) {  // the library's own mesh: nothing in it to refuse
    finding(std::string("refine_mesh refused a constrained triangulation: ") + e.what());
  }
  if (!r.warning.empty() || r.steiner.size() >= q.max_steiner) return;
  io::Pslg as_given;
  as_given.points = all;
  as_given.segments = carved.edges;
  ridt::Quality asked = q;
  if (!q.split_boundary || !q.split_segments) asked.min_angle = asked.max_area = 0;
  validate(as_given, r, {}, asked);
}

// With -YY no segment is split but where segments cross: each segment edge ends at an input
// point or a crossing. A finding where one does not.
void segments_whole(const io::Pslg& g, const ridt::ConstrainedTriangulation& t) {
  for (const VertexId v : t.edges)
    if (v >= g.points.size() + t.crossings) finding("-YY: a segment edge ends at a point refinement added");
}

// A .poly: either IoError, or finite points and holes, segments between them, and then a
// constrained triangulation (crossings split) and a quality mesh (quality_for: at most 5000
// points added, its regions too) that the exact validator accepts, with the bounds asked where
// points may go on the boundary.
void graph(std::string_view data) {
  io::Pslg g;
  try {
    g = io::parse_pslg(data, "in.poly");
  } catch (const io::IoError&) {
    return;
  }
  for (const Point& p : g.points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) finding("a vertex is not finite");
  for (const Point& h : g.holes)
    if (!std::isfinite(h.x) || !std::isfinite(h.y)) finding("a hole is not finite");
  if (g.segments.size() % 2 != 0) finding("a partial segment");
  for (const VertexId v : g.segments)
    if (v >= g.points.size()) finding("a segment's end is not a vertex");
  if (g.points.size() > 2000) return;
  try {
    const ridt::ConstrainedTriangulation t = ridt::triangulate_constrained(g.points, g.segments);
    validate(g, t, {}, {});
    ridt::Domain domain;
    domain.convex_hull = false;
    domain.holes = g.holes;
    const ridt::ConstrainedTriangulation carved = ridt::triangulate_constrained(g.points, g.segments, {}, domain);
    if (carved.size() > t.size()) finding("carving added triangles");
    validate(g, carved, domain, {});
    const ridt::Quality q = quality_for(data, g);
    for (const auto& [x, y, attribute, max_area] : g.regions) domain.regions.push_back({{x, y}, attribute, max_area});
    const ridt::ConstrainedTriangulation meshed = ridt::triangulate_constrained(g.points, g.segments, {}, domain, q);
    ridt::Quality asked = q;
    // -Y, -YY: a bad triangle may have to stay
    if (!q.split_boundary || !q.split_segments) asked.min_angle = asked.max_area = 0;
    if (meshed.steiner.size() < q.max_steiner + meshed.crossings && meshed.warning.empty())
      validate(g, meshed, domain, asked);
    if (!q.split_segments) segments_whole(g, meshed);
    refine_again(g, carved, q);
  } catch (const ridt::InputError&) {}
}

// A size field from an ESRI ASCII grid: IoError, or a field that a square is meshed to (a few
// thousand points at most), no triangle's longest edge then above the size at its centroid.
void size_grid(std::string_view data) {
  const std::string path = (scratch_dir() / "in.asc").string();
  if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data.data(), 1, data.size(), f);
    std::fclose(f);
  }
  ridt::SizeField field;
  try {
    field = io::read_size_field(path);
  } catch (const io::IoError&) {
    return;
  }
  const std::vector<Point> square = {{-1, -1}, {2, -1}, {2, 2}, {-1, 2}};
  const std::vector<VertexId> sides = {0, 1, 1, 2, 2, 3, 3, 0};
  ridt::Quality q;
  q.size = field;
  q.max_steiner = 3000;
  const ridt::ConstrainedTriangulation t = ridt::triangulate_constrained(square, sides, {}, {}, q);
  if (!t.warning.empty()) return;  // stopped at max_steiner: sizes too small for the square
  std::vector<Point> all = square, centroids;
  all.insert(all.end(), t.steiner.begin(), t.steiner.end());
  std::vector<double> longest;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const Point &a = all[t.triangles[3 * k]], &b = all[t.triangles[3 * k + 1]], &c = all[t.triangles[3 * k + 2]];
    centroids.push_back({a.x / 3 + b.x / 3 + c.x / 3, a.y / 3 + b.y / 3 + c.y / 3});
    longest.push_back(std::max(
        {std::hypot(a.x - b.x, a.y - b.y), std::hypot(b.x - c.x, b.y - c.y), std::hypot(c.x - a.x, c.y - a.y)}));
  }
  const std::vector<double> h = field.sizes(centroids);
  for (std::size_t k = 0; k < h.size(); ++k)
    if (!(longest[k] <= h[k] * (1 + 1e-9))) finding("a triangle above the size field's size");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view data(reinterpret_cast<const char*>(bytes) + 1, size - 1);
  if (bytes[0] == 0xff) return graph(data), 0;  // the other first bytes pick as they always did
  if (bytes[0] == 0xfe) return size_grid(data), 0;
  switch (bytes[0] % 7) {
    case 0:
      points(data, "in.txt");
      break;
    case 1:
      points(data, "in.node");
      break;
    case 2:
      points(data, "in.bin");
      break;
    case 3:
      triangles(data, "in.ele", 0);
      break;
    case 4:
      triangles(data, "in.ele", 1);
      break;
    case 5:
      triangles(data, "in.txt", 1);
      break;
    case 6:
      triangles(data, "in.bin", 0);
      break;
  }
  return 0;
}
