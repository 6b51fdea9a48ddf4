// Threaded methods return exactly the serial triangle set, for every thread count, seed and
// input; their statistics add up. These tests also run under ThreadSanitizer.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <span>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "helpers.hpp"
#include "methods/partition.hpp"
#include "order/order.hpp"
#include "ridt/generate.hpp"
#include "runtime/parallel.hpp"

namespace ridt::test {
namespace {

struct Variant {
  Method method;
  bool paper;
  std::string name() const { return std::string(to_string(method)) + (paper ? "_paper" : ""); }
};
constexpr Variant kVariants[] = {
    {Method::Pessimistic, false}, {Method::Pessimistic, true}, {Method::Optimistic, false}, {Method::Batch, false}};
constexpr unsigned kThreadCounts[] = {1, 2, 3, 4, 8};

// Smaller under sanitizers, which run these tests many times slower.
#if defined(__SANITIZE_THREAD__) || defined(__SANITIZE_ADDRESS__)
constexpr int kN = 4000;
#else
constexpr int kN = 30000;
#endif

std::vector<std::pair<std::string, std::vector<Point>>> inputs() {
  std::vector<std::pair<std::string, std::vector<Point>>> sets;
  for (Distribution d : {Distribution::Uniform, Distribution::Normal, Distribution::Grid, Distribution::Clusters})
    sets.emplace_back(to_string(d), generate(d, kN, 17));
  std::vector<Point> dup = generate(Distribution::Uniform, 2000, 3);
  for (int i = 0; i < 500; ++i) dup.push_back(dup[i * 3]);
  sets.emplace_back("duplicates", dup);
  std::vector<Point> lines;
  for (int i = 0; i < 1000; ++i) lines.push_back({double(i), 0}), lines.push_back({i + 0.5, 3});
  sets.emplace_back("two_lines", lines);
  std::vector<Point> circle;
  for (int i = 0; i < 1000; ++i) circle.push_back({std::cos(2 * M_PI * i / 1000), std::sin(2 * M_PI * i / 1000)});
  sets.emplace_back("polygon", circle);
  sets.emplace_back("one_line", std::vector<Point>{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {5, 5}});
  sets.emplace_back("tiny", std::vector<Point>{{0, 0}, {1, 0}});
  return sets;
}

class Threaded : public ::testing::TestWithParam<Variant> {};

TEST_P(Threaded, SameTrianglesAsSerialForEveryThreadCount) {
  const Variant v = GetParam();
  std::uint64_t run = 0;
  for (const auto& [name, pts] : inputs()) {
    const Triangulation serial = triangulate(pts);
    ASSERT_EQ(audit(pts, serial), "") << name << ", serial";
    for (unsigned threads : kThreadCounts) {
      for (Order order : {Order::Brio, Order::Random}) {
        Options o;
        o.order = order;
        o.method = v.method;
        o.experiment.paper_locking = v.paper;
        o.threads = threads;
        o.seed = 1 + 7919 * run++;  // a seed of its own for each run: the set must not change
        const Triangulation t = triangulate(pts, o);
        const std::string what = name + ", " + std::to_string(threads) + " threads, " + std::string(to_string(order));
        // The whole result: triangles, neighbours, hull, duplicates, then the same as serial.
        EXPECT_EQ(audit(pts, t), "") << what;
        EXPECT_EQ(compare(t, serial), "") << what;
      }
    }
  }
}

TEST_P(Threaded, ResultPassesTheValidator) {
  Options o;
  o.method = GetParam().method;
  o.experiment.paper_locking = GetParam().paper;
  o.threads = 4;
  triangulate_checked(generate(Distribution::Uniform, kN, 5), o);
}

// Methods whose threads are all workers (batch has roles: Batch.StatisticsAddUp).
class Workers : public ::testing::TestWithParam<Variant> {};

TEST_P(Workers, StatisticsAddUp) {
  const std::vector<Point> pts = generate(Distribution::Uniform, kN, 8);
  Options o;
  o.method = GetParam().method;
  o.experiment.paper_locking = GetParam().paper;
  o.threads = 3;
  const Stats s = triangulate(pts, o).stats;
  EXPECT_EQ(s.threads, 3u);
  ASSERT_EQ(s.per_thread.size(), 3u);
  std::uint64_t points = 0;
  double critical = 0, wait = 0;
  for (const ThreadStats& p : s.per_thread) {
    points += p.points;
    critical += p.time_critical_s;
    wait += p.time_wait_s;
    // A worker may find every chunk taken (3 threads on 2 cores, under a sanitizer): then it
    // spent no time in a critical section.
    if (p.points > 0) {
      EXPECT_GT(p.time_critical_s, 0);
    }
    EXPECT_LE(p.time_critical_s + p.time_wait_s, p.time_insert_s * 1.0001 + 1e-6);
    EXPECT_LE(p.time_insert_s, s.time_insert_s * 1.0001 + 1e-6);
  }
  EXPECT_EQ(points, pts.size());
  EXPECT_GT(critical, 0);
  EXPECT_DOUBLE_EQ(critical, s.time_critical_s);
  EXPECT_DOUBLE_EQ(wait, s.time_wait_s);
  EXPECT_LE(s.time_insert_s, s.time_triangulate_s);

  o.experiment.time_threads = false;
  const Stats quiet = triangulate(pts, o).stats;
  EXPECT_EQ(quiet.time_critical_s, 0);
  EXPECT_EQ(quiet.time_wait_s, 0);
}

// The partition method: threads own regions of each BRIO round's curve. Its passes need rounds
// of some thousands of points (detail::cut_among_threads), so its inputs are larger than kN
// under the sanitizers too.
#if defined(__SANITIZE_THREAD__) || defined(__SANITIZE_ADDRESS__)
constexpr int kPartitionN = 20000;
constexpr unsigned kPartitionThreads[] = {2, 3, 8};
#else
constexpr int kPartitionN = 60000;
constexpr unsigned kPartitionThreads[] = {1, 2, 3, 4, 8, 16};
#endif

TEST(Partition, SameResultAsSerialForEveryThreadCountAndSeed) {
  auto sets = inputs();
  for (Distribution d : {Distribution::Uniform, Distribution::Normal, Distribution::Grid, Distribution::Clusters})
    sets.emplace_back(std::string(to_string(d)) + "_large", generate(d, kPartitionN, 29));
  std::vector<Point> dup = generate(Distribution::Uniform, kPartitionN / 2, 4);
  for (int i = 0; i < kPartitionN / 4; ++i) dup.push_back(dup[static_cast<std::size_t>(i) * 2]);
  sets.emplace_back("duplicates_large", dup);
  // The extremes of the doubles: the threads' predicates run on the scaled copy too.
  for (const double scale : {1e300, 1e-300}) {
    std::vector<Point> scaled = generate(Distribution::Clusters, kPartitionN, 6);
    for (Point& q : scaled) q = {q.x * scale, q.y * scale};
    sets.emplace_back(scale > 1 ? "clusters_1e300" : "clusters_1e-300", scaled);
  }
  // Equal points by the thousand: every key alike, so that the cuts meet at the round's end.
  sets.emplace_back("all_equal", std::vector<Point>(static_cast<std::size_t>(kPartitionN), Point{0.25, -3}));
  std::vector<Point> two(static_cast<std::size_t>(kPartitionN), Point{1, 1});
  for (std::size_t i = 0; i < two.size(); i += 3) two[i] = {2, 5};
  two.push_back({7, -1});
  sets.emplace_back("three_points_repeated", two);
  // Distinct points in a speck and one far away: most share a Hilbert key, so the cuts, and
  // what a thread gives another, cannot fall between them.
  std::vector<Point> speck = generate(Distribution::Uniform, kPartitionN, 3);
  for (Point& q : speck) q = {q.x * 1e-9, q.y * 1e-9};
  speck.push_back({1, 1});
  sets.emplace_back("speck_and_outlier", speck);
  // A grid on a line of points: cocircular everywhere, and collinear runs along the borders.
  std::vector<Point> grid_line = generate(Distribution::Grid, kPartitionN, 2);
  for (int i = 0; i < kPartitionN / 10; ++i) grid_line.push_back({i * 1e-3, 0.5});
  sets.emplace_back("grid_and_line", grid_line);
  std::uint64_t run = 0;
  for (const auto& [name, pts] : sets) {
    const Triangulation serial = triangulate(pts);
    ASSERT_EQ(audit(pts, serial), "") << name << ", serial";
    for (unsigned threads : kPartitionThreads) {
      Options o;
      o.method = Method::Partition;
      o.threads = threads;
      o.seed = 1 + 7919 * run++;
      const Triangulation t = triangulate(pts, o);
      const std::string what = name + ", " + std::to_string(threads) + " threads";
      EXPECT_EQ(audit(pts, t), "") << what;
      EXPECT_EQ(compare(t, serial), "") << what;
      EXPECT_EQ(t.stats.dag_nodes, 0u) << what;
      EXPECT_EQ(t.stats.locate, Locate::Walk) << what;
    }
  }
}

// The partition method on `threads` threads, its output checked.
Triangulation partition_of_uniform(const std::vector<Point>& pts, unsigned threads) {
  Options o;
  o.method = Method::Partition;
  o.threads = threads;
  return triangulate_checked(pts, o);
}

// The passes really share the work: on a large round each thread inserts points, and the
// points put off along the regions' borders are few. The counts add up to the input.
TEST(Partition, ThreadsShareTheRoundsAndFewPointsArePutOff) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 4 * kPartitionN, 12);
  const Triangulation t = partition_of_uniform(pts, 4);
  ASSERT_EQ(t.stats.per_thread.size(), 4u);
  std::uint64_t points = 0;
  for (const ThreadStats& w : t.stats.per_thread) {
    EXPECT_GT(w.points, pts.size() / 16) << "a thread that inserted almost nothing";
    points += w.points;
  }
  EXPECT_EQ(points, pts.size());
  EXPECT_LT(t.stats.retries, pts.size() / 10);
}

