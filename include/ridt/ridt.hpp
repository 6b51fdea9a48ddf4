// ridt: exact 2D Delaunay triangulation by randomized incremental insertion.
//
// One call, plain data out:
//
//   std::vector<ridt::Point> pts = ...;
//   ridt::Triangulation t = ridt::triangulate(pts);
//   // t.triangles: #T by 3 vertex indices into pts, counter-clockwise
//   // t.neighbors: #T by 3 triangle indices, neighbours[3*k+i] across from vertex i, -1 on the hull
//
// Preconditions: every coordinate is finite (NaN or infinity throws ridt::InputError).
// Postconditions: the triangles are exactly the Delaunay triangulation of the distinct input
// points (cocircular ties broken by a fixed symbolic perturbation, so the result is unique and
// does not depend on the seed, the method or the input order); the boundary is the convex hull;
// every distinct point is a vertex; duplicates are reported and left out.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace ridt {

/// A point in the plane.
struct Point {
  double x = 0;
  double y = 0;
  friend bool operator==(const Point&, const Point&) = default;
};

/// A point in space (the triangulation on the sphere, include/ridt/sphere.hpp).
struct Point3 {
  double x = 0;
  double y = 0;
  double z = 0;
  friend bool operator==(const Point3&, const Point3&) = default;
};

using VertexId = std::uint32_t;
using TriangleId = std::uint32_t;
/// Marks "no triangle" in neighbour lists of the result (a hull edge).
inline constexpr std::int32_t kNoNeighbor = -1;

/// Who drives the insertion kernel.
enum class Method {
  /// Serial on one thread (or with Experiment::profile); on more, Partition where the order
  /// and the location allow it, else Optimistic. Stats::method says which ran.
  Auto,
  Serial,  ///< one thread, the paper's Fig. 4
  Pessimistic,  ///< threads share one triangulation; one critical section for the leaf step (Fig. 10)
  Optimistic,  ///< threads lock only the triangles an insertion changes (try-lock, back off)
  Batch,  ///< threads - 1 locators queue DAG nodes for one modifier thread
  /// Threads own regions of the plane (stretches of each BRIO round's curve) and insert into
  /// one mesh without a lock and without a DAG; the points near a region's border go to a
  /// second pass with other borders, and what is left to one thread. BRIO order, walking.
  Partition,
};

/// The order in which points are inserted.
enum class Order {
  Random,  ///< a uniformly random permutation: the paper's order
  Brio,  ///< biased randomized: random rounds of doubling size, each along a Hilbert curve
};

/// How an insertion finds the triangle that holds its point.
enum class Locate {
  Auto,  ///< Walk where the method and the order allow it, else Dag
  Dag,  ///< descend the history DAG in rounds along a curve (serial and the paper's methods)
  Walk,  ///< walk from the last insertion; keeps no DAG (serial and partition, BRIO order)
  /// The paper's own location: every point descends the history DAG from its root when its
  /// turn comes, with no rounds and no look-ahead (serial and the paper's three methods).
  Root,
};

/// The starting triangle that encloses every point.
enum class Bounding {
  Symbolic,  ///< vertices at infinity, decided combinatorially: the hull is always complete
  Finite,  ///< the paper's (K,0), (0,K), (-K,-K) around the box centre, K = k * box size
};

/// Switches for the paper's experiments (section 4) and their variants. A user who wants the
/// triangulation leaves them as they are.
struct Experiment {
  /// Pessimistic: descend outside the lock only to the parents of leaves, as the paper does.
  /// Off (the default), a worker descends to a leaf outside the lock and, inside, continues
  /// only if that leaf has been split meanwhile.
  bool paper_locking = false;
  /// Threaded methods: time each thread's insertion, critical section and waiting (Tables 2
  /// and 3). Three clock reads a point.
  bool time_threads = true;
  /// Time the phases of insertion (locate, split, legalize): the paper's Fig. 8. Serial only.
  bool profile = false;
  /// The starting triangle: symbolic (the default, the hull always complete) or the paper's
  /// finite one, which can lose hull edges (Triangulation::warning says so).
  Bounding bounding = Bounding::Symbolic;
  double k = 10.0;  ///< K = k * M for Bounding::Finite; k >= 2 keeps every point strictly inside
};

