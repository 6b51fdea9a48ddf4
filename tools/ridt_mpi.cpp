// ridt-mpi: the Delaunay triangulation of a point file too large for one machine, on MPI.
//
//   mpirun -np P ridt-mpi POINTS.bin -o OUT.ele [--merge] [--threads T] [--stats]
//
// Every rank reads its share of the .bin file (MPI-IO), the ranks split the plane into P boxes
// balanced by a sample (k-d splits), each rank triangulates the points of its box with the
// serial or threaded kernel, and then asks the other ranks for the points it is missing: those
// inside the circumcircle of a triangle it keeps, and beyond a hull edge at one of its points.
// A rank answers a circle with only those of its points whose own triangles' circles reach the
// asker's box (the others cannot be the asker's neighbours), so clustered data do not ship
// whole clusters. The rounds end when no rank learns a new point. The predicates and their symbolic
// perturbation depend on the coordinates only, so every rank decides as one process would, and
// the union of the kept triangles is the one Delaunay triangulation. A triangle is kept by the
// rank that owns its smallest input index.
//
// Output: each rank writes OUT.r-of-P.ele (Triangle's format, input indices from 0), and rank 0
// an index OUT.parts naming them, which `ridt check POINTS OUT.parts` reads; --merge writes one
// ordinary OUT.ele instead (every triangle rotated to start at its smallest index, sorted: the
// single process's `ridt triangulate -o` file). Nothing appears under a final name unless every
// rank succeeded; an error on any rank stops all with one message and exit status 2.
#include <mpi.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iterator>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "io.hpp"
#include "io_common.hpp"
#include "ridt/predicates.hpp"
#include "ridt/ridt.hpp"

namespace {

using ridt::Point;
using Clock = std::chrono::steady_clock;

// A point and its input index, as sent between ranks.
struct Site {
  double x, y;
  std::uint64_t id;
};
static_assert(sizeof(Site) == 24);

struct Box {
  double x0, y0, x1, y1;

  // The distance from (x, y) to the box (0 inside), without overflow or underflow.
  double distance(double x, double y) const {
    const double dx = x < x0 ? x0 - x : x > x1 ? x - x1 : 0;
    const double dy = y < y0 ? y0 - y : y > y1 ? y - y1 : 0;
    return std::hypot(dx, dy);
  }
};

// What a rank asks another for: its points inside or on the circumcircle of the
// counter-clockwise triangle (a, b), (c, d), (e, f) (kind 0), its neighbour across the line
// from (a, b) to (c, d) (kind 1: a point strictly to its right), or all its points (kind 2).
struct Request {
  double kind, a, b, c, d, e, f;
};

// A disc in the plane (r infinite: the whole plane).
struct Disc {
  double x, y, r;
};

// An error on one rank, to be shared with all.
struct Failure : std::exception {
  std::string message;
  explicit Failure(std::string m) : message(std::move(m)) {}
};

class Mpi {
 public:
  int rank = 0, size = 1;
  double comm_s = 0;          // time in communication calls
  std::uint64_t bytes_sent = 0;

  Mpi() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    MPI_Type_contiguous(sizeof(Site), MPI_BYTE, &site_);
    MPI_Type_commit(&site_);
    MPI_Type_contiguous(sizeof(Request), MPI_BYTE, &request_);
    MPI_Type_commit(&request_);
  }
  ~Mpi() {
    MPI_Type_free(&site_);
    MPI_Type_free(&request_);
  }

  // Every rank calls this with its error, if any; all then know whether any rank failed, and
  // rank 0 prints the lowest failing rank's message once. Returns false when any failed.
  bool agree(const std::string& error) {
    const int mine = error.empty() ? size : rank;
    int first = size;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first == size) return true;
    int length = rank == first ? static_cast<int>(error.size()) : 0;
    MPI_Bcast(&length, 1, MPI_INT, first, MPI_COMM_WORLD);
    std::string message = rank == first ? error : std::string(static_cast<std::size_t>(length), ' ');
    MPI_Bcast(message.data(), length, MPI_CHAR, first, MPI_COMM_WORLD);
    if (rank == 0) std::fprintf(stderr, "ridt-mpi: error: %s%s\n", size > 1 ? ("rank " + std::to_string(first) + ": ").c_str() : "", message.c_str());
    return false;
  }

  // Sends out[q] to rank q and returns what each rank sent here, in rank order.
  template <class T>
  std::vector<T> exchange(const std::vector<std::vector<T>>& out) {
    std::vector<T> flat;
    std::vector<int> counts(static_cast<std::size_t>(size));
    for (int q = 0; q < size; ++q) {
      counts[static_cast<std::size_t>(q)] = static_cast<int>(out[static_cast<std::size_t>(q)].size());
      flat.insert(flat.end(), out[static_cast<std::size_t>(q)].begin(), out[static_cast<std::size_t>(q)].end());
    }
    return exchange(flat, counts);
  }

  // The same for what is already in rank order: the first send_counts[0] items to rank 0, the
  // next send_counts[1] to rank 1, and so on.
  template <class T>
  std::vector<T> exchange(const std::vector<T>& flat, std::vector<int> send_counts) {
    const auto t0 = Clock::now();
    const MPI_Datatype type = std::is_same_v<T, Site> ? site_ : request_;
    std::vector<int> recv_counts(size), send_at(size), recv_at(size);
    for (int q = 0, at = 0; q < size; ++q) {
      send_at[q] = at;
      at += send_counts[q];
      if (q != rank) bytes_sent += static_cast<std::uint64_t>(send_counts[q]) * sizeof(T);
    }
    MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    std::size_t total = 0;
    for (int q = 0; q < size; ++q) recv_at[q] = static_cast<int>(total), total += recv_counts[q];
    std::vector<T> in(total);
    MPI_Alltoallv(flat.data(), send_counts.data(), send_at.data(), type, in.data(), recv_counts.data(),
                  recv_at.data(), type, MPI_COMM_WORLD);
    comm_s += std::chrono::duration<double>(Clock::now() - t0).count();
    return in;
  }

  // The same, keeping which rank each came from.
  template <class T>
  std::vector<std::vector<T>> exchange_by_rank(const std::vector<std::vector<T>>& out) {
    const auto t0 = Clock::now();
    const MPI_Datatype type = std::is_same_v<T, Site> ? site_ : request_;
    std::vector<int> send_counts(size), recv_counts(size);
    for (int q = 0; q < size; ++q) {
      send_counts[q] = static_cast<int>(out[q].size());
      if (q != rank) bytes_sent += out[q].size() * sizeof(T);
    }
    MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    std::vector<std::vector<T>> in(size);
    std::vector<MPI_Request> pending;
    for (int q = 0; q < size; ++q) {
      in[q].resize(static_cast<std::size_t>(recv_counts[q]));
      if (recv_counts[q] > 0) {
        pending.emplace_back();
        MPI_Irecv(in[q].data(), recv_counts[q], type, q, 7, MPI_COMM_WORLD, &pending.back());
      }
    }
    for (int q = 0; q < size; ++q)
      if (send_counts[q] > 0) {
        pending.emplace_back();
        MPI_Isend(out[q].data(), send_counts[q], type, q, 7, MPI_COMM_WORLD, &pending.back());
      }
    MPI_Waitall(static_cast<int>(pending.size()), pending.data(), MPI_STATUSES_IGNORE);
    comm_s += std::chrono::duration<double>(Clock::now() - t0).count();
    return in;
  }

  std::uint64_t sum(std::uint64_t v) {
    const auto t0 = Clock::now();
    std::uint64_t s = 0;
    MPI_Allreduce(&v, &s, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
    comm_s += std::chrono::duration<double>(Clock::now() - t0).count();
    return s;
  }

 private:
  MPI_Datatype site_{}, request_{};
};