// The second pass's regions cross the first pass's borders rather than share them: of the
// points put off along those borders few are left to one thread, besides the small rounds,
// which it takes whole. (Regions cut along the curve again left over a third of them.)
TEST(Partition, TheSecondPassLeavesFewPointsToOneThread) {
  // 240,000 points under the sanitizers too: at a third of that the small rounds weigh more and
  // the share left is 0.22, against 0.16 here and 0.36 for regions cut along the curve.
  const std::vector<Point> pts = generate(Distribution::Uniform, 240000, 12);
  constexpr unsigned kThreads = 8;
  const Triangulation t = partition_of_uniform(pts, kThreads);
  std::uint64_t small = 0;  // points of rounds too small to cut among the threads
  for (std::uint32_t b = 0; b < pts.size(); b = detail::round_end(b)) {
    const std::uint64_t e = std::min<std::uint64_t>(detail::round_end(b), pts.size());
    if (!detail::cut_among_threads(e - b, kThreads)) small += e - b;
  }
  ASSERT_GE(t.stats.alone, small);
  EXPECT_GT(t.stats.retries, 0u);
  EXPECT_LT(t.stats.alone - small, t.stats.retries / 4);
  EXPECT_GT(t.stats.time_second_pass_s, 0);
  EXPECT_LE(t.stats.time_second_pass_s + t.stats.time_alone_s, t.stats.time_insert_s);
}

