// ridt-mpi's exchange of points between ranks (main.cpp): the split of the plane into boxes,
// what each rank knows and has sent, the circles it asks about, and whom it asks.
#pragma once

#include "mpi.hpp"

namespace ridt::mpi {

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

using regions::circle;

inline Disc circle_of(const Request& q) { return circle({q.a, q.b}, {q.c, q.d}, {q.e, q.f}); }

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
    return std::sqrt(w) * std::sqrt(h) *
        std::sqrt(static_cast<double>(cells) / static_cast<double>(std::max<std::size_t>(count, 1)));
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

using regions::hull_of_sorted;

inline std::vector<std::vector<Point>> gather_hulls(Mpi& mpi, const std::vector<Site>& mine) {
  std::vector<double> flat;
  for (const Site& p : mine) flat.push_back(p.x), flat.push_back(p.y);
  std::vector<int> counts(static_cast<std::size_t>(mpi.size)), at(static_cast<std::size_t>(mpi.size));
  const int count = static_cast<int>(flat.size());
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  int total = 0;
  for (int q = 0; q < mpi.size; ++q)
    at[static_cast<std::size_t>(q)] = total, total += counts[static_cast<std::size_t>(q)];
  std::vector<double> all(static_cast<std::size_t>(total));
  MPI_Allgatherv(flat.data(), count, MPI_DOUBLE, all.data(), counts.data(), at.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  std::vector<std::vector<Point>> hulls(static_cast<std::size_t>(mpi.size));
  for (int q = 0; q < mpi.size; ++q)
    for (int k = 0; k < counts[static_cast<std::size_t>(q)]; k += 2)
      hulls[static_cast<std::size_t>(q)].push_back(
          {all[static_cast<std::size_t>(at[static_cast<std::size_t>(q)] + k)],
           all[static_cast<std::size_t>(at[static_cast<std::size_t>(q)] + k + 1)]});
  return hulls;
}

// Whether some point of a hull lies strictly to the right of the line from a to b.
inline bool beyond(const std::vector<Point>& hull, const Point& a, const Point& b) {
  for (const Point& p : hull)
    if (ridt::orientation(a, b, p) < 0) return true;
  return false;
}

// Among own points strictly to the right of the line in request q (kind 1), the one whose
// circle with the line's two points bulges least to that side: the circle's centre lies at
// m + t n (m the middle of the edge, n its outward normal), and the least t wins.
inline std::optional<std::uint32_t> across(const std::vector<Point>& s, std::size_t own, const Request& q) {
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

}  // namespace ridt::mpi