/// Options of a triangulation. Every choice gives the same triangles; they differ in speed.
struct Options {
  Method method = Method::Serial;
  /// Threads of a threaded method (at most kMaxThreads); 0 = the machine's hardware threads.
  /// Batch: threads - 1 locators and one modifier.
  unsigned threads = 0;
  std::uint64_t seed = 1;  ///< seed of the random insertion order
  Order order = Order::Brio;
  Locate locate = Locate::Auto;
  /// Rotate each triangle so its smallest vertex index comes first and sort the triangles:
  /// the output is then byte-identical for every seed and method. Costs a sort.
  bool canonical_order = false;
  /// Fill Triangulation::neighbors. Off, they are left empty: a caller that needs only the
  /// triangles (a file of them, say) spares their memory and, with canonical_order, the half
  /// of the sort that renumbers them.
  bool neighbors = true;
  /// With canonical_order: called with each stretch of the sorted triangles once it holds its
  /// final ones, `first` the number of its first triangle and `triangles` their vertex triples
  /// (3 numbers a triangle, as the result will hold them there); every triangle once, from
  /// the sorting threads, several at a time, in no particular order. A file of the triangles
  /// written from here (at byte 12 * first, say) is then written while the rest are sorted,
  /// complete when triangulate returns. It may throw: the exception reaches the caller of
  /// triangulate once the sort has stopped.
  std::function<void(std::size_t first, std::span<const VertexId> triangles)> on_sorted;
  /// Called with the share of the points inserted so far (0 to 1), on the calling thread, each
  /// time some 65,536 more are in, and with 1 when all are. It may throw to abandon the run:
  /// the exception reaches the caller of triangulate once every worker has stopped.
  std::function<void(double)> progress;
  /// The paper's experiment switches (Bounding::Finite makes the result depend on them).
  Experiment experiment;
  /// The most memory the call may take, in bytes: 0 (the default) means what the system can
  /// give (available_memory()). A call that would need more (estimate_memory) throws
  /// MemoryError before it allocates anything large.
  std::size_t memory_limit = 0;
};

/// What one thread did (the paper's Tables 2 and 3, per thread).
struct ThreadStats {
  std::string role = "worker";  ///< "worker"; batch: "modifier" or "locator"
  std::uint64_t points = 0;  ///< points it inserted (a locator: located; duplicates included)
  double time_insert_s = 0;  ///< from its start to its end
  double time_critical_s = 0;  ///< pessimistic: holding the lock; optimistic: holding triangles
  /// Pessimistic: waiting for the lock; optimistic: backing off after a failed try-lock; both
  /// also waiting for the others at the end of a round. Batch: the modifier waiting for a
  /// hint, a locator waiting for room in the queue.
  double time_wait_s = 0;
  std::uint64_t retries = 0;  ///< optimistic: insertions restarted after a failed try-lock
};