// This rank's share of a .bin file of float64 pairs: points [first, first + count).
std::vector<Site> read_share(Mpi& mpi, const std::string& path, std::uint64_t& n) {
  MPI_File f;
  std::string error;
  if (MPI_File_open(MPI_COMM_WORLD, path.c_str(), MPI_MODE_RDONLY, MPI_INFO_NULL, &f) != MPI_SUCCESS)
    throw Failure("cannot read " + path);
  MPI_Offset bytes = 0;
  MPI_File_get_size(f, &bytes);
  if (bytes % 16 != 0) error = path + ": " + std::to_string(bytes) + " bytes is not a whole number of float64 pairs";
  n = static_cast<std::uint64_t>(bytes) / 16;
  const std::uint64_t first = n * mpi.rank / mpi.size, last = n * (mpi.rank + 1) / mpi.size;
  std::vector<Site> out(last - first);
  // Read through a buffer of 2^20 points, every rank the same number of times (collective
  // calls), so that the raw share is never held beside the sites.
  constexpr std::uint64_t piece = 1u << 20;
  const std::uint64_t pieces = (n / mpi.size + 1 + piece - 1) / piece + 1;
  std::vector<double> raw(2 * std::min(piece, out.size()));
  for (std::uint64_t k = 0; k < pieces; ++k) {
    const std::uint64_t from = std::min(last - first, k * piece), to = std::min(last - first, (k + 1) * piece);
    MPI_File_read_at_all(f, static_cast<MPI_Offset>((first + from) * 16), raw.data(), static_cast<int>(2 * (to - from)),
                         MPI_DOUBLE, MPI_STATUS_IGNORE);
    for (std::uint64_t i = from; i < to; ++i) out[i] = {raw[2 * (i - from)], raw[2 * (i - from) + 1], first + i};
  }
  MPI_File_close(&f);
  if (!error.empty()) throw Failure(error);
  for (std::uint64_t i = 0; i < out.size(); ++i)
    if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y))
      throw Failure(path + ": point " + std::to_string(first + i) + " is not finite");
  return out;
}

// The k-d split of the plane into one box a rank, balanced by a sample of the points. Every
// rank builds the same tree from the same gathered sample.
class Regions {
 public:
  Regions(std::vector<Point> sample, const Box& all, int ranks) : boxes_(static_cast<std::size_t>(ranks)) {
    build(sample, 0, sample.size(), all, 0, ranks);
  }

  int owner(double x, double y) const {
    std::size_t at = 0;
    for (;;) {
      const Node& node = nodes_[at];
      if (node.leaf >= 0) return node.leaf;
      at = (node.axis == 0 ? x : y) < node.split ? node.left : node.right;
    }
  }
  const Box& box(int r) const { return boxes_[static_cast<std::size_t>(r)]; }

 private:
  struct Node {
    int axis = 0, leaf = -1;
    double split = 0;
    std::size_t left = 0, right = 0;
  };

  std::size_t build(std::vector<Point>& s, std::size_t lo, std::size_t hi, const Box& b, int r0, int r1) {
    const std::size_t at = nodes_.size();
    nodes_.emplace_back();
    if (r1 - r0 == 1) {
      nodes_[at].leaf = r0;
      boxes_[static_cast<std::size_t>(r0)] = b;
      return at;
    }
    const int axis = b.x1 / 2 - b.x0 / 2 >= b.y1 / 2 - b.y0 / 2 ? 0 : 1;
    const int mid = r0 + (r1 - r0) / 2;
    const std::size_t m = lo + (hi - lo) * static_cast<std::size_t>(mid - r0) / static_cast<std::size_t>(r1 - r0);
    auto coord = [axis](const Point& p) { return axis == 0 ? p.x : p.y; };
    double split = axis == 0 ? b.x0 / 2 + b.x1 / 2 : b.y0 / 2 + b.y1 / 2;
    if (m > lo && m < hi) {
      std::nth_element(s.begin() + static_cast<std::ptrdiff_t>(lo), s.begin() + static_cast<std::ptrdiff_t>(m),
                       s.begin() + static_cast<std::ptrdiff_t>(hi),
                       [&](const Point& a, const Point& c) { return coord(a) < coord(c); });
      split = coord(s[m]);
    }
    Box left = b, right = b;
    (axis == 0 ? left.x1 : left.y1) = split;
    (axis == 0 ? right.x0 : right.y0) = split;
    nodes_[at].axis = axis;
    nodes_[at].split = split;
    const std::size_t l = build(s, lo, std::max(lo, std::min(m, hi)), left, r0, mid);
    const std::size_t r = build(s, std::max(lo, std::min(m, hi)), hi, right, mid, r1);
    nodes_[at].left = l;
    nodes_[at].right = r;
    return at;
  }

