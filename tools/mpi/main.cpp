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
#include "args.hpp"
#include "exchange.hpp"
#include "mpi.hpp"
#include "temporaries.hpp"

namespace ridt::mpi {
namespace {

struct Stats {
  std::uint64_t own = 0, received = 0, triangles = 0, rounds = 0, bytes_sent = 0;
  double comm_s = 0, total_s = 0, peak_mib = 0;
};

double peak_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

// The triangulation of the points this rank knows, in their order.
ridt::Triangulation triangulate(const Known& k, unsigned threads) {
  ridt::Options o;
  o.method = threads > 1 ? ridt::Method::Partition : ridt::Method::Serial;
  o.threads = threads;
  return ridt::triangulate(k.points, o);
}

// Runs `step` on every rank; false, with the message of the first rank that failed on all,
// when it threw on any.
template <class Step>
bool together(Mpi& mpi, Step&& step) {
  std::string error;
  try {
    step();
  } catch (const Failure& f) {
    error = f.message;
  } catch (const std::exception& e) {
    error = e.what();
  }
  return mpi.agree(error);
}

// The k-d split of the plane: the box of all points, and a sample of each rank's share.
Regions split_plane(Mpi& mpi, const std::vector<Site>& mine) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const Site& s : mine)
    lo[0] = std::min(lo[0], s.x), lo[1] = std::min(lo[1], s.y), hi[0] = std::max(hi[0], s.x),
    hi[1] = std::max(hi[1], s.y);
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
  return Regions(std::move(points), {glo[0], glo[1], ghi[0], ghi[1]}, mpi.size);
}

// Each point to the rank of its box: the share put in rank order in place (a cycle sort on
// the owners), then sent in one call. Returns the points of this rank's box.
std::vector<Site> to_owners(Mpi& mpi, const Regions& regions, std::vector<Site> mine) {
  std::vector<int> owner(mine.size()), counts(static_cast<std::size_t>(mpi.size), 0);
  for (std::size_t i = 0; i < mine.size(); ++i)
    ++counts[static_cast<std::size_t>(owner[i] = regions.owner(mine[i].x, mine[i].y))];
  std::vector<std::size_t> next(static_cast<std::size_t>(mpi.size)), end(static_cast<std::size_t>(mpi.size));
  for (std::size_t q = 0, at = 0; q < next.size(); ++q)
    next[q] = at, end[q] = at += static_cast<std::size_t>(counts[q]);
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
  return mpi.exchange(mine, counts);
}

// What a rank works with: its regions, the points it knows (its own first), every rank's hull,
// its own hull's local indices, the buckets that answer circles, what it has sent.
struct Rank {
  Mpi& mpi;
  const Regions regions;
  Known known;
  std::vector<std::vector<Point>> hulls;
  std::vector<std::uint32_t> my_hull;
  std::optional<Buckets> buckets;
  Sent sent;
};

// Own points by input index, duplicates dropped (equal points share a box, so a rank sees all
// of a group; the smallest index stands for it, as in one process), and the hulls.
void take_own(Rank& r, std::vector<Site> sites) {
  std::sort(sites.begin(), sites.end(), regions::by_place);
  sites.erase(
      std::unique(sites.begin(), sites.end(), [](const Site& p, const Site& q) { return p.x == q.x && p.y == q.y; }),
      sites.end());
  // Every rank's convex hull, to tell which ranks have points beyond a line.
  const std::vector<Site> hull_sites = hull_of_sorted(sites);
  r.hulls = gather_hulls(r.mpi, hull_sites);
  std::sort(sites.begin(), sites.end(), [](const Site& p, const Site& q) { return p.id < q.id; });
  r.known.add(sites);
  r.known.own = sites.size();
  const auto own_end = r.known.ids.begin() + static_cast<std::ptrdiff_t>(r.known.own);
  for (const Site& h : hull_sites)  // local indices: own ids are sorted
    r.my_hull.push_back(
        static_cast<std::uint32_t>(std::lower_bound(r.known.ids.begin(), own_end, h.id) - r.known.ids.begin()));
}

// Round 0: to each other box, the own points within some three local spacings of it, sent
// unasked. The spacing is the local one (from the points around each), so clusters send a
// thin margin and sparse parts a wide one.
void send_margins(Rank& r) {
  const int ranks = r.mpi.size;
  std::vector<std::vector<std::uint32_t>> picked(static_cast<std::size_t>(ranks));
  for (std::size_t i = 0; i < r.known.own; ++i) {
    const Point& p = r.known.points[i];
    const double margin = 3 * r.buckets->spacing(p.x, p.y);
    for (int q = 0; q < ranks; ++q)
      if (q != r.mpi.rank && r.regions.box(q).distance(p.x, p.y) <= margin)
        picked[static_cast<std::size_t>(q)].push_back(static_cast<std::uint32_t>(i));
  }
  std::vector<std::vector<Site>> out(static_cast<std::size_t>(ranks));
  for (int q = 0; q < ranks; ++q) r.sent.send(q, picked[static_cast<std::size_t>(q)], r.known, out[std::size_t(q)]);
  r.known.add(r.mpi.exchange(out));
}