/// Counters and timings of one run.
struct Stats {
  unsigned threads = 1;  ///< threads that inserted points
  std::uint64_t points = 0;  ///< input points
  std::uint64_t distinct = 0;  ///< distinct points
  std::uint64_t duplicates = 0;  ///< input points dropped as duplicates
  std::uint64_t dag_nodes = 0;  ///< triangle records made (each one a node of the history DAG); 0 when walking
  /// Edge flips during legalization. Walking (cavity insertion): the flips the same insertions
  /// would have made, the triangles each cavity replaced beyond the first.
  std::uint64_t flips = 0;
  std::uint64_t edge_splits = 0;  ///< points inserted on an edge (2 -> 4 splits); 0 when walking
  double time_triangulate_s = 0;  ///< the whole call: set-up, insertion, finish
  /// The call's phases, wall seconds, in the order they run; with the few checks between them
  /// they add up to time_triangulate_s.
  double time_scan_s = 0;  ///< the points' extent (and the check that every coordinate is finite)
  double time_mesh_s = 0;  ///< the walking mesh's memory, made and its pages touched; 0 for the DAG
  double time_order_s = 0;  ///< the insertion order (BRIO: the Hilbert sort of each round)
  double time_copy_s = 0;  ///< the points copied in insertion order (and scaled)
  double time_insert_s = 0;  ///< wall time of the insertion phase
  double time_finish_s = 0;  ///< the mesh into the result's arrays (triangles, neighbours, hull, duplicates)
  double time_canonical_s = 0;  ///< Options::canonical_order: the triangles sorted (and on_sorted's calls)
  double time_critical_s = 0;  ///< summed over threads (threaded methods, Experiment::time_threads)
  double time_wait_s = 0;  ///< summed over threads (threaded methods, Experiment::time_threads)
  /// Optimistic: insertions restarted after a failed try-lock; partition: points put off to a
  /// later pass because they met another thread's region.
  std::uint64_t retries = 0;
  Method method = Method::Serial;  ///< the method that ran (Method::Auto made definite)
  Locate locate = Locate::Dag;  ///< the location used (Locate::Auto made definite)
  double time_idle_s = 0;  ///< batch: the modifier waiting for hints
  double time_stall_s = 0;  ///< batch: locators waiting for room in the queue, summed
  double queue_depth_mean = 0;  ///< batch: hints queued ahead of the modifier, on average
  std::uint64_t stale_hints = 0;  ///< batch: hints no longer a leaf when the modifier took them
  double time_second_pass_s = 0;  ///< partition: wall seconds of the second passes (within time_insert_s)
  double time_alone_s = 0;  ///< partition: wall seconds inserting on one thread (within time_insert_s)
  std::uint64_t alone = 0;  ///< partition: points inserted on one thread (small rounds, what both passes put off)
  std::vector<ThreadStats> per_thread;
  double time_locate_s = 0;  ///< only with Experiment::profile
  double time_split_s = 0;  ///< only with Experiment::profile
  double time_legalize_s = 0;  ///< only with Experiment::profile
  std::uint64_t memory_estimate = 0;  ///< bytes: estimate_memory for this call, checked before it started
};

/// A dropped duplicate input point and the input index that stands for it (the smallest
/// index among the equal points).
struct Duplicate {
  VertexId dropped;
  VertexId kept;
};

/// The result: flat arrays, as plain data.
struct Triangulation {
  std::vector<VertexId> triangles;  ///< #T by 3, counter-clockwise
  /// #T by 3, neighbour i across from vertex i, -1 on the hull (empty: Options::neighbors off)
  std::vector<std::int32_t> neighbors;
  std::vector<VertexId> hull;  ///< convex hull, counter-clockwise, collinear hull points included
  std::vector<Duplicate> duplicates;  ///< sorted by `dropped`
  /// Why the triangulation is empty ("fewer than three distinct points", "all points are
  /// collinear"), or a problem of Bounding::Finite ("hull edge lost"); empty when all is well.
  std::string warning;
  Stats stats;

  std::size_t size() const { return triangles.size() / 3; }
};

/// Thrown for input that cannot be triangulated (a NaN or infinite coordinate, a bad option).
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A file that cannot be read or written, or malformed content; the message names the file
/// (the out-of-core triangulation, and the tools' readers and writers).
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Thrown before a call starts its work when it would need more memory than there is: the
/// message names what it needs and what there is, and what would fit where something would.
class MemoryError : public InputError {
 public:
  MemoryError(const std::string& what, std::size_t needed, std::size_t available)
      : InputError(what), needed(needed), available(available) {}
  std::size_t needed, available;  ///< bytes
};

/// The most threads a run takes (Options::threads).
inline constexpr unsigned kMaxThreads = 1024;

/// One value of an option and the name the tool, the Python package, the tests and the
/// benchmarks give it, with a line of help.
template <class E>
struct Named {
  std::string_view name;
  E value;
  std::string_view help;
};

/// The names of each option's values: their one definition (`option` names the option in a
/// message). names<E>() lists them, to_string(e) names one, parse<E>(text) reads one.
template <class E>
struct OptionNames;

