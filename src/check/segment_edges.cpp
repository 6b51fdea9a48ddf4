// edges_along_segments (check/on_segment.hpp): a mesh's segment edges found from the input's
// segments, for a mesh whose files do not name them.
#include <algorithm>

#include "check/on_segment.hpp"
#include "runtime/parallel.hpp"

namespace ridt::detail {
namespace {

// What a thread follows segments with: a stamp a vertex (the segment that saw it last), the
// points still to visit, the edges found.
struct Scratch {
  std::vector<std::uint32_t> seen;
  std::uint32_t stamp = 0;
  std::vector<VertexId> todo, edges;
  std::vector<std::size_t> unfinished;  // segments whose end b was not reached from a
};

class Follow {
 public:
  Follow(std::span<const Point> pts, const Adjacency& sides, std::span<const VertexId> segments, std::size_t input,
         const std::vector<std::uint8_t>& used, const Standing& stand, long double least)
      : pts_(pts), sides_(sides), segments_(segments), input_(input), least_(least), used_(used), stand_(stand) {}

  // Segment s followed from its end a. Where b is not reached so, s is left for through_holes.
  void from_a(std::size_t s, Scratch& scratch) const {
    VertexId a = 0, b = 0;
    if (!ends(s, a, b)) return;
    const OnSegment near(pts_, a, b, input_, least_);
    ++scratch.stamp;
    from(a, near, scratch);
    if (scratch.seen[b] != scratch.stamp) scratch.unfinished.push_back(s);
  }

  // Segment s, which runs through a hole or the exterior, followed from a, from b, and, where
  // `boundary` is given, from every boundary vertex on it.
  void through_holes(std::size_t s, const std::vector<std::pair<double, VertexId>>* boundary, Scratch& scratch) const {
    VertexId a = 0, b = 0;
    if (!ends(s, a, b)) return;
    const OnSegment near(pts_, a, b, input_, least_);
    ++scratch.stamp;
    from(a, near, scratch);
    from(b, near, scratch);
    if (boundary == nullptr) return;
    for (auto it = std::lower_bound(boundary->begin(), boundary->end(), std::pair{near.x0, VertexId{0}});
         it != boundary->end() && it->first <= near.x1; ++it)
      if (near(it->second)) from(it->second, near, scratch);
  }

  // The used vertices on the boundary (a side of one triangle alone: a neighbour listed once),
  // by x.
  std::vector<std::pair<double, VertexId>> boundary(unsigned threads) const {
    InOrder<std::vector<std::pair<double, VertexId>>> parts;
    parallel_for(pts_.size(), threads, 1 << 16, [&](std::size_t first, std::size_t last) {
      std::vector<std::pair<double, VertexId>> part;
      for (std::size_t v = first; v < last; ++v) {
        const std::span<const VertexId> n = sides_[static_cast<VertexId>(v)];
        if (used_[v] &&
            std::any_of(n.begin(), n.end(), [&](VertexId w) { return std::count(n.begin(), n.end(), w) == 1; }))
          part.emplace_back(pts_[v].x, static_cast<VertexId>(v));
      }
      parts.put(first, std::move(part));
    });
    std::vector<std::pair<double, VertexId>> out;
    for (const auto& part : parts.take()) out.insert(out.end(), part.begin(), part.end());
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  // Segment s's ends as the vertices they stand for; false where it has none to follow (an end
  // out of range, which check_mesh reports, or both at one place).
  bool ends(std::size_t s, VertexId& a, VertexId& b) const {
    if (segments_[2 * s] >= input_ || segments_[2 * s + 1] >= input_) return false;
    a = stand_(segments_[2 * s]), b = stand_(segments_[2 * s + 1]);
    return a != b && !(pts_[a] == pts_[b]);
  }

  // Depth first from `start` through the points on the segment, each edge between two of them
  // onto the scratch's edges.
  void from(VertexId start, const OnSegment& near, Scratch& scratch) const {
    if (scratch.seen[start] == scratch.stamp || !used_[start]) return;
    scratch.seen[start] = scratch.stamp;
    scratch.todo.assign(1, start);
    while (!scratch.todo.empty()) {
      const VertexId v = scratch.todo.back();
      scratch.todo.pop_back();
      for (const VertexId w : sides_[v]) {
        if (!near(w)) continue;
        if (v < w) scratch.edges.push_back(v), scratch.edges.push_back(w);
        if (scratch.seen[w] != scratch.stamp) scratch.seen[w] = scratch.stamp, scratch.todo.push_back(w);
      }
    }
  }

  std::span<const Point> pts_;
  const Adjacency& sides_;
  std::span<const VertexId> segments_;
  std::size_t input_;
  long double least_;
  const std::vector<std::uint8_t>& used_;
  const Standing& stand_;
};

}  // namespace

std::vector<VertexId> edges_along_segments(std::span<const Point> pts, const Adjacency& sides,
                                           std::span<const VertexId> segments, std::size_t whole,
                                           std::size_t input_points, const std::vector<std::uint8_t>& used,
                                           const Standing& stand, long double least, unsigned threads) {
  const Follow follow(pts, sides, segments, input_points, used, stand, least);
  const std::size_t count = segments.size() / 2;
  InOrder<Scratch> done;
  parallel_for(count, threads, 1 << 12, [&](std::size_t first, std::size_t last) {
    Scratch scratch;
    scratch.seen.assign(pts.size(), 0);
    for (std::size_t s = first; s < last; ++s) follow.from_a(s, scratch);
    done.put(first, std::move(scratch));
  });
  std::vector<Scratch> parts = done.take();
  std::vector<std::size_t> unfinished;
  for (const Scratch& part : parts) unfinished.insert(unfinished.end(), part.unfinished.begin(), part.unfinished.end());
  // Segments through holes (rare: on one thread), and the others, which need be followed only
  // from their ends.
  std::vector<std::pair<double, VertexId>> boundary;
  if (std::any_of(unfinished.begin(), unfinished.end(), [&](std::size_t s) { return s < whole; }))
    boundary = follow.boundary(threads);
  for (const std::size_t s : unfinished) follow.through_holes(s, s < whole ? &boundary : nullptr, parts.front());
  std::vector<std::pair<VertexId, VertexId>> edges;
  for (const Scratch& part : parts)
    for (std::size_t k = 0; k < part.edges.size(); k += 2) edges.emplace_back(part.edges[k], part.edges[k + 1]);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<VertexId> flat;
  flat.reserve(2 * edges.size());
  for (const auto& [u, w] : edges) flat.push_back(u), flat.push_back(w);
  return flat;
}

}  // namespace ridt::detail