// A thread that falls behind gives points away: thread 0 sleeps in the progress callback (it
// runs on the calling thread), so the other ends its stretches first and asks it for points,
// again and again. The triangles are the serial ones, and the thread that was awake inserted
// more. (Large enough under the sanitizers too: a thread asks for points only when another
// has some thousands left.)
TEST(Partition, AThreadThatFallsBehindGivesPointsAway) {
  // The nap: longer under the sanitizers, whose threads run many times slower (two awake
  // threads sharing one core besides).
#if defined(__SANITIZE_THREAD__) || defined(__SANITIZE_ADDRESS__)
  static constexpr std::chrono::milliseconds kNap{400};
#else
  static constexpr std::chrono::milliseconds kNap{100};
#endif
  const std::vector<Point> pts = generate(Distribution::Uniform, 240000, 13);
  const Triangulation serial = triangulate(pts);
  for (const unsigned threads : {2u, 3u}) {
    Options o;
    o.method = Method::Partition;
    o.threads = threads;
    o.progress = [](double share) {
      if (share < 1) std::this_thread::sleep_for(kNap);
    };
    const Triangulation t = triangulate(pts, o);
    EXPECT_EQ(audit(pts, t), "") << threads << " threads";
    EXPECT_EQ(compare(t, serial), "") << threads << " threads";
    ASSERT_EQ(t.stats.per_thread.size(), threads);
    std::uint64_t points = 0, others = 0;
    for (const ThreadStats& w : t.stats.per_thread) points += w.points;
    for (unsigned i = 1; i < threads; ++i) others += t.stats.per_thread[i].points;
    EXPECT_EQ(points, pts.size());
    EXPECT_GT(others, t.stats.per_thread[0].points * (threads - 1) + pts.size() / 20) << threads << " threads";
  }
}