template <>
struct OptionNames<Method> {
  static constexpr std::string_view option = "method";
  static constexpr Named<Method> values[] = {
      {"auto", Method::Auto, "serial on one thread, else partition where it can run, else optimistic"},
      {"serial", Method::Serial, "one thread, the paper's Fig. 4"},
      {"pessimistic", Method::Pessimistic, "the paper's: threads share the DAG, one lock for the leaf step"},
      {"optimistic", Method::Optimistic, "the paper's: threads lock only the triangles they change"},
      {"batch", Method::Batch, "the paper's: threads - 1 locators feed one modifier"},
      {"partition", Method::Partition, "threads own regions of the plane; no lock, no DAG"},
  };
};

template <>
struct OptionNames<Order> {
  static constexpr std::string_view option = "order";
  static constexpr Named<Order> values[] = {
      {"brio", Order::Brio, "random rounds, each along a Hilbert curve"},
      {"random", Order::Random, "a uniformly random permutation, the paper's"},
  };
};

template <>
struct OptionNames<Locate> {
  static constexpr std::string_view option = "location";
  static constexpr Named<Locate> values[] = {
      {"auto", Locate::Auto, "walk where the method and the order allow it, else dag"},
      {"dag", Locate::Dag, "the history DAG, in rounds along a curve"},
      {"walk", Locate::Walk, "from the last insertion, no DAG (serial and partition, brio order)"},
      {"root", Locate::Root, "the paper's: every point descends the DAG from its root"},
  };
};

template <>
struct OptionNames<Bounding> {
  static constexpr std::string_view option = "bounding";
  static constexpr Named<Bounding> values[] = {
      {"symbolic", Bounding::Symbolic, "vertices at infinity: the hull is always complete"},
      {"finite", Bounding::Finite, "the paper's triangle, k times the box; can lose hull edges"},
  };
};

/// Every value of option type E with its name and help.
template <class E>
constexpr std::span<const Named<E>> names() {
  return OptionNames<E>::values;
}

/// The name of `value` ("partition" for Method::Partition).
template <class E>
constexpr std::string_view to_string(E value) {
  for (const Named<E>& n : names<E>())
    if (n.value == value) return n.name;
  return "?";
}

/// "a, b or c": the names of E's values, for a message.
template <class E>
std::string name_list() {
  std::string list;
  const std::span<const Named<E>> all = names<E>();
  for (std::size_t i = 0; i < all.size(); ++i)
    list += std::string(i == 0 ? "" : i + 1 == all.size() ? " or " : ", ") + std::string(all[i].name);
  return list;
}

/// The value named `text`; throws InputError naming the choices when there is none.
template <class E>
E parse(std::string_view text) {
  for (const Named<E>& n : names<E>())
    if (n.name == text) return n.value;
  throw InputError("unknown " + std::string(OptionNames<E>::option) + " '" + std::string(text) + "' (use " +
                   name_list<E>() + ")");
}

/// Calls visit(name, member) for each counter and time of Stats (not per_thread), in the order
/// the tool prints them: the one list the tool, the Python package and the benchmarks read.
/// A member is a pointer to a field of Stats: `stats.*member` is its value.
template <class Visit>
constexpr void for_each_stat(Visit&& visit) {
  visit("method", &Stats::method);
  visit("threads", &Stats::threads);
  visit("locate", &Stats::locate);
  visit("points", &Stats::points);
  visit("distinct", &Stats::distinct);
  visit("duplicates", &Stats::duplicates);
  visit("dag_nodes", &Stats::dag_nodes);
  visit("flips", &Stats::flips);
  visit("edge_splits", &Stats::edge_splits);
  visit("retries", &Stats::retries);
  visit("time_triangulate_s", &Stats::time_triangulate_s);
  visit("time_scan_s", &Stats::time_scan_s);
  visit("time_mesh_s", &Stats::time_mesh_s);
  visit("time_order_s", &Stats::time_order_s);
  visit("time_copy_s", &Stats::time_copy_s);
  visit("time_insert_s", &Stats::time_insert_s);
  visit("time_finish_s", &Stats::time_finish_s);
  visit("time_canonical_s", &Stats::time_canonical_s);
  visit("time_critical_s", &Stats::time_critical_s);
  visit("time_wait_s", &Stats::time_wait_s);
  visit("time_idle_s", &Stats::time_idle_s);
  visit("time_stall_s", &Stats::time_stall_s);
  visit("queue_depth_mean", &Stats::queue_depth_mean);
  visit("stale_hints", &Stats::stale_hints);
  visit("time_second_pass_s", &Stats::time_second_pass_s);
  visit("time_alone_s", &Stats::time_alone_s);
  visit("alone", &Stats::alone);
  visit("time_locate_s", &Stats::time_locate_s);
  visit("time_split_s", &Stats::time_split_s);
  visit("time_legalize_s", &Stats::time_legalize_s);
  visit("memory_estimate", &Stats::memory_estimate);
}