  std::vector<Node> nodes_;
  std::vector<Box> boxes_;
};

// The points this rank knows: its own (first, sorted by input index, duplicates dropped) and
// those other ranks sent. Every point has one owner and an owner sends a point to a rank once,
// so what arrives is always new.
struct Known {
  std::vector<Point> points;
  std::vector<std::uint64_t> ids;  // their input indices
  std::size_t own = 0;

  Site site(std::size_t i) const { return {points[i].x, points[i].y, ids[i]}; }

  // Appends `more`, growing the arrays by exactly that much.
  void add(const std::vector<Site>& more) {
    points.reserve(points.size() + more.size());
    ids.reserve(ids.size() + more.size());
    for (const Site& s : more) points.push_back({s.x, s.y}), ids.push_back(s.id);
  }
};

// What this rank has sent to each other rank: sorted local indices of own points.
class Sent {
 public:
  explicit Sent(int ranks) : to_(static_cast<std::size_t>(ranks)) {}

  // Appends to `out` the own points among `picked` (local indices, in any order, repeats
  // allowed) that rank r does not have yet, and remembers them.
  void send(int r, std::vector<std::uint32_t>& picked, const Known& k, std::vector<Site>& out) {
    std::sort(picked.begin(), picked.end());
    picked.erase(std::unique(picked.begin(), picked.end()), picked.end());
    std::vector<std::uint32_t>& sent = to_[static_cast<std::size_t>(r)];
    fresh_.clear();
    std::set_difference(picked.begin(), picked.end(), sent.begin(), sent.end(), std::back_inserter(fresh_));
    for (const std::uint32_t i : fresh_) out.push_back(k.site(i));
    const std::size_t before = sent.size();
    sent.insert(sent.end(), fresh_.begin(), fresh_.end());
    std::inplace_merge(sent.begin(), sent.begin() + static_cast<std::ptrdiff_t>(before), sent.end());
    picked.clear();
  }

 private:
  std::vector<std::vector<std::uint32_t>> to_;
  std::vector<std::uint32_t> fresh_;
};

struct Stats {
  std::uint64_t own = 0, received = 0, triangles = 0, rounds = 0, bytes_sent = 0;
  double comm_s = 0, total_s = 0, peak_mib = 0;
};

double peak_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

struct Args {
  std::string input, output;
  bool merge = false, stats = false;
  unsigned threads = 1;
};

void usage() {
  std::fprintf(stderr,
               "usage: mpirun -np P ridt-mpi POINTS.bin -o OUT.ele [--merge] [--threads T] [--stats]\n"
               "  POINTS.bin  raw little-endian float64 x, y pairs (ridt generate -o FILE.bin writes one)\n"
               "  -o OUT.ele  each rank writes OUT.r-of-P.ele and rank 0 the index OUT.parts\n"
               "  --merge     write one OUT.ele instead (canonical order; for sets that fit one machine)\n"
               "  --threads T threads for each rank's triangulation (default 1)\n"
               "  --stats     print each rank's points, rounds, traffic and time\n");
}

std::optional<Args> parse(int argc, char** argv, std::string& error) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw Failure(s + " needs a value");
      return argv[++i];
    };
    try {
      if (s == "-h" || s == "--help") return std::nullopt;
      if (s == "-o" || s == "--output") {
        a.output = value();
      } else if (s == "--merge") {
        a.merge = true;
      } else if (s == "--stats") {
        a.stats = true;
      } else if (s == "--threads") {
        const std::string v = value();
        const unsigned long t = std::stoul(v);
        if (t < 1 || t > 1024 || std::to_string(t) != v) throw Failure("--threads must be 1 to 1024, not " + v);
        a.threads = static_cast<unsigned>(t);
      } else if (!s.empty() && s[0] == '-') {
        throw Failure("unknown option " + s);
      } else if (a.input.empty()) {
        a.input = s;
      } else {
        throw Failure("one input file only (got " + a.input + " and " + s + ")");
      }
    } catch (const Failure& f) {
      error = f.message;
      return a;
    } catch (const std::exception&) {
      error = "bad value for " + s;
      return a;
    }
  }
  if (a.input.empty()) error = "no input file";
  else if (a.output.empty()) error = "no output (-o OUT.ele)";
  else if (ridt::io::detail::extension_of(a.input) != ".bin")
    error = a.input + ": ridt-mpi reads .bin files (float64 x, y pairs); ridt generate -o FILE.bin writes one";
  else if (ridt::io::detail::extension_of(a.output) != ".ele")
    error = a.output + ": ridt-mpi writes .ele files";
  return a;
}

// The triangulation of the points this rank knows, in their order.
ridt::Triangulation triangulate(const Known& k, unsigned threads) {
  ridt::Options o;
  o.method = threads > 1 ? ridt::Method::Partition : ridt::Method::Serial;
  o.threads = threads;
  return ridt::triangulate(k.points, o);
}