TEST(Partition, RefusesTheDagAndTheRandomOrder) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 100, 1);
  Options o;
  o.method = Method::Partition;
  o.locate = Locate::Dag;
  EXPECT_THROW(triangulate(pts, o), InputError);
  o.locate = Locate::Auto;
  o.order = Order::Random;
  EXPECT_THROW(triangulate(pts, o), InputError);
}

// Many threads on few points: insertions collide often, and every retry must leave the mesh
// as it was. Repeated, since collisions depend on timing.
TEST(Optimistic, CollisionsLeaveNoTrace) {
  for (Distribution d : {Distribution::Uniform, Distribution::Grid}) {
    const std::vector<Point> pts = generate(d, 3000, 21);
    const TriangleSet expected = canonical(triangulate(pts).triangles);
    for (int run = 0; run < 10; ++run) {
      Options o;
      o.method = Method::Optimistic;
      o.threads = 8;
      o.seed = run;
      const Triangulation t = triangulate(pts, o);
      ASSERT_EQ(canonical(t.triangles), expected) << to_string(d) << " run " << run;
      std::uint64_t retries = 0;
      for (const ThreadStats& p : t.stats.per_thread) retries += p.retries;
      EXPECT_EQ(retries, t.stats.retries);
    }
  }
}

TEST(Batch, StatisticsAddUp) {
  const std::vector<Point> pts = generate(Distribution::Uniform, kN, 8);
  Options o;
  o.method = Method::Batch;
  o.threads = 3;
  const Stats s = triangulate(pts, o).stats;
  EXPECT_EQ(s.threads, 3u);
  ASSERT_EQ(s.per_thread.size(), 3u);  // one modifier, two locators
  EXPECT_EQ(s.per_thread[0].role, "modifier");
  EXPECT_EQ(s.per_thread[0].points, pts.size());
  std::uint64_t located = 0;
  double stalled = 0;
  for (std::size_t i = 1; i < 3; ++i) {
    EXPECT_EQ(s.per_thread[i].role, "locator");
    located += s.per_thread[i].points;
    stalled += s.per_thread[i].time_wait_s;
  }
  EXPECT_EQ(located, pts.size());
  EXPECT_DOUBLE_EQ(stalled, s.time_stall_s);
  EXPECT_DOUBLE_EQ(s.per_thread[0].time_wait_s, s.time_idle_s);
  EXPECT_LE(s.stale_hints, pts.size());
  EXPECT_GE(s.queue_depth_mean, 0);
  EXPECT_LE(s.queue_depth_mean, 65536);
  EXPECT_LE(s.time_idle_s, s.time_insert_s * 1.0001 + 1e-6);

  o.threads = 1;  // no locator: the one thread locates and modifies
  const Stats one = triangulate(pts, o).stats;
  ASSERT_EQ(one.per_thread.size(), 1u);
  EXPECT_EQ(one.per_thread[0].role, "modifier");
  EXPECT_EQ(one.stale_hints, 0u);
}