/// The same for each thread's ThreadStats.
template <class Visit>
constexpr void for_each_thread_stat(Visit&& visit) {
  visit("role", &ThreadStats::role);
  visit("points", &ThreadStats::points);
  visit("retries", &ThreadStats::retries);
  visit("time_insert_s", &ThreadStats::time_insert_s);
  visit("time_critical_s", &ThreadStats::time_critical_s);
  visit("time_wait_s", &ThreadStats::time_wait_s);
}

/// Triangulates `points`; the library copies what it keeps.
Triangulation triangulate(std::span<const Point> points, const Options& options = {});

/// The same for a flat array x0, y0, x1, y1, ... (its size must be even).
Triangulation triangulate(std::span<const double> xy, const Options& options = {});

/// triangulate keeps the large blocks of its work space (the triangle records, some 250 bytes
/// a point, and its copy of the points) for the next call in the process instead of giving
/// them back to the system, up to this many bytes in all: 512 MiB by default (enough for some
/// two million points), none in builds with AddressSanitizer or ThreadSanitizer nor under a
/// limit on address space (ulimit -v), which what is kept would count against. A block the
/// system hands out anew has its pages faulted in and zeroed on first touch, which can take a
/// third of a call's time. Set 0 when one call is all a process makes, or to give back at
/// once what is kept: kept blocks also raise the call's peak memory, since the records are
/// then kept while the result is written. Thread-safe. Returns the previous limit.
std::size_t set_memory_cache_limit(std::size_t bytes);

/// The bytes kept now for the next call (see set_memory_cache_limit).
std::size_t cached_memory();

/// While one lives, the blocks calls give back are kept, up to `bytes` more than the cache's
/// limit, for the calls that follow to take where a size matches: a sequence of calls made as
/// one (a triangulation, then an interpolation on it) reuses its pages instead of having fresh
/// ones faulted in and zeroed, even under a limit of 0. Its end gives back what is then over
/// the limit. Nothing in builds with AddressSanitizer or ThreadSanitizer. Thread-safe.
class MemoryReuse {
 public:
  explicit MemoryReuse(std::size_t bytes);
  ~MemoryReuse();
  MemoryReuse(const MemoryReuse&) = delete;
  MemoryReuse& operator=(const MemoryReuse&) = delete;

 private:
  std::size_t bytes_ = 0;
};

/// The most memory triangulate(points, options) takes for n points, in bytes: its work space,
/// its copy of the points and the result, by the method, location and threads that the
/// options make (Method::Auto resolved as triangulate resolves it), from the bytes a point each
/// kernel was measured to take (docs/performance.md) with a margin. The caller's points are not
/// counted. Throws InputError for options that cannot run.
std::size_t estimate_memory(std::size_t n, const Options& options = {});

/// The memory this process can take now without swapping or being killed: the system's
/// MemAvailable, and below it the room left under the process's cgroup limit (memory.max) and
/// under its limits on address space and data (ulimit -v, -d) where there are such; in bytes, 0
/// where none can be read.
std::size_t available_memory();

}  // namespace ridt
