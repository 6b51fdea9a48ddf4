// The one mutable triangulation (tds/tds.hpp): its storage, and the changes that are not the
// hot loops of insertion.
#include "tds/tds.hpp"

#include <new>
#include <string>

#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"

namespace ridt::detail {

Tds::Tds(std::vector<VertexId> v, std::vector<Link> link, TriangleId slots)
    : vertex_store_(std::move(v)), link_store_(std::move(link)), top_(slots) {
  if (link_store_.size() != vertex_store_.size() || 3 * std::size_t{slots} > vertex_store_.size())
    throw std::logic_error("ridt: a triangulation's arrays of unequal or too small sizes");
  refresh();
}

Tds& Tds::operator=(Tds&& o) noexcept {
  growable_ = o.growable_;
  vertex_store_ = std::move(o.vertex_store_);
  link_store_ = std::move(o.link_store_);
  constraints_ = std::move(o.constraints_);
  top_ = o.top_;
  refresh();
  o.refresh();
  o.top_ = 0;
  return *this;
}

Tds Tds::copy() const {
  const std::size_t size = 3 * std::size_t{top_};
  Tds out(std::vector<VertexId>(vertex_store_.begin(), vertex_store_.begin() + static_cast<std::ptrdiff_t>(size)),
          std::vector<Link>(link_store_.begin(), link_store_.begin() + static_cast<std::ptrdiff_t>(size)), top_);
  if (!constraints_.empty())
    out.constraints_.assign(constraints_.begin(), constraints_.begin() + static_cast<std::ptrdiff_t>(size));
  out.growable_ = true;
  return out;
}

Tds Tds::from_neighbours(std::vector<VertexId> triangles, std::vector<std::int32_t> neighbours, unsigned threads) {
  if (neighbours.size() != triangles.size() || triangles.size() % 3 != 0)
    throw std::logic_error("ridt: triangles and neighbours of unequal sizes");
  // In place: slot s's neighbour is read only to write its link (so the slots may be taken in
  // parts side by side). Edge i of t runs x -> y; the neighbour runs it y -> x, as its edge j
  // (found by the vertices, not by its neighbours, which may be links by now). The
  // neighbours' vertices lie anywhere: those some slots on are asked for ahead, so that the
  // misses overlap.
  constexpr std::size_t kAhead = 24;
  std::vector<Link>& links = neighbours;
  parallel_for(triangles.size(), threads, std::size_t{1} << 18, [&](std::size_t from, std::size_t to) {
    for (std::size_t s = from; s < to; ++s) {
      if (s + kAhead < to && neighbours[s + kAhead] >= 0)
        __builtin_prefetch(&triangles[3 * static_cast<std::size_t>(neighbours[s + kAhead])]);
      const std::int32_t n = neighbours[s];
      if (n < 0) {
        links[s] = kNoLink;
        continue;
      }
      const std::size_t t = s / 3, i = s % 3;
      const VertexId x = triangles[3 * t + (i + 1) % 3], y = triangles[3 * t + (i + 2) % 3];
      const std::size_t nb = 3 * static_cast<std::size_t>(n);
      links[s] = kNoLink;
      for (int j = 0; j < 3; ++j)
        if (triangles[nb + next3(j)] == y && triangles[nb + prev3(j)] == x) links[s] = static_cast<Link>(nb + j);
      if (links[s] == kNoLink) throw std::logic_error("ridt: neighbours that share no edge");
    }
  });
  return from_links(std::move(triangles), std::move(links));
}

Tds Tds::from_links(std::vector<VertexId> triangles, std::vector<Link> links) {
  const auto count = static_cast<TriangleId>(triangles.size() / 3);
  Tds tds(std::move(triangles), std::move(links), count);
  tds.growable_ = true;
  return tds;
}

void Tds::use_constraints(bool on, unsigned threads) {
  constraints_.clear();
  if (!on) return constraints_.shrink_to_fit();
  // Fresh pages made present together (runtime/memory.hpp), not faulted in one by one as the
  // fill first writes each.
  const std::size_t size = 3 * std::size_t{top_};
  constraints_.reserve(size);
  make_present(constraints_.data(), size * sizeof(Constraint), threads);
  constraints_.assign(size, kFree);
}

void Tds::reserve(TriangleId end) {
  const std::size_t need = 3 * std::size_t{end};
  if (!growable_) throw std::logic_error("ridt: the triangulation ran out of slots");
  // The slots are added a few at a time, so the capacity grows geometrically; by four, not
  // two: each growth copies the arrays into fresh pages, and refinement, which grows a mesh
  // severalfold, spent a tenth of its time copying and faulting those in. Only the slots asked
  // for are written: the rest of the capacity is address space whose pages are not made
  // present before they are used, so the larger step costs no memory; but it does cost address
  // space, which ulimit -v limits (and available_memory() then counts): by two where four
  // would take more than a quarter of what is left, or is refused; then by what is asked.
  auto roomy = [&] {
    return need <= vertex_store_.capacity() && need <= link_store_.capacity() &&
        (constraints_.empty() || need <= constraints_.capacity());
  };
  if (roomy()) return;
  const std::size_t capacity = vertex_store_.capacity();
  const std::size_t slot_bytes = sizeof(VertexId) + sizeof(Link) + (constraints_.empty() ? 0 : sizeof(Constraint));
  const std::size_t left = available_memory();  // 0 where it cannot be read (asked once a growth: it reads files)
  const bool ample = left == 0 || 4 * capacity * slot_bytes <= left / 4;
  for (const std::size_t step : {ample ? 4 : 2, 2, 0}) {
    if (roomy()) break;
    try {
      const std::size_t room = std::max(need, step * capacity);
      vertex_store_.reserve(room), link_store_.reserve(room);
      if (!constraints_.empty()) constraints_.reserve(room);
    } catch (const std::bad_alloc&) {
      refresh();
      if (step == 0) throw;
    }
  }
  refresh();
}

void Tds::make_room(TriangleId end, unsigned threads) {
  const std::size_t need = 3 * std::size_t{end};
  if (need <= vertex_store_.size()) {
    if (!constraints_.empty() && constraints_.size() < need) constraints_.resize(vertex_store_.size(), kFree);
    return;
  }
  reserve(end);
  // The new pages made present together (a megabyte or more: runtime/memory.hpp), not faulted
  // in one by one as the fill below first writes each.
  auto fresh = [&](auto& v) { make_present(v.data() + v.size(), (need - v.size()) * sizeof(v[0]), threads); };
  fresh(vertex_store_), fresh(link_store_);
  if (!constraints_.empty()) fresh(constraints_);
  vertex_store_.resize(need, kNoVertex);
  link_store_.resize(need, kNoLink);
  if (!constraints_.empty()) constraints_.resize(need, kFree);
  refresh();
}

void Tds::keep_constraints(CavityScratch& s) const {
  if (s.kept.size() < s.edges) s.kept.resize(2 * s.edges);
  for (std::size_t i = 0; i < s.edges; ++i) s.kept[i] = constraints_[static_cast<std::uint32_t>(s.boundary[i].inside)];
}

void Tds::set_fan_constraints(const CavityScratch& s) {
  for (std::size_t i = 0; i < s.edges; ++i) {
    Constraint* c = constraints_.data() + 3 * std::size_t{s.cavity[i]};
    c[0] = s.kept[i], c[1] = c[2] = kFree;
  }
}

void Tds::flip(Link e) {
  const TriangleId t = triangle_of(e), u = triangle_of(link_at(e));
  const int i = edge_of(e), j = edge_of(link_at(e));
  const VertexId p = vertex(t, i), a = vertex(t, next3(i)), b = vertex(t, prev3(i)), d = vertex(u, j);
  const Link ta = link(t, next3(i)), tb = link(t, prev3(i));  // across b-p, p-a
  const Link ub = link(u, next3(j)), ua = link(u, prev3(j));  // across a-d, d-b
  Constraint cta = kFree, ctb = kFree, cub = kFree, cua = kFree;
  if (has_constraints())
    cta = constraint(link_to(t, next3(i))), ctb = constraint(link_to(t, prev3(i))),
    cub = constraint(link_to(u, next3(j))), cua = constraint(link_to(u, prev3(j)));
  const Link t0 = link_to(t, 0), u0 = link_to(u, 0);
  set_vertex(t, 0, p), set_vertex(t, 1, a), set_vertex(t, 2, d);
  set_vertex(u, 0, p), set_vertex(u, 1, d), set_vertex(u, 2, b);
  glue(t0, ub), glue(t0 + 1, u0 + 2), glue(t0 + 2, tb);
  glue(u0, ua), glue(u0 + 1, ta);
  if (has_constraints()) {
    const Constraint ct[3] = {cub, kFree, ctb}, cu[3] = {cua, cta, kFree};
    for (int k = 0; k < 3; ++k) set_constraint(t0 + k, ct[k]), set_constraint(u0 + k, cu[k]);
  }
}

std::array<TriangleId, 3> Tds::split_triangle(TriangleId t, VertexId p, SlotPool& pool) {
  const VertexId a = vertex(t, 0), b = vertex(t, 1), c = vertex(t, 2);
  const Link na = link(t, 0), nb = link(t, 1), nc = link(t, 2);
  Constraint fa = kFree, fb = kFree, fc = kFree;
  if (has_constraints()) fa = constraint(link_to(t, 0)), fb = constraint(link_to(t, 1)), fc = constraint(link_to(t, 2));
  const TriangleId t1 = pool.take(), t2 = pool.take();
  const Link e = link_to(t, 0), e1 = link_to(t1, 0), e2 = link_to(t2, 0);
  set_vertex(t, 0, a), set_vertex(t, 1, b), set_vertex(t, 2, p);
  set_vertex(t1, 0, b), set_vertex(t1, 1, c), set_vertex(t1, 2, p);
  set_vertex(t2, 0, c), set_vertex(t2, 1, a), set_vertex(t2, 2, p);
  glue(e, e1 + 1), glue(e + 1, e2), glue(e1, e2 + 1);
  glue(e + 2, nc), glue(e1 + 2, na), glue(e2 + 2, nb);
  if (has_constraints()) {
    for (const Link f : {e, e1, e2}) set_constraint(f, kFree), set_constraint(f + 1, kFree);
    set_constraint(e + 2, fc), set_constraint(e1 + 2, fa), set_constraint(e2 + 2, fb);
  }
  return {t, t1, t2};
}

std::array<TriangleId, 4> Tds::split_edge(Link e, VertexId p, SlotPool& pool) {
  const TriangleId t = triangle_of(e);
  const int k = edge_of(e);
  const VertexId a = vertex(t, k), x = vertex(t, next3(k)), y = vertex(t, prev3(k));
  const Link n1 = link(t, next3(k)), n2 = link(t, prev3(k)), across = link_at(e);  // across y-a, a-x, x-y
  const bool cons = has_constraints();
  const Constraint fe = cons ? constraint(e) : kFree, f1 = cons ? constraint(link_to(t, next3(k))) : kFree,
                   f2 = cons ? constraint(link_to(t, prev3(k))) : kFree;
  const TriangleId t1 = pool.take();
  const TriangleId u = across == kNoLink ? kNoTriangle : triangle_of(across);
  const TriangleId m1 = u == kNoTriangle ? kNoTriangle : pool.take();
  const Link te = link_to(t, 0), t1e = link_to(t1, 0);
  set_vertex(t, 0, a), set_vertex(t, 1, x), set_vertex(t, 2, p);
  set_vertex(t1, 0, a), set_vertex(t1, 1, p), set_vertex(t1, 2, y);
  if (u == kNoTriangle) {
    set_link(te, kNoLink), set_link(t1e, kNoLink);
  } else {
    const int j = edge_of(across);
    const VertexId d = vertex(u, j);  // u is (d, y, x)
    const Link g1 = link(u, next3(j)), g2 = link(u, prev3(j));  // across x-d, d-y
    const Constraint h1 = cons ? constraint(link_to(u, next3(j))) : kFree,
                     h2 = cons ? constraint(link_to(u, prev3(j))) : kFree;
    const Link ue = link_to(u, 0), me = link_to(m1, 0);
    set_vertex(u, 0, d), set_vertex(u, 1, y), set_vertex(u, 2, p);
    set_vertex(m1, 0, d), set_vertex(m1, 1, p), set_vertex(m1, 2, x);
    glue(te, me), glue(t1e, ue);
    glue(ue + 1, me + 2), glue(ue + 2, g2), glue(me + 1, g1);
    if (cons) {
      set_constraint(ue, fe), set_constraint(ue + 1, kFree), set_constraint(ue + 2, h2);
      set_constraint(me, fe), set_constraint(me + 1, h1), set_constraint(me + 2, kFree);
    }
  }
  glue(te + 1, t1e + 2), glue(te + 2, n2), glue(t1e + 1, n1);
  if (cons) {
    set_constraint(te, fe), set_constraint(te + 1, kFree), set_constraint(te + 2, f2);
    set_constraint(t1e, fe), set_constraint(t1e + 1, f1), set_constraint(t1e + 2, kFree);
  }
  return {t, t1, u, m1};
}

void Tds::give_back(SlotPool& pool) {
  for (; pool.listed > 0; --pool.listed) free_slot(pool.list[pool.listed - 1]);
  if (pool.end == top_) {
    top_ = pool.next;
  } else {
    for (; pool.next < pool.end; ++pool.next) free_slot(pool.next);
  }
  pool.next = pool.end;
}

}  // namespace ridt::detail
