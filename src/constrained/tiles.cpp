// Refinement on threads that gives the same mesh on any number of them (constrained/refine.hpp's
// refine_tiles).
//
// The box of the mesh is cut into a grid of tiles, as many as the mesh's size asks (never the
// threads'). A triangle is a tile's when its three corners lie in the tile; a tile's triangles
// and, beside them, its ghosts (triangles that share an edge with one of its triangles but are
// not its own) are copied into a mesh of their own, with the edges between the two fixed (its
// fence), and refined there as the whole mesh would be (Refiner, with its Fence), but that no
// step may change a ghost: a point whose cavity would take in a ghost (one whose circle holds
// it), a point beyond the fence, a subsegment beside a ghost, are left. Each tile's outcome
// depends on its own triangles alone, so the threads may take the tiles in any order. The tiles
// are then put back, in their order (vertex ids and triangle slots numbered tile by tile). Before
// the tiles, the bad triangles too long for one are mended serially; after them, a grid shifted
// by half a tile takes the triangles near the first one's seams, and refine goes on over the
// whole mesh from the queue of what is still bad: what the fences held back.
//
// Two tiles never share a triangle that either may change: a triangle a step changes has all
// three corners in its tile (a ghost is never changed), and the triangle beyond an edge of the
// cavity, whose link the step rewrites, has two; no triangle has two corners in each of two
// tiles. So the tiles are refined apart and put back without a conflict.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <memory>
#include <new>

#include "constrained/refiner.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"