using Asks = std::vector<std::vector<Request>>;

// Triangle k's circle goes to every rank whose box it meets, and makes its own vertices points
// those ranks may need (a circle inside this rank's box meets no other); each hull side at an
// own point goes to the ranks with points beyond it (the others' answer would be empty).
void ask_for(const Rank& r, const ridt::Triangulation& t, std::size_t k, Asks& asks, Relevant& relevant) {
  const auto& s = r.known.points;
  const std::size_t own = r.known.own;
  const ridt::VertexId* v = &t.triangles[3 * k];
  const Disc d = circle(s[v[0]], s[v[1]], s[v[2]]);
  const Box& home = r.regions.box(r.mpi.rank);
  if (!(d.x - d.r > home.x0 && d.x + d.r < home.x1 && d.y - d.r > home.y0 && d.y + d.r < home.y1))
    for (int q = 0; q < r.mpi.size; ++q)
      if (q != r.mpi.rank && (!std::isfinite(d.r) || r.regions.box(q).distance(d.x, d.y) <= d.r)) {
        asks[std::size_t(q)].push_back({0, s[v[0]].x, s[v[0]].y, s[v[1]].x, s[v[1]].y, s[v[2]].x, s[v[2]].y});
        for (int i = 0; i < 3; ++i)
          if (v[i] < own) relevant.add(q, v[i]);
      }
  for (int i = 0; i < 3; ++i) {
    if (t.neighbors[3 * k + i] >= 0) continue;  // the hull side across from corner i, at an own point
    const ridt::VertexId p = v[(i + 1) % 3], q = v[(i + 2) % 3];
    if (p >= own && q >= own) continue;
    const Point a{s[p].x, s[p].y}, b{s[q].x, s[q].y};
    for (int o = 0; o < r.mpi.size; ++o)
      if (o != r.mpi.rank && beyond(r.hulls[std::size_t(o)], a, b))
        asks[std::size_t(o)].push_back({1, a.x, a.y, b.x, b.y, 0, 0});
  }
}

// What to ask every other rank, from the triangulation of what is known.
Asks asks_of(const Rank& r, const ridt::Triangulation& t, Relevant& relevant) {
  Asks asks(static_cast<std::size_t>(r.mpi.size));
  const std::size_t own = r.known.own;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const ridt::VertexId* v = &t.triangles[3 * k];
    if (v[0] < own || v[1] < own || v[2] < own) ask_for(r, t, k, asks, relevant);
  }
  for (const ridt::VertexId h : t.hull)
    if (h < own)
      for (int q = 0; q < r.mpi.size; ++q)
        if (q != r.mpi.rank) relevant.add(q, h);
  if (t.size() == 0) {
    relevant.everything();
    // Too few points here, or all on a line: ask everyone for everything near.
    if (own > 0)
      for (int q = 0; q < r.mpi.size; ++q)
        if (q != r.mpi.rank) asks[static_cast<std::size_t>(q)].push_back({2, 0, 0, 0, 0, 0, 0});
  }
  return asks;
}

// Beyond a hull edge: the one point that makes the smallest circle with it on that side, its
// Delaunay neighbour across the edge among this rank's points (the circle requests of the next
// round bring whatever else that triangle needs); with it, what this rank has in that
// triangle's circle, and its hull vertices beyond: along a nearly straight stretch of the hull,
// neighbour after neighbour would otherwise take a round each.
template <class Take, class Wanted>
void answer_beyond(const Rank& r, const Request& q, std::vector<std::uint32_t>& picked, Take& take, Wanted& wanted) {
  const std::optional<std::uint32_t> best = across(r.known.points, r.known.own, q);
  if (!best) return;
  picked.push_back(*best);
  const Point& b = r.known.points[*best];  // (b, a, best) is counter-clockwise
  r.buckets->each(Request{0, q.c, q.d, q.a, q.b, b.x, b.y}, take, wanted);
  for (const std::uint32_t h : r.my_hull)
    if (ridt::orientation({q.a, q.b}, {q.c, q.d}, r.known.points[h]) < 0) picked.push_back(h);
}

