// The partition method's first pass: the threads' stretches, and the handing over of points
// between them (partition.hpp says how the method works).
#include "methods/partition.hpp"

namespace ridt::detail {

template <bool kLattice>
void Partition<kLattice>::run() {
  const VertexId n = tds_.vertices().n();
  const auto t0 = Clock::now();
  for (VertexId b = 0; b < n; b = round_end(b)) {
    const VertexId e = std::min(round_end(b), n);
    if (!cut_among_threads(e - b, threads_)) {
      std::vector<PutOff> all(e - b);
      for (VertexId p = b; p < e; ++p) all[p - b] = {p, kNoTriangle};
      insert_alone(all);
    } else {
      insert_round(b, e);
    }
  }
  const double total = seconds(Clock::now() - t0);
  for (const Worker& w : workers_) add_worker(w, 0.0, 0.0, total, duplicates_, stats_);
}

template <bool kLattice>
void Partition<kLattice>::insert_round(VertexId b, VertexId e) {
  const VertexId m = e - b;
  // Equal stretches of the round, cut where the key changes (points of one key lie in one
  // region); the regions' first keys, the first from 0 and the last round to the end.
  std::vector<VertexId> cut(threads_ + 1);
  cut[0] = b, cut[threads_] = e;
  for (unsigned i = 1; i < threads_; ++i) {
    VertexId c = std::max(cut[i - 1], b + static_cast<VertexId>(std::uint64_t{m} * i / threads_));
    while (c > b && c < e && key_[c] == key_[c - 1]) ++c;
    cut[i] = c;
  }
  std::vector<std::uint32_t> from(threads_);
  from[0] = 0;
  for (unsigned i = 1; i < threads_; ++i) from[i] = cut[i] < e ? key_[cut[i]] : 0xffffffffu;
  // Before the threads start, with the triangulation at rest: each thread's start, and slots for all
  // its points (two a point inserted), from a range for the whole round.
  const TriangleId base = tds_.grow(2 * m);
  const auto anywhere = Tds::kAnywhere;
  std::vector<Stretch> stretch(threads_);
  for (unsigned i = 0; i < threads_; ++i) {
    Worker& w = workers_[i];
    Stretch& s = stretch[i];
    s.a = cut[i], s.b = cut[i + 1];
    s.range =
        region(from[i], i + 1 < threads_ ? std::uint64_t{from[i + 1]} - from[i] : (std::uint64_t{1} << 32) - from[i]);
    w.pool = {nullptr, 0, base + 2 * (s.a - b), base + 2 * (s.b - b)};
    w.giving = true;
    if (s.a < s.b && find_start(anywhere, s.range, s.a, s.b, last_, s.from, w.seen)) {
      s.start = last_;
      w.remaining.store(s.b - s.a, std::memory_order_relaxed);
      w.ask.store(kWorking, std::memory_order_relaxed);
    } else {  // no start: every point is put off, and the thread begins by asking for some
      for (VertexId p = s.a; p < s.b; ++p) w.deferred.push_back({p, kNoTriangle});
      w.remaining.store(0, std::memory_order_relaxed);
      w.ask.store(kIdle, std::memory_order_relaxed);
    }
  }
  run_threads([&](unsigned i) { first_pass(i, stretch[i]); });
  // What no thread inserted: the points put off, and the slots the pools did not hand out.
  std::vector<PutOff> left;
  for (Worker& w : workers_) {
    left.insert(left.end(), w.deferred.begin(), w.deferred.end());
    w.deferred.clear();
    w.spare.emplace_back(w.pool.next, w.pool.end);
    w.pool = SlotPool{};
    for (const auto& [first, end] : w.spare) release(first, end);
    w.spare.clear();
  }
  if (left.size() >= 64 * threads_) {
    const auto t0 = Clock::now();
    left = second_pass(std::move(left));
    stats_.time_second_pass_s += seconds(Clock::now() - t0);
  }
  std::sort(left.begin(), left.end());
  insert_alone(left);
}

template <bool kLattice>
void Partition<kLattice>::first_pass(unsigned i, Stretch s) {
  Worker& w = workers_[i];
  if (s.start != kNoTriangle && !insert_stretch(i, s)) return;
  for (;;) {
    go_idle(w);
    if (!take_from_another(i, s)) return;
    w.giving = true;
    w.remaining.store(s.b - s.a, std::memory_order_relaxed);
    w.ask.store(kWorking, std::memory_order_relaxed);  // only this thread leaves kIdle
    if (!insert_stretch(i, s)) return;
  }
}

template <bool kLattice>
bool Partition<kLattice>::insert_stretch(unsigned i, Stretch& s) {
  Worker& w = workers_[i];
  w.last = s.start;
  bool up = true;
  VertexId next = s.from;  // up: the next point; down: one past it
  for (;;) {
    if (up && next >= s.b) {
      up = false;
      next = s.from;
      if (next <= s.a) break;  // it gave all its points below away
      w.last = s.start;  // a triangle of its own, or one its insertions wrote in the slot
      continue;
    }
    if (!up && next <= s.a) break;
    // acquire: whatever the asker read of a last answer was read before this question.
    if (w.ask.load(std::memory_order_acquire) == kAsked) {
      answer(w, s, up, next);
      continue;  // its stretch may have shrunk to nothing left to try
    }
    const VertexId p = up ? next++ : --next;
    if (!try_insert(i, s.range, p, w.deferred, w.pool)) return false;
    if ((p & 63) == 0)
      w.remaining.store(!w.giving ? 0 : up ? (s.b - next) + (s.from - s.a) : next - s.a, std::memory_order_relaxed);
  }
  return true;
}

template <bool kLattice>
void Partition<kLattice>::answer(Worker& w, Stretch& s, bool up, VertexId next) {
  const VertexId above = up ? s.b - next : 0, below = up ? s.from - s.a : next - s.a;
  const VertexId half = (above + below) / 2;
  // What it gives: the bottom of its points below, or the top of those above, whichever's
  // border lies further from the point it is at, cut where the key changes.
  VertexId a = 0, b = 0;
  if (w.giving) {
    VertexId bottom = s.a + std::min(below, half);
    while (bottom < (up ? s.from : next) && key_[bottom] == key_[bottom - 1]) ++bottom;
    VertexId top = next + above / 2;
    while (top < s.b && key_[top] == key_[top - 1]) ++top;
    const VertexId bottom_gap = next - bottom, top_gap = up ? top - next : 0;
    if (bottom_gap >= top_gap && bottom - s.a >= kMinShare / 2)
      a = s.a, b = bottom;
    else if (top_gap > bottom_gap && s.b - top >= kMinShare / 2)
      a = top, b = s.b;
  }
  bool ok = a < b;
  KeyRange keep = s.range, give = s.range;
  if (ok) {
    const bool bottom = a == s.a;
    const std::uint32_t at = key_[bottom ? b : a];  // the cut's key: the rest's first, or the gift's
    const std::uint64_t offset = static_cast<std::uint32_t>(at - s.range.lo);
    (bottom ? give : keep) = region(s.range.lo, offset);
    (bottom ? keep : give) = region(at, s.range.len - offset);
    // Its next walk starts at w.last, and the walk down at s.start when points below it are
    // left to it: both must stay its own.
    const bool down_left = up && (bottom ? b : s.a) < s.from;
    ok = owns(keep, w.last) && (!down_left || owns(keep, s.start));
  }
  TriangleId t = ok ? w.last : kNoTriangle;
  VertexId from = 0;
  // From where its next walk starts, along a walk to the part it gives; else, where the region's
  // shape blocks that walk, from a triangle deep in the part found by a search through its
  // region.
  const auto held = own_edges(s.range);
  if (ok && !find_start(held, give, a, b, t, from, w.seen)) {
    t = reach(s.range, give, w.last, w.seen);
    ok = t != kNoTriangle && find_start(held, give, a, b, t, from, w.seen);
  }
  if (!ok) {
    w.giving = false;  // it will not be asked again for this stretch
    w.remaining.store(0, std::memory_order_relaxed);
    w.ask.store(kRefused, std::memory_order_release);
    return;
  }
  w.given = {a, b, from, give, t};
  w.pool.end -= 2 * (b - a);  // its pool holds two slots for each point it has yet to try
  w.given_slots = w.pool.end;
  if (a == s.a)
    s.a = b;
  else
    s.b = a;
  s.range = keep;
  w.remaining.store(above + below - (b - a), std::memory_order_relaxed);
  // release: what it wrote in the part it gives, and `given`, before the answer.
  w.ask.store(kGiven, std::memory_order_release);
}

template <bool kLattice>
bool Partition<kLattice>::take_from_another(unsigned i, Stretch& s) {
  Worker& me = workers_[i];
  for (unsigned spins = 0;; ++spins) {
    unsigned from = threads_;
    VertexId most = 2 * kMinShare - 1;
    for (unsigned v = 0; v < threads_; ++v) {
      const VertexId r = workers_[v].remaining.load(std::memory_order_relaxed);
      if (v != i && r > most) from = v, most = r;
    }
    if (from == threads_ || stop_.load(std::memory_order_relaxed)) return false;
    Worker& v = workers_[from];
    int state = kWorking;
    if (!v.ask.compare_exchange_strong(state, kAsked, std::memory_order_acq_rel)) {
      wait_a_little(spins);  // another asks it, or it is between stretches
      continue;
    }
    // acquire: its answer, and what it wrote in the points it gives, before we read them.
    for (unsigned wait = 0; (state = v.ask.load(std::memory_order_acquire)) == kAsked; ++wait) wait_a_little(wait);
    Stretch given;
    TriangleId slots = 0;
    if (state == kGiven) given = v.given, slots = v.given_slots;
    v.ask.store(kWorking, std::memory_order_release);  // read: it may be asked again
    if (state == kGiven) {
      s = given;
      me.spare.emplace_back(me.pool.next, me.pool.end);
      me.pool = {nullptr, 0, slots, slots + 2 * (s.b - s.a)};
      return true;
    }
  }
}

void insert_partition(DelaunayTds& tds, const Insertion& run) {
  const std::uint32_t* key = run.keys;
  const unsigned threads = run.threads;
  std::vector<DuplicateHit>& duplicates = run.duplicates;
  Stats& stats = run.stats;
  Progress& progress = run.progress;
  if (tds.vertices().lattice())
    Partition<true>(tds, key, std::max(threads, 1u), duplicates, stats, progress).run();
  else
    Partition<false>(tds, key, std::max(threads, 1u), duplicates, stats, progress).run();
}

}  // namespace ridt::detail