namespace ridt::detail {
namespace {

// The fence's edges that are no segment's: fixed in a tile's mesh, free again once it is back.
constexpr Constraint kFence = kUnnamed - 1;

// Tiles are some 16,384 triangles of the mesh to refine (or of an area bound's mesh, where that
// is more), in a grid of 2 x 2 to 32 x 32; a mesh for fewer than 2 x 2 is refined whole.
constexpr double kTileTriangles = 16384;
constexpr int kMostSide = 32;
// The shifted grid's tiles take the triangles within a sixteenth of a tile of the first grid's
// seams (and those astride them): room for the seams' cavities, a quarter of the mesh to copy.
constexpr double kBand = 1.0 / 16;

// A grid of side x side tiles over the box, or, shifted by half a tile, of side + 1 x side + 1
// (its tiles astride the first's seams).
struct Grid {
  Extent box;
  int side = 0;
  bool shifted = false;
  int cells() const { return side + (shifted ? 1 : 0); }
  // Where p lies in the unshifted grid, in tiles (x and y).
  std::pair<double, double> at(const Point& p) const {
    return {(p.x - box.x0) / (box.x1 - box.x0) * side, (p.y - box.y0) / (box.y1 - box.y0) * side};
  }
  // The tile that owns triangle (a, b, c): the one its three corners lie in (in the shifted
  // grid, only for a triangle astride a seam of the unshifted one, or a corner of it near one:
  // within kBand of a tile); -1 where none does.
  int owner(const Point& a, const Point& b, const Point& c) const {
    const auto [ax, ay] = at(a);
    const auto [bx, by] = at(b);
    const auto [cx, cy] = at(c);
    const double shift = shifted ? 0.5 : 0.0;
    auto cell = [&](double f) {
      f += shift;
      return f >= 0 ? std::min(cells() - 1, static_cast<int>(f)) : 0;  // (NaN: 0)
    };
    const int k = cell(ax) + cells() * cell(ay);
    if (cell(bx) + cells() * cell(by) != k || cell(cx) + cells() * cell(cy) != k) return -1;
    if (!shifted) return k;
    auto near = [](double f) { return std::fabs(f - std::round(f)) < kBand; };
    auto astride = [](double f, double g, double h) {
      return std::floor(f) != std::floor(g) || std::floor(f) != std::floor(h);
    };
    const bool seam = near(ax) || near(ay) || near(bx) || near(by) || near(cx) || near(cy) || astride(ax, bx, cx) ||
        astride(ay, by, cy);
    return seam ? k : -1;
  }
};

// The grid for m, side 0 where tiles do not apply: with the caller's test or a size field (both
// asked on the calling thread; and a size field's mesh, whose sizes a tile asks in smaller
// batches, comes out 1 to 10 % larger in tiles), a given mesh's regions or a limit on the points
// added.
Grid grid_for(const Cdt& m, const Refinement& r) {
  Grid g;
  if (r.unsuitable || r.sizes || r.given != nullptr || r.max_steiner > 0) return g;
  // The mesh's size: its triangles, or, where more, twice its area over its area bounds, on
  // threads: summed in blocks of a fixed size, then the blocks in order (the same sum, so the
  // same grid, on any number of threads).
  constexpr std::size_t kBlock = 1 << 16;
  std::vector<std::pair<double, double>> part((m.size() + kBlock - 1) / kBlock);
  parallel_for(part.size(), r.threads, 1, [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k)
      for (std::size_t t = k * kBlock; t < std::min<std::size_t>(m.size(), (k + 1) * kBlock); ++t) {
        const auto u = static_cast<TriangleId>(t);
        if (m.at(u, 0) == kNoVertex) continue;
        ++part[k].first;
        double bound = r.max_area;
        if (!m.region.empty() && m.region[t] >= 0)
          if (const double own = r.region_area[static_cast<std::size_t>(m.region[t])]; own > 0)
            bound = bound > 0 ? std::min(bound, own) : own;
        const Point &a = m.pts[m.at(u, 0)], &b = m.pts[m.at(u, 1)], &c = m.pts[m.at(u, 2)];
        if (bound > 0) part[k].second += ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / bound;
      }
  });
  double triangles = 0, bounded = 0;
  for (const auto& [count, area] : part) triangles += count, bounded += area;
  const double estimate = std::max(triangles, bounded);
  // RIDT_TILE_TRIANGLES sets the tiles' size (the tests run small meshes in tiny tiles).
  const char* size = std::getenv("RIDT_TILE_TRIANGLES");
  const double per_tile = size != nullptr && std::atof(size) > 0 ? std::atof(size) : kTileTriangles;
  const double side = std::floor(std::sqrt(estimate / per_tile));
  if (!(side >= 2)) return g;
  g.side = static_cast<int>(std::min<double>(side, kMostSide));
  g.box = extent_of(m.pts);
  if (!(g.box.x1 > g.box.x0 && g.box.y1 > g.box.y0)) g.side = 0;
  return g;
}

// A tile: its triangles' slots in the whole mesh (ascending) and its ghosts' (as copy_out meets
// them), its vertices' ids there (its mesh's vertex i is vertex global[i]; those added come after
// `given`), and its mesh.
struct Tile {
  std::vector<TriangleId> own, ghosts;
  std::vector<VertexId> global;
  VertexId given = 0;
  std::unique_ptr<Cdt> mesh;
  std::vector<std::pair<VertexId, VertexId>> ends;
};

// What each tile of a round reads: the mesh, each triangle's tile (-1: none) and place in it
// (its ghosts' set as they are copied), the chains' corners, and the tiles' share of memory.
struct Round {
  const Cdt& m;
  const Refinement& r;
  const std::vector<std::int32_t>& owner;
  std::vector<std::uint32_t>& place;
  const Extent& box;
  const std::vector<std::uint8_t>& small;
  const std::vector<std::pair<VertexId, VertexId>>& ends;
  std::size_t memory;
};

// Tile k's mesh, copied out of m, with the corners at the ends of its vertices' chains
// (`ends`, there as isolated vertices). `place` holds each of the tile's triangles' place among
// them and gets its ghosts' (a ghost has two corners in the tile: it is no other tile's);
// `local` (kNoVertex throughout) is the calling thread's, given back so. Vertices and ghosts are
// numbered as the tile's triangles meet them, in their order, the input's corners first (so
// below the same number): a tile is copied the same way whoever copies it.
void copy_out(const Round& round, std::int32_t k, std::vector<VertexId>& local, Tile& tile) {
  const Cdt& m = round.m;
  std::vector<std::uint32_t>& place = round.place;
  const std::size_t own = tile.own.size();
  for (const TriangleId t : tile.own)
    for (int i = 0; i < 3; ++i)
      if (const TriangleId n = m.tds.neighbour(t, i);
          n != kNoTriangle && round.owner[n] != k && place[n] == kNoTriangle) {
        place[n] = static_cast<std::uint32_t>(own + tile.ghosts.size());
        tile.ghosts.push_back(n);
      }
  const std::size_t count = own + tile.ghosts.size();
  auto slot = [&](std::size_t i) { return i < own ? tile.own[i] : tile.ghosts[i - own]; };
  auto meet = [&](VertexId v) {
    if (local[v] == kNoVertex) local[v] = 0, tile.global.push_back(v);
  };
  for (std::size_t i = 0; i < count; ++i)
    for (int c = 0; c < 3; ++c)
      if (const VertexId v = m.at(slot(i), c); meet(v), round.ends[v].first != kNoVertex)
        meet(round.ends[v].first), meet(round.ends[v].second);
  std::stable_partition(tile.global.begin(), tile.global.end(), [&](VertexId v) { return v < round.r.corners; });
  tile.given = static_cast<VertexId>(tile.global.size());
  for (VertexId v = 0; v < tile.given; ++v) local[tile.global[v]] = v;
  tile.ends.assign(tile.given, {kNoVertex, kNoVertex});
  for (VertexId v = 0; v < tile.given; ++v)
    if (const auto [a, b] = round.ends[tile.global[v]]; a != kNoVertex) tile.ends[v] = {local[a], local[b]};
  Triangulation t;
  t.triangles.resize(3 * count);
  t.neighbors.resize(3 * count);
  for (std::size_t i = 0; i < count; ++i)
    for (int c = 0; c < 3; ++c) {
      t.triangles[3 * i + c] = local[m.at(slot(i), c)];
      // The neighbour's place in the tile, or none beyond a ghost.
      const TriangleId n = m.tds.neighbour(slot(i), c);
      const bool linked = n != kNoTriangle && (round.owner[n] == k || (i < own && place[n] >= own));
      t.neighbors[3 * i + c] = linked ? static_cast<std::int32_t>(place[n]) : -1;
    }
  std::vector<Point> pts(tile.given);
  for (VertexId v = 0; v < tile.given; ++v) pts[v] = m.pts[tile.global[v]], local[tile.global[v]] = kNoVertex;
  tile.mesh = std::make_unique<Cdt>(std::move(pts), t);
  Cdt& s = *tile.mesh;
  for (std::size_t i = 0; i < count; ++i)
    for (int c = 0; c < 3; ++c)
      s.tds.constraint_array()[3 * i + c] = m.tds.constraint(static_cast<Link>(3 * std::size_t{slot(i)} + c));
  for (std::size_t i = 0; i < own; ++i)
    for (int c = 0; c < 3; ++c)
      if (const auto e = static_cast<Link>(3 * i + c); !s.boundary(e) && s.across(e) >= own && !s.fixed(e))
        s.constrain(e, kFence);
  if (!m.region.empty()) {
    s.region.resize(count);
    for (std::size_t i = 0; i < count; ++i) s.region[i] = m.region[slot(i)];
  }
}

void refine_tile(const Round& round, std::int32_t k, std::vector<VertexId>& local, Tile& tile) {
  const Refinement& r = round.r;
  copy_out(round, k, local, tile);
  Refinement part = r;
  part.corners = static_cast<VertexId>(
      std::partition_point(tile.global.begin(), tile.global.end(), [&](VertexId v) { return v < r.corners; }) -
      tile.global.begin());
  part.memory = round.memory;
  const refining::Fence fence{static_cast<TriangleId>(tile.own.size()),
                              static_cast<TriangleId>(tile.own.size() + tile.ghosts.size()), round.box};
  std::vector<std::uint8_t> small(part.corners);
  for (VertexId v = 0; v < part.corners; ++v) small[v] = round.small[tile.global[v]];
  refining::Refiner refiner(*tile.mesh, part, {std::move(tile.ends), std::move(small)}, &fence);
  refiner.run();
  tile.ends = std::move(refiner.take_chains().ends);
}

// Tile `tile` put back into m: its added vertices as vertices `vertices` on (m.pts has room),
// its triangles into its own slots and then slots `slots` on (grown), linked to its ghosts
// (whose links back are set), the fence's edges free again; `ends` gets the chains of the
// vertices added. Tiles put back side by side write apart: each its own vertices and slots, and
// the links back of its own ghosts (a ghost has two corners in its tile, so it is no other's).
void put_back(Cdt& m, Tile& tile, VertexId vertices, TriangleId slots,
              std::vector<std::pair<VertexId, VertexId>>& ends) {
  const Cdt& s = *tile.mesh;
  for (VertexId v = tile.given; v < s.pts.size(); ++v) {
    tile.global.push_back(vertices + (v - tile.given));
    m.pts[tile.global.back()] = s.pts[v];
  }
  for (VertexId v = tile.given; v < s.pts.size(); ++v)
    if (const auto [a, b] = tile.ends[v]; a != kNoVertex) ends[tile.global[v]] = {tile.global[a], tile.global[b]};
  const std::size_t own = tile.own.size(), fence = own + tile.ghosts.size();
  auto slot = [&](std::size_t i) {
    return i < own ? tile.own[i] : i < fence ? tile.ghosts[i - own] : slots + static_cast<TriangleId>(i - fence);
  };
  std::vector<VertexId>& v = m.tds.vertex_array();
  std::vector<Link>& link = m.tds.link_array();
  std::vector<Constraint>& constraint = m.tds.constraint_array();
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (i == own) i = fence;  // the ghosts stay as they are
    if (i >= s.size()) break;
    const std::size_t g = slot(i);
    for (int c = 0; c < 3; ++c) {
      const std::size_t e = 3 * g + c;
      v[e] = tile.global[s.at(static_cast<TriangleId>(i), c)];
      m.corner[v[e]] = static_cast<std::uint32_t>(e);
      const Link l = s.tds.link(static_cast<TriangleId>(i), c);
      const Constraint kept = s.tds.constraint(static_cast<Link>(3 * i + c));
      constraint[e] = kept == kFence ? kFree : kept;
      if (l == kNoLink) {
        link[e] = kNoLink;
        continue;
      }
      const std::size_t n = triangle_of(l);
      link[e] = static_cast<Link>(3 * slot(n) + edge_of(l));
      if (n >= own && n < fence) link[link[e]] = static_cast<Link>(e);
    }
    if (!m.region.empty()) m.region[g] = s.region[i];
  }
  tile.mesh.reset();
}