// The answers to every rank's requests: of the points inside circles, only those it may need.
std::vector<std::vector<Site>> answers_to(Rank& r, const Asks& asked, Relevant& relevant) {
  std::vector<std::vector<Site>> answers(static_cast<std::size_t>(r.mpi.size));
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
  auto wanted = [&](std::uint32_t i) { return relevant.wanted(i); };
  auto anything = [](std::uint32_t) { return true; };
  for (int o = 0; o < r.mpi.size; ++o) {
    relevant.begin(o);
    for (const Request& q : asked[static_cast<std::size_t>(o)])
      if (q.kind == 1)
        answer_beyond(r, q, picked, take, wanted);
      else if (q.kind == 0)
        r.buckets->each(q, take, wanted);
      else
        r.buckets->each(q, take, anything);
    relevant.end(o);
    r.sent.send(o, picked, r.known, answers[static_cast<std::size_t>(o)]);
  }
  return answers;
}

// Rounds: triangulate what is known, ask for what the kept triangles' circles and the hull
// edges at own points may be missing, until no rank learns anything. The triangulation of a
// round that learns something is dropped before the points arrive: one at a time. Returns
// false when a rank failed.
bool exchange_rounds(Rank& r, const Args& a, Stats& st, ridt::Triangulation& t) {
  for (;;) {
    ++st.rounds;
    Asks asks;
    std::optional<Relevant> relevant;
    if (!together(r.mpi, [&] {
          t = triangulate(r.known, a.threads);
          relevant.emplace(r.known.own, r.mpi.size);
          asks = asks_of(r, t, *relevant);
        }))
      return false;
    const std::vector<Site> learned = r.mpi.exchange(answers_to(r, r.mpi.exchange_by_rank(asks), *relevant));
    if (r.mpi.sum(learned.size()) == 0) return true;
    t = ridt::Triangulation{};
    r.known.add(learned);
  }
}

// The triangles this rank keeps: those whose smallest input index is an own point, in input
// indices, rotated to start there, orientation kept.
struct Kept {
  const ridt::Triangulation& t;
  const Known& known;
  bool operator()(std::size_t k, std::uint64_t out[3]) const {
    const ridt::VertexId* v = &t.triangles[3 * k];
    const ridt::VertexId low =
        std::min({v[0], v[1], v[2]}, [&](ridt::VertexId p, ridt::VertexId q) { return known.ids[p] < known.ids[q]; });
    if (low >= known.own) return false;
    const int i = v[0] == low ? 0 : v[1] == low ? 1 : 2;
    for (int j = 0; j < 3; ++j) out[j] = known.ids[v[(i + j) % 3]];
    return true;
  }
};

void put_triangle(io::Writer& w, std::uint64_t k, const std::uint64_t* v) {
  w.put_int(static_cast<std::int64_t>(k));
  for (int j = 0; j < 3; ++j) w.put(' '), w.put_int(static_cast<std::int64_t>(v[j]));
  w.put('\n');
}

// --merge: rank 0 gathers every part (a small case), sorts and writes one file.
void write_merged(Mpi& mpi, const Args& a, ridt::Triangulation& t, const Kept& kept, std::uint64_t count,
                  std::optional<io::Writer>& writer) {
  std::vector<std::uint64_t> mine;  // input indices: past 2^32 for 10^10 points
  mine.reserve(3 * count);
  std::uint64_t triangle[3];
  for (std::size_t k = 0; k < t.size(); ++k)
    if (kept(k, triangle)) mine.insert(mine.end(), triangle, triangle + 3);
  t = ridt::Triangulation{};
  std::vector<std::uint64_t> merged;
  std::vector<int> sizes(static_cast<std::size_t>(mpi.size)), offsets(static_cast<std::size_t>(mpi.size));
  const int size = static_cast<int>(mine.size());
  MPI_Gather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  int sum = 0;
  for (int q = 0; q < mpi.size; ++q) offsets[std::size_t(q)] = sum, sum += sizes[std::size_t(q)];
  if (mpi.rank == 0) merged.resize(static_cast<std::size_t>(sum));
  MPI_Gatherv(mine.data(), size, MPI_UINT64_T, merged.data(), sizes.data(), offsets.data(), MPI_UINT64_T, 0,
              MPI_COMM_WORLD);
  if (mpi.rank != 0) return;
  std::vector<std::uint32_t> order(merged.size() / 3);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t p, std::uint32_t q) {
    return std::lexicographical_compare(&merged[3 * p], &merged[3 * p + 3], &merged[3 * q], &merged[3 * q + 3]);
  });
  writer.emplace(a.output);
  writer->put_int(static_cast<std::int64_t>(order.size()));
  writer->put(" 3 0\n");
  for (std::size_t k = 0; k < order.size(); ++k) put_triangle(*writer, k, &merged[3 * std::size_t(order[k])]);
}