TEST(Threaded, ZeroThreadsMeansTheHardware) {
  Options o;
  o.method = Method::Pessimistic;
  o.threads = 0;
  const Stats s = triangulate(generate(Distribution::Uniform, 1000, 1), o).stats;
  EXPECT_GE(s.threads, 1u);
  EXPECT_EQ(s.per_thread.size(), s.threads);
}

TEST(Threaded, SerialReportsOneThread) {
  const Stats s = triangulate(generate(Distribution::Uniform, 1000, 1)).stats;
  EXPECT_EQ(s.threads, 1u);
  ASSERT_EQ(s.per_thread.size(), 1u);
  EXPECT_EQ(s.per_thread[0].points, 1000u);
}

TEST(Threaded, ProfilingIsSerialOnly) {
  Options o;
  o.method = Method::Pessimistic;
  o.experiment.profile = true;
  EXPECT_THROW(triangulate(generate(Distribution::Uniform, 100, 1), o), InputError);
}

// Options::progress: called on the calling thread, in order, from 0 to 1, by every method;
// throwing from it abandons the run cleanly (under ThreadSanitizer too), and the next run is
// unaffected.
TEST(Progress, ReportedByEveryMethodAndCanAbandonTheRun) {
  struct Abandon {};
  // Enough points for several reports (one each 65,536); fewer under the sanitizers.
#if defined(__SANITIZE_THREAD__) || defined(__SANITIZE_ADDRESS__)
  constexpr int kPoints = 20000;
  constexpr std::size_t kReports = 2;
#else
  constexpr int kPoints = 140000;
  constexpr std::size_t kReports = 3;
#endif
  const std::vector<Point> pts = generate(Distribution::Uniform, kPoints, 5);
  const Triangulation expected = triangulate(pts);
  for (const Method m : {Method::Serial, Method::Pessimistic, Method::Optimistic, Method::Batch, Method::Partition}) {
    for (const Locate where : {Locate::Dag, Locate::Walk, Locate::Root}) {
      if (where == Locate::Walk && m != Method::Serial && m != Method::Partition) continue;
      if (where != Locate::Walk && m == Method::Partition) continue;
      Options o;
      o.method = m;
      o.locate = where;
      o.threads = 2;
      std::vector<double> seen;
      const std::thread::id caller = std::this_thread::get_id();
      bool other_thread = false;
      o.progress = [&](double f) {
        seen.push_back(f);
        other_thread = other_thread || std::this_thread::get_id() != caller;
      };
      EXPECT_EQ(compare(triangulate(pts, o), expected), "");
      EXPECT_FALSE(other_thread);
      ASSERT_GE(seen.size(), kReports);
      EXPECT_LT(seen.front(), 0.1);
      EXPECT_EQ(seen.back(), 1.0);
      EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
      o.progress = [](double f) {
        if (f > 0) throw Abandon{};  // at the second report
      };
      EXPECT_THROW(triangulate(pts, o), Abandon);
    }
  }
  // Nothing of the abandoned runs lingers.
  Options o;
  o.method = Method::Optimistic;
  o.threads = 2;
  EXPECT_EQ(compare(triangulate(pts, o), expected), "");
}