// Room in v for n items, and an eighth more where memory allows (the whole mesh's refinement
// goes on from there).
template <class T>
void room(std::vector<T>& v, std::size_t n) {
  if (n <= v.capacity()) return;
  try {
    v.reserve(n + n / 8);
  } catch (const std::bad_alloc&) {
    v.reserve(n);
  }
}

// v grown to n items of `fill` (room() made first), its new pages made present on `threads`
// together.
template <class T>
void grow(std::vector<T>& v, std::size_t n, const T& fill, unsigned threads) {
  if (n <= v.size()) return;
  room(v, n);
  make_present(v.data() + v.size(), (n - v.size()) * sizeof(T), threads);
  v.resize(n, fill);
}

// body(k, w) for each tile k, on up to `threads` threads (w: which), each taking the next tile left; the
// first exception, by tile, rethrown once all have ended.
template <class Body>
void each_tile(std::size_t tiles, unsigned threads, Body&& body) {
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> error(tiles);
  on_threads(std::min<unsigned>(thread_count(threads), static_cast<unsigned>(tiles)), [&](unsigned w) {
    for (std::size_t k; (k = next.fetch_add(1)) < tiles;) try {
        body(k, w);
      } catch (...) {
        error[k] = std::current_exception();
      }
  });
  for (const std::exception_ptr& e : error)
    if (e) std::rethrow_exception(e);
}