// A part, written straight from the triangulation (no copy in memory); rank 0 the index.
void write_part(Mpi& mpi, const Args& a, const ridt::Triangulation& t, const Kept& kept, std::uint64_t count,
                std::optional<io::Writer>& writer, std::optional<io::Writer>& index) {
  const std::filesystem::path out_path(a.output);
  const std::string stem = (out_path.parent_path() / out_path.stem()).string();
  const auto part_name = [&](int q) { return "." + std::to_string(q) + "-of-" + std::to_string(mpi.size) + ".ele"; };
  writer.emplace(stem + part_name(mpi.rank));
  writer->put_int(static_cast<std::int64_t>(count));
  writer->put(" 3 0\n");
  std::uint64_t written = 0, triangle[3];
  for (std::size_t k = 0; k < t.size(); ++k)
    if (kept(k, triangle)) put_triangle(*writer, written++, triangle);
  if (mpi.rank != 0) return;
  index.emplace(stem + ".parts");
  index->put("ridt parts " + std::to_string(mpi.size) + "\n");
  for (int q = 0; q < mpi.size; ++q) index->put(out_path.stem().string() + part_name(q) + "\n");
}

// The output: written under temporary names, and renamed only when every rank has its file
// whole. What only the rounds needed goes first.
bool write_output(Rank& r, const Args& a, Stats& st, ridt::Triangulation& t) {
  r.buckets.reset();
  r.sent = Sent(0);
  std::vector<Point>().swap(r.known.points);
  ridt::set_memory_cache_limit(0);  // the kernel's work space, kept for another round
  const Kept kept{t, r.known};
  std::uint64_t triangle[3];
  for (std::size_t k = 0; k < t.size(); ++k) st.triangles += kept(k, triangle);
  std::optional<io::Writer> writer, index;
  if (!together(r.mpi, [&] {
        if (a.merge)
          write_merged(r.mpi, a, t, kept, st.triangles, writer);
        else
          write_part(r.mpi, a, t, kept, st.triangles, writer, index);
        if (writer) writer->close();
        if (index) index->close();
      }))
    return false;
  return together(r.mpi, [&] {
    if (writer) writer->commit();
    if (index) index->commit();
  });
}

// --stats: each rank's row, printed by rank 0.
void print_stats(Mpi& mpi, const Stats& st) {
  const double row[8] = {double(st.own),        double(st.received), double(st.triangles), double(st.rounds),
                         double(st.bytes_sent), st.comm_s,           st.total_s,           st.peak_mib};
  std::vector<double> rows(mpi.rank == 0 ? 8 * static_cast<std::size_t>(mpi.size) : 0);
  MPI_Gather(row, 8, MPI_DOUBLE, rows.data(), 8, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  if (mpi.rank != 0) return;
  std::printf("rank,points,received,triangles,rounds,bytes_sent,comm_s,total_s,peak_mib\n");
  for (int q = 0; q < mpi.size; ++q) {
    const double* r = &rows[8 * static_cast<std::size_t>(q)];
    std::printf("%d,%.0f,%.0f,%.0f,%.0f,%.0f,%.4f,%.4f,%.1f\n", q, r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]);
  }
}

// Input indices are 64-bit throughout (Site::id, the parts): past 2^32 points, only each
// rank's own share must fit the kernel's 32-bit local indices, which triangulate checks.
int run(Mpi& mpi, const Args& a) {
  const auto t0 = Clock::now();
  Stats st;
  std::uint64_t n = 0;
  std::vector<Site> mine;
  if (!together(mpi, [&] { mine = read_share(mpi, a.input, n); })) return 2;
  Regions regions = split_plane(mpi, mine);
  std::vector<Site> sites = to_owners(mpi, regions, std::move(mine));
  Rank r{mpi, std::move(regions), {}, {}, {}, std::nullopt, Sent(mpi.size)};
  take_own(r, std::move(sites));
  st.own = r.known.own;
  r.buckets.emplace(r.known.points, r.known.own);
  send_margins(r);
  ridt::Triangulation t;
  if (!exchange_rounds(r, a, st, t)) return 2;
  st.received = r.known.points.size() - r.known.own;
  if (!write_output(r, a, st, t)) return 2;
  st.comm_s = mpi.comm_s;
  st.bytes_sent = mpi.bytes_sent;
  st.total_s = std::chrono::duration<double>(Clock::now() - t0).count();
  st.peak_mib = peak_mib();
  if (a.stats) print_stats(mpi, st);
  return 0;
}

}  // namespace
}  // namespace ridt::mpi

int main(int argc, char** argv) {
  using namespace ridt::mpi;
  MPI_Init(&argc, &argv);
  // A rank interrupted or killed (mpirun passes SIGINT and SIGTERM on) leaves no temporary file.
  ridt::io::end_on_signals("ridt-mpi: error: an input file could not be read to its end\n");
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