// The circumcircle of (a, b, c), widened so that it holds every point the exact in-circle
// test finds inside or on it; the whole plane when double precision cannot place it. Computed
// relative to a and scaled by the triangle's size, so that huge and tiny coordinates neither
// overflow nor underflow. Only for choosing whom to ask and where to look: which points are
// inside is decided exactly.
Disc circle(const Point& a, const Point& b, const Point& c) {
  constexpr Disc kEverything{0, 0, INFINITY};
  const double size = std::max({std::fabs(b.x - a.x), std::fabs(b.y - a.y), std::fabs(c.x - a.x), std::fabs(c.y - a.y)});
  if (!(size > 0) || !std::isfinite(size)) return kEverything;
  const double bx = (b.x - a.x) / size, by = (b.y - a.y) / size, cx = (c.x - a.x) / size, cy = (c.y - a.y) / size;
  const double d = 2 * (bx * cy - by * cx);
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
  const double radius = std::hypot(ux, uy) * size;
  const Point centre{a.x + ux * size, a.y + uy * size};
  // The rounding of a flat triangle's centre grows as the triangle flattens: a generous
  // relative margin, and a little absolute one.
  const double scale = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(centre.x), std::fabs(centre.y), radius});
  const double r = radius * (1 + 1e-6) + 1e-9 * scale;
  if (!std::isfinite(centre.x) || !std::isfinite(centre.y) || !std::isfinite(r) || d == 0) return kEverything;
  return {centre.x, centre.y, r};
}

Disc circle_of(const Request& q) { return circle({q.a, q.b}, {q.c, q.d}, {q.e, q.f}); }

// A bucket grid over this rank's own points, to answer requests without a scan.
class Buckets {
 public:
  Buckets(const std::vector<Point>& points, std::size_t own) : points_(points) {
    if (own == 0) return;
    box_ = {points[0].x, points[0].y, points[0].x, points[0].y};
    for (std::size_t i = 0; i < own; ++i) {
      box_.x0 = std::min(box_.x0, points[i].x), box_.x1 = std::max(box_.x1, points[i].x);
      box_.y0 = std::min(box_.y0, points[i].y), box_.y1 = std::max(box_.y1, points[i].y);
    }
    side_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(static_cast<double>(own) / 2)));
    start_.assign(side_ * side_ + 1, 0);
    for (std::size_t i = 0; i < own; ++i) ++start_[cell(points[i].x, points[i].y) + 1];
    std::partial_sum(start_.begin(), start_.end(), start_.begin());
    items_.resize(own);
    std::vector<std::size_t> at(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < own; ++i) items_[at[cell(points[i].x, points[i].y)]++] = static_cast<std::uint32_t>(i);
  }

  // The mean distance between own points around (x, y): from the count in the 3 x 3 cells
  // about its cell.
  double spacing(double x, double y) const {
    if (items_.empty()) return 0;
    const std::size_t i = index(x, box_.x0, box_.x1), j = index(y, box_.y0, box_.y1);
    std::size_t count = 0, cells = 0;
    for (std::size_t b = j > 0 ? j - 1 : 0; b <= std::min(j + 1, side_ - 1); ++b)
      for (std::size_t a = i > 0 ? i - 1 : 0; a <= std::min(i + 1, side_ - 1); ++a)
        count += start_[b * side_ + a + 1] - start_[b * side_ + a], ++cells;
    // A cell's sides, halved first: the box may span more than the largest double.
    const double w = (box_.x1 / 2 - box_.x0 / 2) / static_cast<double>(side_) * 2;
    const double h = (box_.y1 / 2 - box_.y0 / 2) / static_cast<double>(side_) * 2;
    return std::sqrt(w) * std::sqrt(h) * std::sqrt(static_cast<double>(cells) / static_cast<double>(std::max<std::size_t>(count, 1)));
  }

  // Calls take(i) for each own point i with want(i) inside or on the circumcircle of request q
  // (kind 0), decided by the exact in-circle test, or for every own point (kind 2). The cells
  // looked at are those the widened circle meets, row by row, so that the flat circles along
  // the hull look at a strip.
  template <class Take, class Want>
  void each(const Request& q, Take&& take, Want&& want) const {
    if (items_.empty()) return;
    const Disc c = q.kind == 2 ? Disc{0, 0, INFINITY} : circle_of(q);
    const Point a{q.a, q.b}, b{q.c, q.d}, t{q.e, q.f};
    auto test = [&](std::size_t cell) {
      for (std::size_t k = start_[cell]; k < start_[cell + 1]; ++k) {
        const std::uint32_t i = items_[k];
        if (want(i) && (q.kind == 2 || ridt::in_circle(a, b, t, points_[i]) >= 0)) take(i);
      }
    };
    if (!std::isfinite(c.r)) {
      for (std::size_t cell = 0; cell < side_ * side_; ++cell) test(cell);
      return;
    }
    if (box_.distance(c.x, c.y) > c.r) return;
    const double h = (box_.y1 / 2 - box_.y0 / 2) / static_cast<double>(side_) * 2;  // a row's height
    for (std::size_t j = index(c.y - c.r, box_.y0, box_.y1); j <= index(c.y + c.r, box_.y0, box_.y1); ++j) {
      const double y0 = j == 0 ? -INFINITY : box_.y0 + h * static_cast<double>(j);
      const double y1 = j + 1 == side_ ? INFINITY : box_.y0 + h * static_cast<double>(j + 1);
      const double dy = c.y < y0 ? y0 - c.y : c.y > y1 ? c.y - y1 : 0;
      if (dy > c.r) continue;
      const double half = std::sqrt(c.r - dy) * std::sqrt(c.r + dy) * (1 + 1e-9);
      for (std::size_t i = index(c.x - half, box_.x0, box_.x1); i <= index(c.x + half, box_.x0, box_.x1); ++i)
        test(j * side_ + i);
    }
  }

 private:
  std::size_t index(double v, double lo, double hi) const {
    if (!(hi > lo)) return 0;
    // Scaled before the difference: the box may span more than the largest double.
    const double f = (v / 2 - lo / 2) / (hi / 2 - lo / 2) * static_cast<double>(side_);
    return !(f > 0) ? 0 : f >= static_cast<double>(side_ - 1) ? side_ - 1 : static_cast<std::size_t>(f);
  }
  std::size_t cell(double x, double y) const { return index(y, box_.y0, box_.y1) * side_ + index(x, box_.x0, box_.x1); }

  const std::vector<Point>& points_;
  Box box_{};
  std::size_t side_ = 0;
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> items_;
};