// Blocks kept between calls (set_memory_cache_limit) hold the records of the run before, of
// another method, or of an abandoned run: every method must give the same result on them as
// on fresh memory. (The sanitizers' builds keep nothing by default; here the limit is set.)
TEST(MemoryCache, ReusedBlocksGiveTheSameResult) {
  // Enough points for the records' chunks to be on huge pages, which are the ones kept.
  // The DAG's records are the blocks kept; the walking kernel's arrays become the output.
  const std::vector<Point> pts = generate(Distribution::Uniform, 20000, 9);
  Options dag;
  dag.locate = Locate::Dag;
  const std::size_t before = set_memory_cache_limit(0);
  ASSERT_EQ(cached_memory(), 0u);
  const Triangulation fresh = triangulate(pts, dag);
  ASSERT_EQ(audit(pts, fresh), "");
  EXPECT_EQ(cached_memory(), 0u);  // with no room, nothing is kept

  set_memory_cache_limit(std::size_t{1} << 30);
  EXPECT_EQ(compare(triangulate(pts, dag), fresh), "");
  const std::size_t kept = cached_memory();
  EXPECT_GT(kept, 0u);
  struct Abandon {};
  for (const Method m : {Method::Serial, Method::Pessimistic, Method::Optimistic, Method::Batch}) {
    const std::string name(to_string(m));
    for (const Order order : {Order::Random, Order::Brio}) {
      Options o;
      o.method = m;
      o.order = order;
      o.locate = Locate::Dag;
      o.threads = 2;
      o.seed = 3;
      const Triangulation t = triangulate(pts, o);
      EXPECT_EQ(audit(pts, t), "") << name;
      EXPECT_EQ(compare(t, fresh), "") << name;
      // The same amount is kept after each run: its blocks were taken from the cache and
      // given back, none added.
      EXPECT_EQ(cached_memory(), kept) << name;
      // Abandoned at the first report, once the records' blocks are taken (Progress above
      // abandons runs midway, on the default limit).
      o.progress = [](double) { throw Abandon{}; };
      EXPECT_THROW(triangulate(pts, o), Abandon);
    }
  }
  EXPECT_EQ(cached_memory(), kept);

  // A lower limit gives back what is over it at once.
  EXPECT_EQ(set_memory_cache_limit(0), std::size_t{1} << 30);
  EXPECT_EQ(cached_memory(), 0u);

  // A limit below the records' range keeps its start, in whole huge pages, and makes the
  // rest reserved address space again; the next call commits that afresh.
  constexpr std::size_t kPart = std::size_t{4} << 20;
  ASSERT_LT(kPart, kept);
  set_memory_cache_limit(kPart + 1000);
  for (const Method m : {Method::Serial, Method::Optimistic}) {
    Options o;
    o.method = m;
    o.locate = Locate::Dag;
    o.threads = 2;
    EXPECT_EQ(compare(triangulate(pts, o), fresh), "");
    EXPECT_EQ(cached_memory(), kPart);
  }
  set_memory_cache_limit(before);
}

// MemoryReuse keeps nothing in the sanitizers' builds (as the cache's default limit there).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kReuses = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kReuses = false;
#else
constexpr bool kReuses = true;
#endif
#else
constexpr bool kReuses = true;
#endif

// Under a limit of 0, what calls give back is kept while a MemoryReuse lives, taken by the
// calls that follow (the same result on it), and given back at its end.
TEST(MemoryCache, ReuseKeepsWhatIsGivenBackWhileItLives) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 20000, 9);
  Options dag;
  dag.locate = Locate::Dag;
  const std::size_t before = set_memory_cache_limit(0);
  const Triangulation fresh = triangulate(pts, dag);
  ASSERT_EQ(cached_memory(), 0u);
  {
    const MemoryReuse reuse(std::size_t{1} << 30);
    EXPECT_EQ(compare(triangulate(pts, dag), fresh), "");
    const std::size_t kept = cached_memory();
    EXPECT_EQ(kept > 0, kReuses);
    EXPECT_EQ(compare(triangulate(pts, dag), fresh), "");
    EXPECT_EQ(cached_memory(), kept);  // taken and given back, none added
  }
  EXPECT_EQ(cached_memory(), 0u);
  set_memory_cache_limit(before);
}

// Where the system grants less address space than the records' range asks (a limit on it),
// the range is as large as it grants, and a run that fits gives the same triangles. Not under
// the sanitizers, which need far more address space than any such limit leaves.
#if !defined(__SANITIZE_THREAD__) && !defined(__SANITIZE_ADDRESS__)
// Exits 0 when both runs give `expected`, under a 4 GiB limit on address space (of the 56 the
// range asks for).
[[noreturn]] void triangulate_in_4_gib(const std::vector<Point>& pts, const Triangulation& expected) {
  const rlimit limit{rlim_t{4} << 30, rlim_t{4} << 30};
  if (setrlimit(RLIMIT_AS, &limit) != 0) std::exit(3);
  set_memory_cache_limit(0);  // a fresh range
  Options o;
  o.method = Method::Optimistic;
  o.threads = 2;
  const bool same = compare(triangulate(pts), expected) == "" && compare(triangulate(pts, o), expected) == "";
  std::exit(same ? 0 : 1);
}

