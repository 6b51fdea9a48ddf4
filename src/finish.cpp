// Fig. 4, line 24: remove the bounding vertices and everything incident to them; then number
// the remaining triangles compactly, give neighbours across the hull as -1, trace the hull and
// resolve duplicates so the output names the smallest input index of each group of equal points.
#include <algorithm>
#include <numeric>
#include <thread>
#include <unordered_map>

#include "driver.hpp"

namespace ridt::detail {
void canonicalize(Triangulation& out) {
  const std::size_t count = out.size();
  auto& tv = out.triangles;
  auto& tn = out.neighbors;
  for (std::size_t t = 0; t < count; ++t) {
    VertexId* v = &tv[3 * t];
    std::int32_t* n = &tn[3 * t];
    const int s = v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2);
    std::rotate(v, v + s, v + 3);
    std::rotate(n, n + s, n + 3);
  }
  // Sorted by first vertex with a counting sort (the first vertex of a triangle is now its
  // smallest, and each vertex is first in some two triangles), then each group by the other
  // two vertices: linear time, where a comparison sort through the indices missed the cache
  // at every step.
  VertexId first_max = 0;
  for (std::size_t t = 0; t < count; ++t) first_max = std::max(first_max, tv[3 * t]);
  std::vector<std::uint32_t> start(count > 0 ? std::size_t{first_max} + 2 : 1, 0);
  for (std::size_t t = 0; t < count; ++t) ++start[tv[3 * t] + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::uint32_t> order(count);
  // start[a] runs to the end of group a while it is filled, then moves back one place.
  for (std::size_t t = 0; t < count; ++t) order[start[tv[3 * t]]++] = static_cast<std::uint32_t>(t);
  std::copy_backward(start.begin(), start.end() - 1, start.end());
  start[0] = 0;
  for (std::size_t a = 0; a + 1 < start.size(); ++a)
    if (start[a + 1] - start[a] > 1)
      std::sort(order.begin() + start[a], order.begin() + start[a + 1], [&](std::uint32_t x, std::uint32_t y) {
        return tv[3 * x + 1] < tv[3 * y + 1] || (tv[3 * x + 1] == tv[3 * y + 1] && tv[3 * x + 2] < tv[3 * y + 2]);
      });
  std::vector<std::int32_t> rank(count);
  for (std::size_t i = 0; i < count; ++i) rank[order[i]] = static_cast<std::int32_t>(i);
  std::vector<VertexId> v2(3 * count);
  std::vector<std::int32_t> n2(3 * count);
  for (std::size_t i = 0; i < count; ++i)
    for (int k = 0; k < 3; ++k) {
      v2[3 * i + k] = tv[3 * order[i] + k];
      const std::int32_t nb = tn[3 * order[i] + k];
      n2[3 * i + k] = nb < 0 ? kNoNeighbor : rank[nb];
    }
  tv.swap(v2);
  tn.swap(n2);
}

Triangulation finish(Kernel& kernel, const std::vector<std::uint32_t>& input_index,
                     const std::vector<DuplicateHit>& duplicates, const Options& options,
                     unsigned threads) {
  Triangulation out;
  const std::uint32_t n = kernel.n();
  TriangleStore& tris = kernel.triangles_for_finish();
  const std::uint32_t records = tris.size();

  // Duplicates: the smallest input index of each group stands for all of them.
  std::unordered_map<VertexId, VertexId> keep;  // mesh vertex -> standing index
  for (const DuplicateHit& d : duplicates) {
    const VertexId v = input_index[d.vertex];
    auto [it, fresh] = keep.try_emplace(v, v);
    it->second = std::min(it->second, input_index[d.dropped]);
  }
  for (const DuplicateHit& d : duplicates) {
    const VertexId v = input_index[d.vertex], dropped = input_index[d.dropped];
    const VertexId kept = keep[v];
    if (dropped != kept) out.duplicates.push_back({dropped, kept});
    if (v != kept) out.duplicates.push_back({v, kept});
  }
  std::sort(out.duplicates.begin(), out.duplicates.end(),
            [](const Duplicate& a, const Duplicate& b) { return a.dropped < b.dropped; });
  out.duplicates.erase(std::unique(out.duplicates.begin(), out.duplicates.end(),
                                   [](const Duplicate& a, const Duplicate& b) {
                                     return a.dropped == b.dropped;
                                   }),
                       out.duplicates.end());
  for (auto it = keep.begin(); it != keep.end();)
    it = it->first == it->second ? keep.erase(it) : std::next(it);
  auto standing = [&](VertexId mesh_vertex) {
    const VertexId v = input_index[mesh_vertex];
    if (keep.empty()) return v;
    const auto it = keep.find(v);
    return it == keep.end() ? v : it->second;
  };

  // The first two passes run on `threads` threads, each over its own range of records.
  const unsigned workers = std::max(1u, std::min(threads, records / 65536 + 1));
  auto range = [&](unsigned w) {
    return std::pair<TriangleId, TriangleId>(TriangleId(std::uint64_t{records} * w / workers),
                                             TriangleId(std::uint64_t{records} * (w + 1) / workers));
  };
  auto in_parallel = [&](auto&& body) {
    std::vector<std::jthread> pool;
    for (unsigned w = 1; w < workers; ++w) pool.emplace_back(body, w);
    body(0u);
  };  // the pool joins on leaving

  // Ids 1 .. kMaxOwner are never written (mesh.hpp).
  auto unused = [](TriangleId t) { return t != 0 && t < kFirstChild; };
  // Pass 1: the child links are dead now; a kept triangle's link becomes its new id + 1.
  auto kept = [&](const Triangle& r) {
    return is_leaf(r.child) && r.v[0] < n && r.v[1] < n && r.v[2] < n;
  };
  std::vector<std::uint32_t> first_id(workers + 1, 0);
  std::vector<std::uint64_t> made(workers, 0);  // records that are triangles (DAG nodes)
  in_parallel([&](unsigned w) {
    std::uint32_t c = 0;
    std::uint64_t m = 0;
    for (TriangleId t = range(w).first; t < range(w).second; ++t) {
      if (unused(t)) continue;
      c += kept(tris[t]);
      m += tris[t].v[0] != kNone;
    }
    first_id[w + 1] = c;
    made[w] = m;
  });
  for (unsigned w = 0; w < workers; ++w) first_id[w + 1] += first_id[w];
  const std::uint32_t count = first_id[workers];
  in_parallel([&](unsigned w) {
    std::uint32_t id = first_id[w];
    for (TriangleId t = range(w).first; t < range(w).second; ++t) {
      if (unused(t)) continue;
      Triangle& r = tris[t];
      r.child = kept(r) ? ++id : 0;
    }
  });

  // Pass 2, in place: a kept record's vertices become the input indices that stand for them,
  // its neighbours their new ids + 1 (0 across the hull), and its hull edges are noted.
  std::vector<std::vector<std::pair<VertexId, VertexId>>> hull_parts(workers);
  in_parallel([&](unsigned w) {
    // The records are read in order, their neighbours and the input numbers of their
    // vertices at random: prefetch those of a record kAhead places on, so the misses overlap.
    // Only this worker's records are rewritten here; from the others it reads child words.
    constexpr TriangleId kAhead = 64;
    const auto [begin, end] = range(w);
    for (TriangleId t = begin; t < end; ++t) {
      if (unused(t)) continue;
      if (t + kAhead < end && !unused(t + kAhead)) {
        const Triangle& a = tris[t + kAhead];
        if (a.child != 0) {
          for (const TriangleId nb : a.n)
            if (nb != kNone) tris.prefetch(nb);
          for (const VertexId v : a.v) __builtin_prefetch(&input_index[v]);
        }
      }
      Triangle& r = tris[t];
      if (r.child == 0) continue;
      VertexId v[3];
      TriangleId nid[3];
      for (int i = 0; i < 3; ++i) {
        v[i] = standing(r.v[i]);
        nid[i] = r.n[i] == kNone ? 0 : tris[r.n[i]].child;
      }
      for (int i = 0; i < 3; ++i) {
        if (nid[i] == 0) hull_parts[w].emplace_back(v[next(i)], v[prev(i)]);
        r.v[i] = v[i];
        r.n[i] = nid[i];
      }
    }
  });

  // Pass 3: the kept records, copied out in order (the order of their new ids), each chunk
  // freed once copied. The output is reserved, not filled, so its pages are first touched
  // as it grows: with the chunks given back meanwhile, the peak is the records' and not the
  // records' and the output's together. The points are no longer needed (but for the finite
  // bounding triangle's check below): their copy goes first.
  if (options.bounding == Bounding::Symbolic) kernel.release_points();
  out.triangles.reserve(3 * std::size_t{count});
  out.neighbors.reserve(3 * std::size_t{count});
  {
    constexpr std::size_t kBlock = 4096;  // triangles a block
    std::vector<VertexId> vs(3 * kBlock);
    std::vector<std::int32_t> ns(3 * kBlock);
    std::size_t k = 0;  // entries in the block
    auto flush = [&] {
      out.triangles.insert(out.triangles.end(), vs.begin(), vs.begin() + k);
      out.neighbors.insert(out.neighbors.end(), ns.begin(), ns.begin() + k);
      k = 0;
    };
    for (TriangleId t = 0; t < records; ++t) {
      if (!unused(t)) {
        const Triangle& r = tris[t];
        if (r.child != 0) {
          for (int i = 0; i < 3; ++i, ++k) {
            vs[k] = r.v[i];
            ns[k] = r.n[i] == 0 ? kNoNeighbor : static_cast<std::int32_t>(r.n[i] - 1);
          }
          if (k == vs.size()) flush();
        }
      }
      if (((t + 1) & (TriangleStore::kChunkSize - 1)) == 0 || t + 1 == records) {
        flush();
        tris.release_chunk(t >> TriangleStore::kChunkBits);
      }
    }
  }
  std::vector<std::pair<VertexId, VertexId>> hull_edges;
  for (const auto& part : hull_parts) hull_edges.insert(hull_edges.end(), part.begin(), part.end());

  // The hull: follow the boundary edges (counter-clockwise: the interior is on their left)
  // from the smallest vertex index.
  if (!hull_edges.empty()) {
    std::sort(hull_edges.begin(), hull_edges.end());
    auto from = [&](VertexId v) {
      auto it = std::lower_bound(hull_edges.begin(), hull_edges.end(), std::pair{v, VertexId{0}});
      return it != hull_edges.end() && it->first == v ? it->second : kNone;
    };
    const VertexId start = hull_edges.front().first;
    VertexId v = start;
    do {
      out.hull.push_back(v);
      v = from(v);
    } while (v != kNone && v != start && out.hull.size() <= hull_edges.size());
  }

  // Stats and warnings.
  Stats& s = out.stats;
  s.points = n;
  s.duplicates = out.duplicates.size();
  s.distinct = n - s.duplicates;
  s.dag_nodes = kernel.history() ? std::accumulate(made.begin(), made.end(), std::uint64_t{0}) : 0;
  if (s.distinct < 3) {
    out.warning = "fewer than three distinct points: no triangle";
  } else if (count == 0 && options.bounding == Bounding::Symbolic) {
    out.warning = "all points are collinear: no triangle";  // else there would be a triangle
  } else if (options.bounding == Bounding::Finite) {
    // The paper's finite bounding triangle can leave a reflex boundary or drop points, or
    // every triangle, when the circle of a thin one holds a bounding vertex.
    std::vector<Point> pts(n);
    for (VertexId v = 0; v < n; ++v) pts[input_index[v]] = kernel.point(v);
    const std::size_t h = out.hull.size();
    if (count == 0) {
      VertexId far = 0;  // a point other than pts[0]
      while (far < n && pts[far] == pts[0]) ++far;
      bool collinear = true;
      for (VertexId v = 0; collinear && v < n; ++v) collinear = orient2d(pts[0], pts[far], pts[v]) == 0;
      if (collinear) {
        out.warning = "all points are collinear: no triangle";
        return out;
      }
    }
    bool convex = h == hull_edges.size();
    for (std::size_t i = 0; convex && i < h; ++i)
      convex = orient2d(pts[out.hull[i]], pts[out.hull[(i + 1) % h]],
                        pts[out.hull[(i + 2) % h]]) >= 0;
    // Euler: a triangulation of all distinct points with h boundary vertices has 2d - 2 - h.
    const bool complete = count == 2 * s.distinct - 2 - h;
    if (!convex || !complete)
      out.warning =
          "finite bounding triangle (k = " + std::to_string(options.k) +
          ") lost convex hull edges: the result is not the Delaunay triangulation of the "
          "points; use the symbolic bounding triangle";
  }
  return out;
}

}  // namespace ridt::detail
