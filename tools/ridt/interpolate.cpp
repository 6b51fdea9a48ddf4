// ridt interpolate POINTS VALUES (QUERIES | --grid nx,ny[,x0,y0,x1,y1]) -o OUT
//                  [--method linear|natural|nearest] [--fill V] [--threads N]
#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <utility>

#include "command.hpp"
#include "ridt/interpolate.hpp"

namespace ridt::tool {
namespace {

struct Args {
  std::string points, values, queries, grid, method = "linear", output, memory_limit;
  double fill = std::numeric_limits<double>::quiet_NaN();
  unsigned threads = 0;
};

// Where to interpolate: the queries, and for a grid its axes too (nx by ny nodes, row by row).
struct Where {
  std::vector<Point> queries;
  std::vector<double> xs, ys;
};

// The grid's nodes; MemoryError first where they, their values (`components` a node) and the
// triangulation of `points` need more than `limit` (0: what the system can give).
Where grid_nodes(const std::string& text, std::span<const Point> points, std::size_t components, std::size_t limit) {
  const std::vector<double> g = numbers(text, "--grid");
  if ((g.size() != 2 && g.size() != 6) || g[0] < 2 || g[1] < 2 || g[0] != std::floor(g[0]) ||
      g[1] != std::floor(g[1]) || g[0] * g[1] > 1e9)
    throw InputError("--grid: give nx,ny (at least 2 each) or nx,ny,x0,y0,x1,y1");
  const auto nx = static_cast<std::size_t>(g[0]), ny = static_cast<std::size_t>(g[1]);
  // A node: its point (16 bytes), its values, and a nearest point's index (4).
  const std::size_t node = 16 + 8 * components + 4;
  Options o;
  o.method = Method::Auto;
  check_memory("interpolating on " + std::to_string(nx) + " by " + std::to_string(ny) + " nodes",
               nx * ny * node + estimate_memory(points.size(), o), limit);
  const io::Box b = g.size() == 6 ? io::Box{g[2], g[3], g[4], g[5]} : io::box_around(points, 0);
  Where w;
  for (std::size_t i = 0; i < nx; ++i)
    w.xs.push_back(b.x0 + (b.x1 - b.x0) * static_cast<double>(i) / static_cast<double>(nx - 1));
  for (std::size_t j = 0; j < ny; ++j)
    w.ys.push_back(b.y0 + (b.y1 - b.y0) * static_cast<double>(j) / static_cast<double>(ny - 1));
  w.queries.resize(nx * ny);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) w.queries[j * nx + i] = {w.xs[i], w.ys[j]};
  return w;
}

// For each query, a nearest of `points` where they lie on one line (no triangle: nearest_vertex
// has no graph to walk), or -1 for a query that is not finite. Ordered along the line, the
// points nearest a query are those beside its projection.
std::vector<std::int32_t> nearest_on_line(std::span<const Point> points, std::span<const Point> queries) {
  std::vector<std::int32_t> out(queries.size(), -1);
  if (points.empty()) return out;
  const auto lex = [](const Point& p, const Point& q) { return p.x < q.x || (p.x == q.x && p.y < q.y); };
  const Point a = *std::min_element(points.begin(), points.end(), lex);
  const Point b = *std::max_element(points.begin(), points.end(), lex);
  // Halves keep b - a finite for any finite points.
  const double dx = b.x * 0.5 - a.x * 0.5, dy = b.y * 0.5 - a.y * 0.5;
  const auto along = [&](const Point& p) { return (p.x * 0.5 - a.x * 0.5) * dx + (p.y * 0.5 - a.y * 0.5) * dy; };
  std::vector<std::pair<double, std::int32_t>> order(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) order[i] = {along(points[i]), static_cast<std::int32_t>(i)};
  std::sort(order.begin(), order.end());
  const auto distance = [&](std::int32_t i, const Point& q) {
    return std::hypot(points[static_cast<std::size_t>(i)].x - q.x, points[static_cast<std::size_t>(i)].y - q.y);
  };
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const Point& q = queries[k];
    if (!std::isfinite(q.x) || !std::isfinite(q.y)) continue;
    const auto at = std::lower_bound(order.begin(), order.end(), std::make_pair(along(q), std::int32_t{-1}));
    std::int32_t best = at != order.end() ? at->second : order.back().second;
    if (at != order.begin() && distance(std::prev(at)->second, q) <= distance(best, q)) best = std::prev(at)->second;
    out[k] = best;
  }
  return out;
}