// Every tile refined put back into m (put_back), its vertices and triangles numbered tile by
// tile after m's.
void put_all_back(Cdt& m, std::vector<Tile>& tile, unsigned threads, std::vector<std::pair<VertexId, VertexId>>& ends) {
  const std::size_t tiles = tile.size();
  std::vector<VertexId> vertices(tiles);
  std::vector<TriangleId> slots(tiles);
  auto count = static_cast<VertexId>(m.pts.size());
  TriangleId top = m.tds.slots();
  for (std::size_t k = 0; k < tiles; ++k) {
    vertices[k] = count, slots[k] = top;
    if (const Cdt* s = tile[k].mesh.get()) {
      count += static_cast<VertexId>(s->pts.size() - tile[k].given);
      top += static_cast<TriangleId>(s->size() - tile[k].own.size() - tile[k].ghosts.size());
    }
  }
  // All the room first: where memory refuses it, the tiles are dropped and m is as it was.
  try {
    room(m.pts, count), room(m.corner, count), room(ends, count);
    m.tds.reserve(top);
    if (!m.region.empty()) room(m.region, top);
  } catch (const std::bad_alloc&) {
    return;
  }
  grow(m.pts, count, Point{}, threads);
  grow(m.corner, count, kNoTriangle, threads);
  m.tds.grow(top - m.tds.slots(), threads);
  if (!m.region.empty()) grow(m.region, top, -1, threads);
  grow(ends, count, {kNoVertex, kNoVertex}, threads);
  each_tile(tiles, threads, [&](std::size_t k, unsigned) {
    if (tile[k].mesh) put_back(m, tile[k], vertices[k], slots[k], ends);
  });
}