// Which own points each other rank may need, judged from this rank's triangulation of the
// points it knows. A point q here is a Delaunay neighbour of a point p in rank r's box only if
// some circle through p and q is empty; that circle is empty of the points known here too, and
// the empty circles through q are covered by the circumcircles of q's triangles (on the hull,
// also by the half-planes beyond its hull edges). So q may matter to r only if one of its
// triangles' circles meets r's box, or q is on the hull. A circle request is answered with
// such points only: a wide circle between clusters does not take a whole cluster with it.
class Relevant {
 public:
  Relevant(std::size_t own, int ranks) : by_rank_(static_cast<std::size_t>(ranks)), mark_(own, 0) {}

  // Own point i may matter to rank r.
  void add(int r, std::uint32_t i) { by_rank_[static_cast<std::size_t>(r)].push_back(i); }
  // Every own point may matter to every rank (this rank has no triangle to judge by).
  void everything() { everything_ = true; }

  // Between begin(r) and end(r), whether rank r may need own point i.
  void begin(int r) {
    for (const std::uint32_t i : by_rank_[static_cast<std::size_t>(r)]) mark_[i] = 1;
  }
  bool wanted(std::uint32_t i) const { return everything_ || mark_[i]; }
  void end(int r) {
    for (const std::uint32_t i : by_rank_[static_cast<std::size_t>(r)]) mark_[i] = 0;
  }

 private:
  bool everything_ = false;
  std::vector<std::vector<std::uint32_t>> by_rank_;
  std::vector<std::uint8_t> mark_;
};

// The convex hull of points sorted by x, then y (Andrew's chain, exact orientation tests),
// counter-clockwise, collinear points left out.
std::vector<Site> hull_of_sorted(const std::vector<Site>& s) {
  if (s.size() < 3) return s;
  std::vector<std::uint32_t> h(2 * s.size());  // indices: a fraction of the points' size
  std::size_t k = 0;
  auto at = [&](std::size_t j) { return Point{s[h[j]].x, s[h[j]].y}; };
  auto add = [&](std::size_t i, std::size_t floor) {
    while (k >= floor && ridt::orientation(at(k - 2), at(k - 1), {s[i].x, s[i].y}) <= 0) --k;
    h[k++] = static_cast<std::uint32_t>(i);
  };
  for (std::size_t i = 0; i < s.size(); ++i) add(i, 2);  // the lower chain
  const std::size_t lower = k + 1;
  for (std::size_t i = s.size() - 1; i-- > 0;) add(i, lower);  // the upper chain, back
  std::vector<Site> hull(k - 1);  // the first point closes the upper chain
  for (std::size_t j = 0; j + 1 < k; ++j) hull[j] = s[h[j]];
  return hull;
}