TEST(MemoryCache, LimitedAddressSpace) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 200000, 5);
  const Triangulation fresh = triangulate(pts);
  EXPECT_EXIT(triangulate_in_4_gib(pts, fresh), ::testing::ExitedWithCode(0), "");
}
#endif

INSTANTIATE_TEST_SUITE_P(Methods, Threaded, ::testing::ValuesIn(kVariants),
                         [](const auto& info) { return info.param.name(); });
INSTANTIATE_TEST_SUITE_P(Methods, Workers, ::testing::ValuesIn(kVariants, kVariants + 3),
                         [](const auto& info) { return info.param.name(); });

// ---- The parked threads of on_threads (runtime/parallel.cpp) ----

// Every part runs once, on its own thread, and what the parts wrote is seen after the call;
// a call from inside a part, or from two threads at once, starts its own threads and still
// runs every part.
TEST(ParkedThreads, EveryPartRunsOnceNestedAndConcurrent) {
  for (int round = 0; round < 50; ++round) {
    for (const unsigned count : {1u, 2u, 3u, 8u}) {
      std::vector<int> ran(count, 0);
      std::vector<std::thread::id> who(count);
      detail::on_threads(count, [&](unsigned w) { ++ran[w], who[w] = std::this_thread::get_id(); });
      EXPECT_EQ(std::count(ran.begin(), ran.end(), 1), static_cast<long>(count));
      EXPECT_EQ(who[0], std::this_thread::get_id());
      std::sort(who.begin(), who.end());
      EXPECT_EQ(std::unique(who.begin(), who.end()), who.end());
    }
  }
  std::vector<int> inner(4 * 3, 0);
  detail::on_threads(4, [&](unsigned w) { detail::on_threads(3, [&](unsigned v) { ++inner[3 * w + v]; }); });
  EXPECT_EQ(std::count(inner.begin(), inner.end(), 1), 12);
  // Two callers at once: one has the parked threads, the other starts its own.
  std::vector<long> sums(2, 0);
  auto caller = [&](int c) {
    for (int i = 0; i < 200; ++i) {
      std::vector<long> part(3, 0);
      detail::on_threads(3, [&](unsigned w) { part[w] = w + 1; });
      sums[c] += part[0] + part[1] + part[2];
    }
  };
  {
    std::jthread other(caller, 1);
    caller(0);
  }
  EXPECT_EQ(sums[0], 1200);
  EXPECT_EQ(sums[1], 1200);
}

