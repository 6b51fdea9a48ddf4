// The partition method's second pass over the points put off, and what is left to one thread
// (partition.hpp says how the method works).
#include <bit>
#include <numeric>
#include <vector>

#include "methods/partition.hpp"

namespace ridt::detail {

template <bool kLattice>
std::size_t Partition<kLattice>::prepare(Task& t, std::size_t taken) {
  t.split = t.todo.size();  // none found: every point is put off
  for (std::size_t k = 0; k < std::min(t.todo.size(), kStartTries); ++k) {
    const std::size_t c = (t.todo.size() / 2 + k) % t.todo.size();
    last_ = tds_.walk(t.todo[c].near != kNoTriangle ? t.todo[c].near : last_, t.todo[c].p);
    if (deep_in(t.range, last_, workers_[0].seen)) {
      t.start = last_;
      t.split = c;
      break;
    }
  }
  if (t.split == t.todo.size()) {
    t.deferred = std::move(t.todo);
    t.todo.clear();
    t.split = 0;
  }
  const std::size_t need = 2 * t.todo.size();
  const std::size_t listed = std::min(need, free_.size() - taken);
  t.pool.list = free_.data() + taken;
  t.pool.listed = listed;
  t.pool.next = tds_.grow(static_cast<TriangleId>(need - listed));
  t.pool.end = t.pool.next + static_cast<TriangleId>(need - listed);
  return listed;
}

namespace {

// The cells of CellRange's grid along the grid's Hilbert curve: the curve of order 16 passes
// through the squares of 2^(16 - k) units in the order of the curve of order k, so the top 2k
// bits of a square's corner's key are its place on the grid's curve.
const std::vector<std::uint16_t>& cells_along_the_curve() {
  constexpr int kSide = CellRange::kSide;
  constexpr int kBits = std::bit_width(unsigned{kSide - 1});
  static_assert(std::has_single_bit(unsigned{kSide}) && 2 * kBits <= 16);
  static const std::vector<std::uint16_t> order = [] {
    std::vector<std::uint16_t> cells(kSide * kSide);
    for (std::uint32_t y = 0; y < kSide; ++y)
      for (std::uint32_t x = 0; x < kSide; ++x)
        cells[hilbert_key(x << (16 - kBits), y << (16 - kBits)) >> (32 - 2 * kBits)] =
            static_cast<std::uint16_t>(y * kSide + x);
    return cells;
  }();
  return order;
}

}  // namespace

template <bool kLattice>
auto Partition<kLattice>::second_pass(std::vector<PutOff> left) -> std::vector<PutOff> {
  const Vertices& v = tds_.vertices();
  const CellRange grid = CellRange::grid(v.data(), n_, left);
  std::vector<std::uint32_t> count(CellRange::kSide * CellRange::kSide);
  for (const PutOff& x : left) ++count[static_cast<std::size_t>(grid.cell(v[x.p]))];
  // Runs of cells along the curve, each with about an equal share of the points.
  const std::size_t regions = 2 * std::size_t{threads_};
  owner_.resize(count.size());
  std::size_t before = 0;
  for (const std::uint16_t c : cells_along_the_curve()) {
    owner_[c] = static_cast<std::uint16_t>(std::min(regions - 1, before * regions / left.size()));
    before += count[c];
  }
  tasks_.assign(regions, Task{});
  for (std::size_t j = 0; j < regions; ++j) {
    tasks_[j].range = grid;
    tasks_[j].range.owner = owner_.data();
    tasks_[j].range.id = static_cast<std::uint16_t>(j);
  }
  std::sort(left.begin(), left.end());  // curve order: the round is sorted by key
  for (PutOff x : left) {
    Task& t = tasks_[owner_[static_cast<std::size_t>(grid.cell(v[x.p]))]];
    // A hint the region does not own may change under another thread: read it now or never.
    if (!tds_.live(x.near) || !owns(t.range, x.near)) x.near = kNoTriangle;
    t.todo.push_back(x);
  }
  // Before the threads start: each region's start, and slots for all its points.
  std::size_t taken = 0;
  for (Task& t : tasks_) taken += prepare(t, taken);
  // The largest regions first: a large one taken last would leave the other threads waiting.
  std::vector<std::size_t> largest_first(tasks_.size());
  std::iota(largest_first.begin(), largest_first.end(), std::size_t{0});
  std::stable_sort(largest_first.begin(), largest_first.end(),
                   [&](std::size_t a, std::size_t b) { return tasks_[a].todo.size() > tasks_[b].todo.size(); });
  std::atomic<std::size_t> next{0};
  run_threads([&](unsigned i) {
    // relaxed: the counter only hands out each region once; the joins order the rest.
    for (std::size_t j; (j = next.fetch_add(1, std::memory_order_relaxed)) < tasks_.size();)
      if (!insert_task(i, tasks_[largest_first[j]])) return;
  });
  // What the pools did not hand out is free now; the free slots they took are used.
  std::vector<TriangleId> unused;
  left.clear();
  for (Task& t : tasks_) {
    unused.insert(unused.end(), t.pool.list, t.pool.list + t.pool.listed);
    for (; t.pool.next < t.pool.end; ++t.pool.next) {
      tds_.free_slot(t.pool.next);
      unused.push_back(t.pool.next);
    }
    left.insert(left.end(), t.deferred.begin(), t.deferred.end());
  }
  unused.insert(unused.end(), free_.begin() + static_cast<std::ptrdiff_t>(taken), free_.end());
  free_ = std::move(unused);
  tasks_.clear();
  return left;
}

template <bool kLattice>
bool Partition<kLattice>::insert_task(unsigned i, Task& t) {
  Worker& w = workers_[i];
  auto insert = [&](const PutOff& x) {
    w.last = nearer(w.last, x);  // the hint is its region's, and so still (PutOff)
    return try_insert(i, t.range, x.p, t.deferred, t.pool);
  };
  w.last = t.start;
  for (std::size_t k = t.split; k < t.todo.size(); ++k)
    if (!insert(t.todo[k])) return false;
  w.last = t.start;
  for (std::size_t k = t.split; k-- > 0;)
    if (!insert(t.todo[k])) return false;
  return true;
}

template <bool kLattice>
void Partition<kLattice>::release(TriangleId first, TriangleId end) {
  for (TriangleId t = first; t < end; ++t) {
    tds_.free_slot(t);
    free_.push_back(t);
  }
}

template <bool kLattice>
void Partition<kLattice>::insert_alone(const std::vector<PutOff>& list) {
  const auto t0 = Clock::now();
  Worker& w = workers_[0];
  SlotPool pool;
  pool.list = free_.data();
  pool.listed = std::min(free_.size(), 2 * list.size());
  const std::size_t listed = pool.listed;
  const std::size_t grown = 2 * list.size() - pool.listed;
  pool.next = tds_.grow(static_cast<TriangleId>(grown));
  pool.end = pool.next + static_cast<TriangleId>(grown);
  for (const auto [p, near] : list) {
    progress_(done_++);
    last_ = nearer(last_, {p, tds_.live(near) ? near : kNoTriangle});
    if (const VertexId hit = tds_.insert<kLattice>(p, last_, w.scratch, pool); hit != kNoVertex)
      w.duplicates.push_back({p, hit});
    else
      ++w.stats.points;
  }
  // The pool takes its listed slots from the back: those it left, at the front of its part
  // of the list, stay free, and its range is given back.
  free_.erase(free_.begin() + static_cast<std::ptrdiff_t>(pool.listed),
              free_.begin() + static_cast<std::ptrdiff_t>(listed));
  pool.listed = 0;
  tds_.give_back(pool);
  stats_.alone += list.size();
  stats_.time_alone_s += seconds(Clock::now() - t0);
}

// The second pass's members, for both forms of the predicates; the first pass's are made where
// insert_partition uses them (partition.cpp).
template class Partition<true>;
template class Partition<false>;

}  // namespace ridt::detail
