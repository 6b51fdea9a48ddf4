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
#include "exchange.hpp"
#include "mpi.hpp"

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
  if (a.input.empty())
    error = "no input file";
  else if (a.output.empty())
    error = "no output (-o OUT.ele)";
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
  const Regions regions(std::move(points), {glo[0], glo[1], ghi[0], ghi[1]}, mpi.size);

  // Each point to the rank of its box: the share put in rank order in place (a cycle sort on
  // the owners), then sent in one call.
  std::vector<Site> sites;
  {
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
    sites = mpi.exchange(mine, counts);
    std::vector<Site>().swap(mine);
  }
  // Own points by input index, duplicates dropped (equal points share a box, so a rank sees
  // all of a group; the smallest index stands for it, as in one process).
  std::sort(sites.begin(), sites.end(), [](const Site& p, const Site& q) {
    return p.x != q.x ? p.x < q.x : p.y != q.y ? p.y < q.y : p.id < q.id;
  });
  sites.erase(
      std::unique(sites.begin(), sites.end(), [](const Site& p, const Site& q) { return p.x == q.x && p.y == q.y; }),
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
    my_hull.push_back(static_cast<std::uint32_t>(
        std::lower_bound(known.ids.begin(), known.ids.begin() + static_cast<std::ptrdiff_t>(known.own), h.id) -
        known.ids.begin()));

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
        if (q != mpi.rank && regions.box(q).distance(p.x, p.y) <= margin)
          picked[static_cast<std::size_t>(q)].push_back(static_cast<std::uint32_t>(i));
    }
    std::vector<std::vector<Site>> out(static_cast<std::size_t>(mpi.size));
    for (int q = 0; q < mpi.size; ++q)
      sent.send(q, picked[static_cast<std::size_t>(q)], known, out[static_cast<std::size_t>(q)]);
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
              asks[static_cast<std::size_t>(r)].push_back(
                  {0, s[v[0]].x, s[v[0]].y, s[v[1]].x, s[v[1]].y, s[v[2]].x, s[v[2]].y});
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
          if (q.kind == 0)
            buckets->each(q, take, wanted);
          else
            buckets->each(q, take, [](std::uint32_t) { return true; });
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
    const ridt::VertexId low =
        std::min({v[0], v[1], v[2]}, [&](ridt::VertexId p, ridt::VertexId q) { return known.ids[p] < known.ids[q]; });
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
      for (int q = 0; q < mpi.size; ++q)
        offsets[static_cast<std::size_t>(q)] = sum, sum += sizes[static_cast<std::size_t>(q)];
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
          for (int j = 0; j < 3; ++j)
            writer->put(' '), writer->put_int(static_cast<std::int64_t>(merged[3 * std::size_t(order[k]) + j]));
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
    const double row[8] = {double(st.own),        double(st.received), double(st.triangles), double(st.rounds),
                           double(st.bytes_sent), st.comm_s,           st.total_s,           st.peak_mib};
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
}  // namespace ridt::mpi

int main(int argc, char** argv) {
  using namespace ridt::mpi;
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