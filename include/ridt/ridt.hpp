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
#include <vector>

namespace ridt {

/// A point in the plane.
struct Point {
  double x = 0;
  double y = 0;
  friend bool operator==(const Point&, const Point&) = default;
};

using VertexId = std::uint32_t;
using TriangleId = std::uint32_t;
/// Marks "no triangle" in neighbour lists of the result (a hull edge).
inline constexpr std::int32_t kNoNeighbor = -1;

/// Who drives the insertion kernel.
enum class Method {
  Serial,       ///< one thread, the paper's Fig. 4
  Pessimistic,  ///< threads share one triangulation; one critical section for the leaf step (Fig. 10)
  Optimistic,   ///< threads lock only the triangles an insertion changes (try-lock, back off)
  Batch,        ///< threads - 1 locators queue DAG nodes for one modifier thread
  /// Threads own regions of the plane (stretches of each BRIO round's curve) and insert into
  /// one mesh without a lock and without a DAG; the points near a region's border go to a
  /// second pass with other borders, and what is left to one thread. BRIO order, walking.
  Partition,
};

/// The order in which points are inserted.
enum class Order {
  Random,  ///< a uniformly random permutation: the paper's order
  Brio,    ///< biased randomized: random rounds of doubling size, each along a Hilbert curve
};

/// How an insertion finds the triangle that holds its point.
enum class Locate {
  Auto,  ///< Walk where the method and the order allow it, else Dag
  Dag,   ///< descend the history DAG in rounds along a curve (serial and the paper's methods)
  Walk,  ///< walk from the last insertion; keeps no DAG (serial and partition, BRIO order)
  /// The paper's own location: every point descends the history DAG from its root when its
  /// turn comes, with no rounds and no look-ahead (serial and the paper's three methods).
  Root,
};

/// The starting triangle that encloses every point.
enum class Bounding {
  Symbolic,  ///< vertices at infinity, decided combinatorially: the hull is always complete
  Finite,    ///< the paper's (K,0), (0,K), (-K,-K) around the box centre, K = k * box size
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
  /// Threads of a threaded method; 0 = the machine's hardware threads. Batch: threads - 1
  /// locators and one modifier.
  unsigned threads = 0;
  std::uint64_t seed = 1;  ///< seed of the random insertion order
  Order order = Order::Brio;
  Locate locate = Locate::Auto;
  /// Rotate each triangle so its smallest vertex index comes first and sort the triangles:
  /// the output is then byte-identical for every seed and method. Costs a sort.
  bool canonical_order = false;
  /// Called with the share of the points inserted so far (0 to 1), on the calling thread, each
  /// time some 65,536 more are in, and with 1 when all are. It may throw to abandon the run:
  /// the exception reaches the caller of triangulate once every worker has stopped.
  std::function<void(double)> progress;
  /// The paper's experiment switches (Bounding::Finite makes the result depend on them).
  Experiment experiment;
};

/// What one thread did (the paper's Tables 2 and 3, per thread).
struct ThreadStats {
  std::string role = "worker";  ///< "worker"; batch: "modifier" or "locator"
  std::uint64_t points = 0;     ///< points it inserted (a locator: located; duplicates included)
  double time_insert_s = 0;     ///< from its start to its end
  double time_critical_s = 0;   ///< pessimistic: holding the lock; optimistic: holding triangles
  /// Pessimistic: waiting for the lock; optimistic: backing off after a failed try-lock; both
  /// also waiting for the others at the end of a round. Batch: the modifier waiting for a
  /// hint, a locator waiting for room in the queue.
  double time_wait_s = 0;
  std::uint64_t retries = 0;    ///< optimistic: insertions restarted after a failed try-lock
};

/// Counters and timings of one run.
struct Stats {
  unsigned threads = 1;          ///< threads that inserted points
  std::uint64_t points = 0;      ///< input points
  std::uint64_t distinct = 0;    ///< distinct points
  std::uint64_t duplicates = 0;  ///< input points dropped as duplicates
  std::uint64_t dag_nodes = 0;   ///< triangle records made (each one a node of the history DAG); 0 when walking
  /// Edge flips during legalization. Walking (cavity insertion): the flips the same insertions
  /// would have made, the triangles each cavity replaced beyond the first.
  std::uint64_t flips = 0;
  std::uint64_t edge_splits = 0; ///< points inserted on an edge (2 -> 4 splits); 0 when walking
  double time_triangulate_s = 0; ///< the whole call: set-up, insertion, finish
  double time_insert_s = 0;      ///< wall time of the insertion phase
  double time_critical_s = 0;    ///< summed over threads (threaded methods, Experiment::time_threads)
  double time_wait_s = 0;        ///< summed over threads (threaded methods, Experiment::time_threads)
  /// Optimistic: insertions restarted after a failed try-lock; partition: points put off to a
  /// later pass because they met another thread's region.
  std::uint64_t retries = 0;
  Locate locate = Locate::Dag;   ///< the location used (Locate::Auto made definite)
  double time_idle_s = 0;        ///< batch: the modifier waiting for hints
  double time_stall_s = 0;       ///< batch: locators waiting for room in the queue, summed
  double queue_depth_mean = 0;   ///< batch: hints queued ahead of the modifier, on average
  std::uint64_t stale_hints = 0; ///< batch: hints no longer a leaf when the modifier took them
  std::vector<ThreadStats> per_thread;
  double time_locate_s = 0;      ///< only with Experiment::profile
  double time_split_s = 0;       ///< only with Experiment::profile
  double time_legalize_s = 0;    ///< only with Experiment::profile
};

/// A dropped duplicate input point and the input index that stands for it (the smallest
/// index among the equal points).
struct Duplicate {
  VertexId dropped;
  VertexId kept;
};

/// The result: flat arrays, as plain data.
struct Triangulation {
  std::vector<VertexId> triangles;     ///< #T by 3, counter-clockwise
  std::vector<std::int32_t> neighbors; ///< #T by 3, neighbour i across from vertex i, -1 on the hull
  std::vector<VertexId> hull;          ///< convex hull, counter-clockwise, collinear hull points included
  std::vector<Duplicate> duplicates;   ///< sorted by `dropped`
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

/// Triangulates `points`; the library copies what it keeps.
Triangulation triangulate(std::span<const Point> points, const Options& options = {});

/// The same for a flat array x0, y0, x1, y1, ... (its size must be even).
Triangulation triangulate(std::span<const double> xy, const Options& options = {});

/// triangulate keeps the large blocks of its work space (the triangle records, some 250 bytes
/// a point, and its copy of the points) for the next call in the process instead of giving
/// them back to the system, up to this many bytes in all: 512 MiB by default (enough for some
/// two million points), none in builds with AddressSanitizer or ThreadSanitizer. A block the
/// system hands out anew has its pages faulted in and zeroed on first touch, which can take a
/// third of a call's time. Set 0 when one call is all a process makes, or to give back at
/// once what is kept: kept blocks also raise the call's peak memory, since the records are
/// then kept while the result is written. Thread-safe. Returns the previous limit.
std::size_t set_memory_cache_limit(std::size_t bytes);

/// The bytes kept now for the next call (see set_memory_cache_limit).
std::size_t cached_memory();

}  // namespace ridt