// Options::on_sorted: the canonical sort hands over every triangle once, each stretch at its
// place holding what the result holds there, from the sorting threads (a lock here), with the
// neighbours or without, from a method of the walking kernel and one of the DAG; never without
// canonical_order. A throw ends the call, and the next one is whole again.
TEST(OnSorted, EveryTriangleOnceInItsPlace) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 60000, 4);
  for (const Method m : {Method::Partition, Method::Pessimistic})
    for (const bool neighbors : {true, false})
      for (const unsigned threads : {1u, 2u, 3u}) {
        std::mutex lock;
        std::vector<VertexId> seen;
        std::vector<int> times;
        Options o;
        o.method = m;
        o.threads = threads;
        o.neighbors = neighbors;
        o.canonical_order = true;
        o.on_sorted = [&](std::size_t first, std::span<const VertexId> tri) {
          const std::lock_guard<std::mutex> guard(lock);
          if (seen.size() < 3 * first + tri.size()) seen.resize(3 * first + tri.size()), times.resize(seen.size() / 3);
          std::copy(tri.begin(), tri.end(), seen.begin() + static_cast<std::ptrdiff_t>(3 * first));
          for (std::size_t k = first; k < first + tri.size() / 3; ++k) ++times[k];
        };
        const Triangulation t = triangulate(pts, o);
        const std::string name = std::string(to_string(m)) + " " + std::to_string(threads) + (neighbors ? "" : " bare");
        EXPECT_EQ(seen, t.triangles) << name;
        EXPECT_EQ(std::count(times.begin(), times.end(), 1), static_cast<std::ptrdiff_t>(t.size())) << name;
      }
  Options o;
  o.method = Method::Partition;
  o.threads = 2;
  bool called = false;
  o.on_sorted = [&](std::size_t, std::span<const VertexId>) { called = true; };
  triangulate(pts, o);
  EXPECT_FALSE(called);
  struct Stop {};
  o.canonical_order = true;
  o.on_sorted = [](std::size_t first, std::span<const VertexId>) {
    if (first > 0) throw Stop{};
  };
  EXPECT_THROW(triangulate(pts, o), Stop);
  o.on_sorted = {};
  EXPECT_EQ(audit(pts, triangulate(pts, o)), "");
}

// A child of fork() has none of its parent's threads: its calls park threads of its own, and
// a triangulation there gives the parent's triangles. Large enough for every part to run on
// threads under the sanitizers too (ThreadSanitizer then needs die_after_fork=0: by default it
// ends a child of a threaded process that starts a thread).
TEST(ParkedThreads, AForkedChildParksItsOwn) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 60000, 3);
  Options o;
  o.method = Method::Partition;
  o.threads = 3;
  o.canonical_order = true;
  const Triangulation parent = triangulate(pts, o);  // the parent's threads are parked now
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // The result is the exit status; a child that waits for threads it does not have is
    // ended by the alarm.
    ::alarm(120);
    bool same = false;
    try {
      same = triangulate(pts, o).triangles == parent.triangles;
    } catch (...) {}
    ::_exit(same ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

// Where no thread can be started (a child of fork(), with no parked threads, under a limit on
// address space that leaves no room for a thread's stack), parallel_for runs every part on the
// caller, each once, and says nothing: the validator of a mesh refinement stopped for memory
// failed so ("Resource temporarily unavailable"). Not under the sanitizers, whose shadow
// memory an address-space limit would starve.
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
TEST(ParkedThreads, PartsRunOnTheCallerWhereNoThreadStarts) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::alarm(60);
    constexpr std::size_t kCount = 1 << 16;
    std::vector<std::uint8_t> seen(kCount, 0);  // allocated before the limit
    std::mutex hold;
    hold.lock();
    std::vector<std::thread> holders;
    holders.reserve(4096);
    long pages = 0;
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
      if (std::fscanf(f, "%ld", &pages) != 1) pages = 0;
      std::fclose(f);
    }
    rlimit limit{};
    ::getrlimit(RLIMIT_AS, &limit);
    limit.rlim_cur = static_cast<rlim_t>(pages) * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE)) + (1 << 20);
    if (pages == 0 || ::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(2);
    // Threads that hold the stacks the C library keeps for reuse (those of the parent's threads
    // among them), until a new thread would need a new one, which the limit refuses.
    bool thread_refused = false;
    while (!thread_refused && holders.size() < 4096) try {
        holders.emplace_back([&] { const std::lock_guard<std::mutex> wait(hold); });
      } catch (const std::system_error&) {
        thread_refused = true;
      }
    bool once = false;
    try {
      detail::parallel_for(kCount, 4, 1024, [&](std::size_t from, std::size_t to) {
        for (std::size_t i = from; i < to; ++i) ++seen[i];
      });
      once = std::all_of(seen.begin(), seen.end(), [](std::uint8_t c) { return c == 1; });
    } catch (...) {}
    hold.unlock();
    for (std::thread& t : holders) t.join();
    ::_exit(!thread_refused ? 3 : once ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "2: no limit set; 3: a thread started under the limit; 1: parts lost";
}
#endif

}  // namespace
}  // namespace ridt::test