// The answers, `components` a query (a grid: each triangle takes the nodes it holds).
std::vector<double> answer(const Args& a, std::span<const Point> points, const Triangulation& t, const Values& v,
                           const Where& w) {
  std::vector<double> out;
  if (a.method == "nearest") {
    const std::vector<std::int32_t> near =
        t.size() > 0 ? nearest_vertex(points, t, w.queries, a.threads) : nearest_on_line(points, w.queries);
    out.assign(w.queries.size() * v.components, a.fill);
    for (std::size_t q = 0; q < w.queries.size(); ++q)
      if (near[q] >= 0)
        std::copy_n(&v.data[static_cast<std::size_t>(near[q]) * v.components], v.components, &out[q * v.components]);
  } else if (!w.xs.empty()) {
    const Grid g{w.xs, w.ys};
    out.resize(g.size() * v.components);
    if (a.method == "natural")
      interpolate_natural_neighbor(points, t, v, g, out, a.fill, a.threads);
    else
      interpolate_linear(points, t, v, g, out, a.fill, a.threads);
  } else if (a.method == "natural") {
    out = interpolate_natural_neighbor(points, t, v, w.queries, a.fill, a.threads);
  } else {
    out = interpolate_linear(points, t, v, w.queries, a.fill, a.threads);
  }
  return out;
}

int run(const Args& a) {
  if (a.queries.empty() == a.grid.empty()) throw InputError("give either a QUERIES file or --grid, not both");
  if (a.method != "linear" && a.method != "natural" && a.method != "nearest")
    throw InputError("unknown method '" + a.method + "' (use linear, natural or nearest)");
  refuse_overwriting({a.points, a.values, a.queries}, {a.output});
  const io::PointFile p = io::read_points(a.points, thread_count(a.threads));
  std::size_t components = 0;
  const std::vector<double> values = io::read_values(a.values, components);
  if (values.size() != p.points.size() * components)
    throw InputError(a.values + ": " + std::to_string(values.size() / components) + " rows of values for " +
                     std::to_string(p.points.size()) + " points");
  const std::size_t limit = a.memory_limit.empty() ? 0 : byte_size(a.memory_limit, "--memory-limit");
  Where w;
  if (!a.grid.empty())
    w = grid_nodes(a.grid, p.points, components, limit);
  else {
    w.queries = io::read_points(a.queries, thread_count(a.threads)).vector();
  }
  Options o;
  o.method = Method::Auto;
  o.threads = a.threads;
  o.memory_limit = limit;
  const Triangulation t = triangulate(p.points, o);
  // Without a triangle every query would be "outside the hull": all --fill, which says nothing.
  if (t.size() == 0 && a.method != "nearest")
    throw InputError(a.points + ": no triangle to interpolate " + a.method + "ly in" +
                     (t.warning.empty() ? "" : " (" + t.warning + ")") + "; --method nearest answers");
  const std::vector<double> out = answer(a, p.points, t, {values, components}, w);
  io::write_values(a.output, w.queries, out, components, w.xs.size(), w.ys.size());
  return 0;
}

}  // namespace

Command add_interpolate(CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* ip = app.add_subcommand("interpolate", "interpolate values given at points, at queries or on a grid");
  ip->add_option("points", a->points, "the points: " + io::point_formats())->required();
  ip->add_option("values", a->values,
                 "their values, a row a point: text/.csv (one or more a line) or .bin "
                 "(float64)")
      ->required();
  ip->add_option("queries", a->queries, "the query points (or --grid)");
  ip->add_option("--grid", a->grid,
                 "nx,ny[,x0,y0,x1,y1]: the nodes of a grid, row by row from (x0, y0) "
                 "(default box: the points')");
  ip->add_option("--method", a->method, "linear (default), natural (Sibson's natural neighbours) or nearest");
  ip->add_option("--fill", a->fill, "the value outside the convex hull (default nan)");
  ip->add_option("-o,--output", a->output, "output: " + io::values_formats())->required();
  ip->add_option("--threads", a->threads, "threads (0, the default: all hardware threads)");
  ip->add_option("--memory-limit", a->memory_limit, kMemoryLimitHelp);
  return {ip, [a] { return run(*a); }};
}

}  // namespace ridt::tool