// One round: each tile of `grid` refined on its own, on threads, and put back; `ends` kept.
void tile_round(Cdt& m, const Refinement& r, const Grid& grid, const std::vector<std::uint8_t>& small,
                std::vector<std::pair<VertexId, VertexId>>& ends) {
  const auto tiles = static_cast<std::size_t>(grid.cells()) * grid.cells();
  // Each triangle's tile (on threads), then each tile's triangles in the order of their slots.
  std::vector<std::int32_t> owner(m.size(), -1);
  std::vector<std::uint32_t> place(m.size(), kNoTriangle);
  parallel_for(m.size(), r.threads, 65536, [&](std::size_t from, std::size_t to) {
    for (std::size_t t = from; t < to; ++t) {
      const auto u = static_cast<TriangleId>(t);
      if (m.at(u, 0) == kNoVertex) continue;
      const Point &a = m.pts[m.at(u, 0)], &b = m.pts[m.at(u, 1)], &c = m.pts[m.at(u, 2)];
      owner[t] = grid.owner(a, b, c);
    }
  });
  std::vector<Tile> tile(tiles);
  for (TriangleId t = 0; t < m.size(); ++t)
    if (owner[t] >= 0) {
      std::vector<TriangleId>& own = tile[static_cast<std::size_t>(owner[t])].own;
      place[t] = static_cast<std::uint32_t>(own.size());
      own.push_back(t);
    }
  // The tiles' copies come beside the mesh: each gets half of what its share would be.
  const Round round{m,        r,     owner, place,
                    grid.box, small, ends,  (r.memory != 0 ? r.memory : available_memory()) / (2 * tiles) + 1};
  const unsigned threads = std::min<unsigned>(thread_count(r.threads), static_cast<unsigned>(tiles));
  std::vector<std::vector<VertexId>> local(threads);
  // A tile memory cannot hold is left as it is, for the whole mesh (which stops with a warning
  // where it too runs short).
  each_tile(tiles, threads, [&](std::size_t k, unsigned w) {
    if (tile[k].own.empty()) return;
    try {
      local[w].resize(m.pts.size(), kNoVertex);
      refine_tile(round, static_cast<std::int32_t>(k), local[w], tile[k]);
    } catch (const std::bad_alloc&) {
      tile[k].mesh.reset();
      std::fill(local[w].begin(), local[w].end(), kNoVertex);  // (as copy_out would have left it)
    }
  });
  local = {};
  put_all_back(m, tile, threads, ends);
}

}  // namespace

Chains refine_tiles(Cdt& m, const Refinement& r) {
  Grid grid = grid_for(m, r);
  if (grid.side == 0) return {};
  // First the bad triangles too large for tiles (an edge above a quarter of a tile's side:
  // those of a coarse mesh with an area bound, or across a wide region), mended serially.
  Refinement large = r;
  large.longer_than = std::min(grid.box.x1 - grid.box.x0, grid.box.y1 - grid.box.y0) / grid.side / 4;
  refining::Refiner first(m, large);
  first.run();
  Chains chains = first.take_chains();
  // The grid, then the grid shifted by half a tile: the second round's tiles take the first's
  // seams in, and little is left for the whole mesh.
  for (const bool shifted : {false, true}) {
    grid.shifted = shifted;
    tile_round(m, r, grid, chains.small, chains.ends);
  }
  return chains;
}

}  // namespace ridt::detail