std::vector<std::vector<Point>> gather_hulls(Mpi& mpi, const std::vector<Site>& mine) {
  std::vector<double> flat;
  for (const Site& p : mine) flat.push_back(p.x), flat.push_back(p.y);
  std::vector<int> counts(static_cast<std::size_t>(mpi.size)), at(static_cast<std::size_t>(mpi.size));
  const int count = static_cast<int>(flat.size());
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  int total = 0;
  for (int q = 0; q < mpi.size; ++q) at[static_cast<std::size_t>(q)] = total, total += counts[static_cast<std::size_t>(q)];
  std::vector<double> all(static_cast<std::size_t>(total));
  MPI_Allgatherv(flat.data(), count, MPI_DOUBLE, all.data(), counts.data(), at.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  std::vector<std::vector<Point>> hulls(static_cast<std::size_t>(mpi.size));
  for (int q = 0; q < mpi.size; ++q)
    for (int k = 0; k < counts[static_cast<std::size_t>(q)]; k += 2)
      hulls[static_cast<std::size_t>(q)].push_back({all[static_cast<std::size_t>(at[static_cast<std::size_t>(q)] + k)],
                                                    all[static_cast<std::size_t>(at[static_cast<std::size_t>(q)] + k + 1)]});
  return hulls;
}

// Whether some point of a hull lies strictly to the right of the line from a to b.
bool beyond(const std::vector<Point>& hull, const Point& a, const Point& b) {
  for (const Point& p : hull)
    if (ridt::orientation(a, b, p) < 0) return true;
  return false;
}

// Among own points strictly to the right of the line in request q (kind 1), the one whose
// circle with the line's two points bulges least to that side: the circle's centre lies at
// m + t n (m the middle of the edge, n its outward normal), and the least t wins.
std::optional<std::uint32_t> across(const std::vector<Point>& s, std::size_t own, const Request& q) {
  const Point a{q.a, q.b}, b{q.c, q.d};
  const double mx = a.x / 2 + b.x / 2, my = a.y / 2 + b.y / 2;
  const double nx = b.y - a.y, ny = a.x - b.x;  // to the right of a -> b
  const double half = std::hypot(a.x / 2 - b.x / 2, a.y / 2 - b.y / 2);
  std::optional<std::uint32_t> best;
  double best_t = INFINITY;
  for (std::size_t i = 0; i < own; ++i) {
    const Point p = s[i];
    if (ridt::orientation(a, b, p) >= 0) continue;
    // |p - (m + t n)| = |a - (m + t n)|: t = (|p - m|^2 - half^2) / (2 (p - m) . n), with n unit.
    const double len = std::hypot(nx, ny);
    const double dx = p.x - mx, dy = p.y - my;
    const double along = (dx * nx + dy * ny) / len;
    const double t = (std::hypot(dx, dy) - half) * ((std::hypot(dx, dy) + half) / (2 * along));
    if (!best || t < best_t) best = static_cast<std::uint32_t>(i), best_t = t;
  }
  return best;
}

int run(Mpi& mpi, const Args& a) {
  const auto t0 = Clock::now();
  Stats st;
  std::string error;
  std::uint64_t n = 0;
  std::vector<Site> mine;
  try {
    mine = read_share(mpi, a.input, n);
  } catch (const Failure& f) {
    error = f.message;
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (!mpi.agree(error)) return 2;
  // Input indices are 64-bit throughout (Site::id, the parts): past 2^32 points, only each
  // rank's own share must fit the kernel's 32-bit local indices, which triangulate checks.

  // The box of all points, and a sample for the split.
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const Site& s : mine) lo[0] = std::min(lo[0], s.x), lo[1] = std::min(lo[1], s.y), hi[0] = std::max(hi[0], s.x), hi[1] = std::max(hi[1], s.y);
  double glo[2], ghi[2];
  MPI_Allreduce(lo, glo, 2, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(hi, ghi, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  const std::size_t per_rank = std::max<std::size_t>(64, 65536 / static_cast<std::size_t>(mpi.size));
  std::vector<double> sample;
  const std::size_t take = std::min(per_rank, mine.size());
  for (std::size_t k = 0; k < take; ++k) {
    const Site& s = mine[k * mine.size() / take];
    sample.push_back(s.x), sample.push_back(s.y);
  }
  std::vector<int> counts(mpi.size), at(mpi.size);
  const int count = static_cast<int>(sample.size());
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  int total = 0;
  for (int q = 0; q < mpi.size; ++q) at[q] = total, total += counts[q];
  std::vector<double> all(static_cast<std::size_t>(total));
  MPI_Allgatherv(sample.data(), count, MPI_DOUBLE, all.data(), counts.data(), at.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  std::vector<Point> points(all.size() / 2);
  for (std::size_t k = 0; k < points.size(); ++k) points[k] = {all[2 * k], all[2 * k + 1]};
  const Regions regions(std::move(points), {glo[0], glo[1], ghi[0], ghi[1]}, mpi.size);

  // Each point to the rank of its box: the share put in rank order in place (a cycle sort on
  // the owners), then sent in one call.
  std::vector<Site> sites;
  {
    std::vector<int> owner(mine.size()), counts(static_cast<std::size_t>(mpi.size), 0);
    for (std::size_t i = 0; i < mine.size(); ++i) ++counts[static_cast<std::size_t>(owner[i] = regions.owner(mine[i].x, mine[i].y))];
    std::vector<std::size_t> next(static_cast<std::size_t>(mpi.size)), end(static_cast<std::size_t>(mpi.size));
    for (std::size_t q = 0, at = 0; q < next.size(); ++q) next[q] = at, end[q] = at += static_cast<std::size_t>(counts[q]);
    for (std::size_t q = 0; q < next.size(); ++q)
      while (next[q] < end[q]) {
        const std::size_t i = next[q], o = static_cast<std::size_t>(owner[i]);
        if (o == q) {
          ++next[q];
        } else {
          std::swap(mine[i], mine[next[o]]);
          std::swap(owner[i], owner[next[o]]);
          ++next[o];
        }
      }
    std::vector<int>().swap(owner);
    sites = mpi.exchange(mine, counts);
    std::vector<Site>().swap(mine);
  }
  // Own points by input index, duplicates dropped (equal points share a box, so a rank sees
  // all of a group; the smallest index stands for it, as in one process).
  std::sort(sites.begin(), sites.end(), [](const Site& p, const Site& q) {
    return p.x != q.x ? p.x < q.x : p.y != q.y ? p.y < q.y : p.id < q.id;
  });
  sites.erase(std::unique(sites.begin(), sites.end(), [](const Site& p, const Site& q) { return p.x == q.x && p.y == q.y; }),
              sites.end());
  // Every rank's convex hull, to tell which ranks have points beyond a line.
  const std::vector<Site> hull_sites = hull_of_sorted(sites);
  const std::vector<std::vector<Point>> hulls = gather_hulls(mpi, hull_sites);
  std::sort(sites.begin(), sites.end(), [](const Site& p, const Site& q) { return p.id < q.id; });
  Known known;
  known.add(sites);
  known.own = sites.size();
  std::vector<Site>().swap(sites);
  st.own = known.own;
  std::vector<std::uint32_t> my_hull;  // local indices: own ids are sorted
  for (const Site& h : hull_sites)
    my_hull.push_back(static_cast<std::uint32_t>(std::lower_bound(known.ids.begin(), known.ids.begin() + static_cast<std::ptrdiff_t>(known.own), h.id) - known.ids.begin()));

  // Round 0: to each other box, the own points within some three local spacings of it, sent
  // unasked. The spacing is the local one (from the points around each), so clusters send a
  // thin margin and sparse parts a wide one.
  std::optional<Buckets> buckets(std::in_place, known.points, known.own);
  Sent sent(mpi.size);
  {
    std::vector<std::vector<std::uint32_t>> picked(static_cast<std::size_t>(mpi.size));
    for (std::size_t i = 0; i < known.own; ++i) {
      const Point& p = known.points[i];
      const double margin = 3 * buckets->spacing(p.x, p.y);
      for (int q = 0; q < mpi.size; ++q)
        if (q != mpi.rank && regions.box(q).distance(p.x, p.y) <= margin) picked[static_cast<std::size_t>(q)].push_back(static_cast<std::uint32_t>(i));
    }
    std::vector<std::vector<Site>> out(static_cast<std::size_t>(mpi.size));
    for (int q = 0; q < mpi.size; ++q) sent.send(q, picked[static_cast<std::size_t>(q)], known, out[static_cast<std::size_t>(q)]);
    known.add(mpi.exchange(out));
  }

  // Rounds: triangulate what is known, ask for what the kept triangles' circles and the hull
  // edges at own points may be missing, until no rank learns anything. The triangulation of a
  // round that learns something is dropped before the points arrive: one at a time.
  ridt::Triangulation t;
  for (;;) {
    ++st.rounds;
    std::vector<std::vector<Request>> asks(static_cast<std::size_t>(mpi.size));
    std::optional<Relevant> relevant;
    try {
      t = triangulate(known, a.threads);
      relevant.emplace(known.own, mpi.size);
      const auto& s = known.points;
      const Box& home = regions.box(mpi.rank);
      for (std::size_t k = 0; k < t.size(); ++k) {
        const ridt::VertexId* v = &t.triangles[3 * k];
        if (v[0] >= known.own && v[1] >= known.own && v[2] >= known.own) continue;
        // Its circle goes to every rank whose box it meets, and makes its own vertices points
        // those ranks may need. A circle inside this rank's box meets no other.
        const Disc d = circle(s[v[0]], s[v[1]], s[v[2]]);
        if (!(d.x - d.r > home.x0 && d.x + d.r < home.x1 && d.y - d.r > home.y0 && d.y + d.r < home.y1))
          for (int r = 0; r < mpi.size; ++r)
            if (r != mpi.rank && (!std::isfinite(d.r) || regions.box(r).distance(d.x, d.y) <= d.r)) {
              asks[static_cast<std::size_t>(r)].push_back({0, s[v[0]].x, s[v[0]].y, s[v[1]].x, s[v[1]].y, s[v[2]].x, s[v[2]].y});
              for (int i = 0; i < 3; ++i)
                if (v[i] < known.own) relevant->add(r, v[i]);
            }
        for (int i = 0; i < 3; ++i)
          if (t.neighbors[3 * k + i] < 0) {  // the hull side across from corner i, at an own point
            const ridt::VertexId p = v[(i + 1) % 3], q = v[(i + 2) % 3];
            if (p >= known.own && q >= known.own) continue;
            // Only the ranks with points beyond: the others' answer would be empty.
            const Point a{s[p].x, s[p].y}, b{s[q].x, s[q].y};
            for (int r = 0; r < mpi.size; ++r)
              if (r != mpi.rank && beyond(hulls[static_cast<std::size_t>(r)], a, b))
                asks[static_cast<std::size_t>(r)].push_back({1, a.x, a.y, b.x, b.y, 0, 0});
          }
      }
      for (const ridt::VertexId h : t.hull)
        if (h < known.own)
          for (int r = 0; r < mpi.size; ++r)
            if (r != mpi.rank) relevant->add(r, h);
      if (t.size() == 0) {
        relevant->everything();
        // Too few points here, or all on a line: ask everyone for everything near.
        if (known.own > 0)
          for (int r = 0; r < mpi.size; ++r)
            if (r != mpi.rank) asks[static_cast<std::size_t>(r)].push_back({2, 0, 0, 0, 0, 0, 0});
      }
    } catch (const std::exception& e) {
      error = e.what();
    }
    if (!mpi.agree(error)) return 2;
    const std::vector<std::vector<Request>> asked = mpi.exchange_by_rank(asks);
    std::vector<std::vector<Site>> answers(static_cast<std::size_t>(mpi.size));
    std::vector<std::uint32_t> picked;
    std::size_t squeeze_at = 1 << 16;
    auto take = [&](std::uint32_t i) {
      picked.push_back(i);
      if (picked.size() == squeeze_at) {  // overlapping circles: repeats kept to a few
        std::sort(picked.begin(), picked.end());
        picked.erase(std::unique(picked.begin(), picked.end()), picked.end());
        squeeze_at = std::max(squeeze_at, 2 * picked.size());
      }
    };
    auto wanted = [&](std::uint32_t i) { return relevant->wanted(i); };
    for (int r = 0; r < mpi.size; ++r) {
      // Of the points inside circles, only those r may need.
      relevant->begin(r);
      for (const Request& q : asked[static_cast<std::size_t>(r)])
        if (q.kind == 1) {
          // Beyond a hull edge: the one point that makes the smallest circle with it on that
          // side, its Delaunay neighbour across the edge among this rank's points. The circle
          // requests of the next round bring whatever else that triangle needs.
          const std::optional<std::uint32_t> best = across(known.points, known.own, q);
          if (!best) continue;
          picked.push_back(*best);
          // With it, what this rank has in that triangle's circle, which the asker would
          // otherwise ask for in the next round.
          // (b, a, best) is counter-clockwise: best lies to the right of a -> b.
          const Point& b = known.points[*best];
          buckets->each(Request{0, q.c, q.d, q.a, q.b, b.x, b.y}, take, wanted);
          // And this rank's hull vertices beyond: along a nearly straight stretch of the hull,
          // neighbour after neighbour would otherwise take a round each.
          for (const std::uint32_t h : my_hull)
            if (ridt::orientation({q.a, q.b}, {q.c, q.d}, known.points[h]) < 0) picked.push_back(h);
        } else {
          if (q.kind == 0) buckets->each(q, take, wanted);
          else buckets->each(q, take, [](std::uint32_t) { return true; });
        }
      relevant->end(r);
      sent.send(r, picked, known, answers[static_cast<std::size_t>(r)]);
    }
    const std::vector<Site> learned = mpi.exchange(answers);
    if (mpi.sum(learned.size()) == 0) break;
    t = ridt::Triangulation{};
    known.add(learned);
  }
  st.received = known.points.size() - known.own;

  // Output: the triangles whose smallest input index is an own point, in input indices,
  // rotated to start there, orientation kept. What only the rounds needed goes first.
  buckets.reset();
  sent = Sent(0);
  std::vector<Point>().swap(known.points);
  ridt::set_memory_cache_limit(0);  // the kernel's work space, kept for another round
  auto kept = [&](std::size_t k, std::uint64_t out[3]) {
    const ridt::VertexId* v = &t.triangles[3 * k];
    const ridt::VertexId low = std::min({v[0], v[1], v[2]}, [&](ridt::VertexId p, ridt::VertexId q) {
      return known.ids[p] < known.ids[q];
    });
    if (low >= known.own) return false;
    const int i = v[0] == low ? 0 : v[1] == low ? 1 : 2;
    for (int j = 0; j < 3; ++j) out[j] = known.ids[v[(i + j) % 3]];
    return true;
  };
  std::uint64_t triangle[3];
  for (std::size_t k = 0; k < t.size(); ++k) st.triangles += kept(k, triangle);
  const std::filesystem::path out_path(a.output);
  const std::string stem = (out_path.parent_path() / out_path.stem()).string();
  const std::string part = stem + "." + std::to_string(mpi.rank) + "-of-" + std::to_string(mpi.size) + ".ele";
  std::optional<ridt::io::detail::Writer> writer, index;
  try {
    if (a.merge) {
      // Rank 0 gathers every part (a small case), sorts and writes one file.
      std::vector<std::uint64_t> mine_kept;  // input indices: past 2^32 for 10^10 points
      mine_kept.reserve(3 * st.triangles);
      for (std::size_t k = 0; k < t.size(); ++k)
        if (kept(k, triangle)) mine_kept.insert(mine_kept.end(), triangle, triangle + 3);
      t = ridt::Triangulation{};
      std::vector<std::uint64_t> merged;
      std::vector<int> sizes(static_cast<std::size_t>(mpi.size)), offsets(static_cast<std::size_t>(mpi.size));
      const int size = static_cast<int>(mine_kept.size());
      MPI_Gather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
      int sum = 0;
      for (int q = 0; q < mpi.size; ++q) offsets[static_cast<std::size_t>(q)] = sum, sum += sizes[static_cast<std::size_t>(q)];
      if (mpi.rank == 0) merged.resize(static_cast<std::size_t>(sum));
      MPI_Gatherv(mine_kept.data(), size, MPI_UINT64_T, merged.data(), sizes.data(), offsets.data(), MPI_UINT64_T, 0,
                  MPI_COMM_WORLD);
      if (mpi.rank == 0) {
        std::vector<std::uint32_t> order(merged.size() / 3);
        std::iota(order.begin(), order.end(), 0u);
        std::sort(order.begin(), order.end(), [&](std::uint32_t p, std::uint32_t q) {
          return std::lexicographical_compare(&merged[3 * p], &merged[3 * p + 3], &merged[3 * q], &merged[3 * q + 3]);
        });
        writer.emplace(a.output);
        writer->put_int(static_cast<std::int64_t>(order.size()));
        writer->put(" 3 0\n");
        for (std::size_t k = 0; k < order.size(); ++k) {
          writer->put_int(static_cast<std::int64_t>(k));
          for (int j = 0; j < 3; ++j) writer->put(' '), writer->put_int(static_cast<std::int64_t>(merged[3 * std::size_t(order[k]) + j]));
          writer->put('\n');
        }
      }
    } else {
      // Written straight from the triangulation: no copy of the part in memory.
      writer.emplace(part);
      writer->put_int(static_cast<std::int64_t>(st.triangles));
      writer->put(" 3 0\n");
      std::uint64_t written = 0;
      for (std::size_t k = 0; k < t.size(); ++k)
        if (kept(k, triangle)) {
          writer->put_int(static_cast<std::int64_t>(written++));
          for (int j = 0; j < 3; ++j) writer->put(' '), writer->put_int(static_cast<std::int64_t>(triangle[j]));
          writer->put('\n');
        }
      if (mpi.rank == 0) {
        index.emplace(stem + ".parts");
        index->put("ridt parts " + std::to_string(mpi.size) + "\n");
        for (int q = 0; q < mpi.size; ++q)
          index->put(out_path.stem().string() + "." + std::to_string(q) + "-of-" + std::to_string(mpi.size) + ".ele\n");
      }
    }
    if (writer) writer->close();
    if (index) index->close();
  } catch (const std::exception& e) {
    error = e.what();
  }
  // Only when every rank has its file whole do the files take their names.
  if (!mpi.agree(error)) return 2;
  try {
    if (writer) writer->commit();
    if (index) index->commit();
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (!mpi.agree(error)) return 2;

  st.comm_s = mpi.comm_s;
  st.bytes_sent = mpi.bytes_sent;
  st.total_s = std::chrono::duration<double>(Clock::now() - t0).count();
  st.peak_mib = peak_mib();
  if (a.stats) {
    const double row[8] = {double(st.own), double(st.received), double(st.triangles), double(st.rounds),
                           double(st.bytes_sent), st.comm_s, st.total_s, st.peak_mib};
    std::vector<double> rows(mpi.rank == 0 ? 8 * static_cast<std::size_t>(mpi.size) : 0);
    MPI_Gather(row, 8, MPI_DOUBLE, rows.data(), 8, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    if (mpi.rank == 0) {
      std::printf("rank,points,received,triangles,rounds,bytes_sent,comm_s,total_s,peak_mib\n");
      for (int q = 0; q < mpi.size; ++q) {
        const double* r = &rows[8 * static_cast<std::size_t>(q)];
        std::printf("%d,%.0f,%.0f,%.0f,%.0f,%.0f,%.4f,%.4f,%.1f\n", q, r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]);
      }
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int status = 0;
  {
    Mpi mpi;
    std::string error;
    const std::optional<Args> a = parse(argc, argv, error);
    if (!a) {
      if (mpi.rank == 0) usage();
    } else if (!mpi.agree(error)) {
      if (mpi.rank == 0) usage();
      status = 2;
    } else {
      status = run(mpi, *a);
    }
  }
  MPI_Finalize();
  return status;
}
