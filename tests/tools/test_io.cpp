// Point and triangle files: exact round trips, every error with its message, and writes that
// never leave a partial or stray file behind.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "io.hpp"
#include "tools/scratch_dir.hpp"

namespace ridt::io {
namespace {

namespace fs = std::filesystem;

class IoTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::fresh_test_dir("ridt_io"); }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  void write_file(const std::string& name, const std::string& content) const {
    std::ofstream f(path(name), std::ios::binary);
    f << content;
    ASSERT_TRUE(f.good());
  }

  std::string read_file(const std::string& name) const {
    std::ifstream f(path(name), std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
  }

  /// Names of the files in the directory (to catch stray temporaries).
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  /// The message of the IoError that `f` throws ("" and a failure if it throws none).
  template <class F>
  static std::string error_of(F&& f) {
    try {
      f();
    } catch (const IoError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no IoError thrown";
    return "";
  }

  fs::path dir_;
};

/// `text` contains `part` (gtest without gmock).
::testing::AssertionResult Has(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" lacks \"" << part << "\"";
}

std::vector<Point> tricky_points() {
  const double two53 = 9007199254740992.0;  // 2^53
  return {
      {0.1, 0.2},
      {1e-300, -1e-300},
      {-0.0, 0.0},
      {two53 + 2, -(two53 + 2)},
      {std::nextafter(two53, 0.0), std::nextafter(1.0, 2.0)},
      {std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest()},
      {std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min()},
      {1.0 / 3.0, 123456789.123456789},
      {-2.5, 1e22},
      {3.141592653589793, 2.718281828459045},
  };
}

std::vector<Point> copy_of(const PointFile& f) { return {f.points.begin(), f.points.end()}; }

/// Equal bit for bit (so -0.0 differs from 0.0).
void expect_same_bits(std::span<const Point> a, std::span<const Point> b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(std::memcmp(&a[i].x, &b[i].x, sizeof(double)), 0) << "point " << i << " x";
    EXPECT_EQ(std::memcmp(&a[i].y, &b[i].y, sizeof(double)), 0) << "point " << i << " y";
  }
}

// A file larger than the writer's buffer (the .bin triangles go in one write) reads back as
// written, line for line, in every triangle format; the text formats, formatted in runs on
// threads (waves of them while the wave before is written), are the same bytes on any number.
TEST_F(IoTest, LargeTriangleFilesComeBackInOrder) {
  const std::size_t count = 3 * 65536 + 123, n = 100000;
  Triangulation t;
  std::uint64_t state = 7;
  auto next = [&] { return state = state * 6364136223846793005u + 1442695040888963407u, state >> 33; };
  for (std::size_t k = 0; k < 3 * count; ++k) {
    t.triangles.push_back(static_cast<VertexId>(next() % n));
    t.neighbors.push_back(static_cast<std::int32_t>(next() % (count + 1)) - 1);
  }
  const std::vector<Point> points(n, Point{0, 0});
  for (const std::string ext : {".ele", ".bin"}) {
    write_triangulation(path("big" + ext), points, t, 1);
    EXPECT_EQ(read_triangles(path("big" + ext), 1), t.triangles) << ext;
  }
  write_triangulation(path("big.neigh"), points, t, 1);
  std::ifstream in(path("big.neigh"));
  std::size_t header = 0, three = 0;
  in >> header >> three;
  ASSERT_EQ(header, count);
  for (std::size_t k = 0; k < count; ++k) {
    std::int64_t index = 0, nb[3];
    in >> index >> nb[0] >> nb[1] >> nb[2];
    ASSERT_EQ(index, static_cast<std::int64_t>(k) + 1);
    for (int i = 0; i < 3; ++i) {
      const std::int32_t want = t.neighbors[3 * k + i];
      ASSERT_EQ(nb[i], want < 0 ? -1 : want + 1) << k;
    }
  }
  for (const std::string ext : {".ele", ".neigh"})
    for (const unsigned threads : {2u, 3u, 5u}) {
      write_triangulation(path("threads" + ext), points, t, 1, threads);
      EXPECT_EQ(read_file("threads" + ext), read_file("big" + ext)) << ext << " " << threads;
    }
}

// Triangle's group of files written in two lanes on threads (the triangles' files beside the
// points' and the edges'): every file the same, byte for byte, on any number of threads; and
// where one of them cannot be written, none that was not there before is left, on threads too.
TEST_F(IoTest, MeshFilesTheSameOnAnyThreads) {
  const std::size_t count = 65536 + 77, n = 70000;  // (some runs of 32,768 lines in each file)
  std::uint64_t state = 11;
  auto next = [&] { return state = state * 6364136223846793005u + 1442695040888963407u, state >> 33; };
  std::vector<Point> points(n);
  for (Point& p : points) p = {static_cast<double>(next()) / 7.0, -static_cast<double>(next()) / 3.0};
  std::vector<VertexId> triangles(3 * count), edges(2 * (n / 2));
  std::vector<std::int32_t> neighbors(3 * count);
  for (VertexId& v : triangles) v = static_cast<VertexId>(next() % n);
  for (std::int32_t& t : neighbors) t = static_cast<std::int32_t>(next() % (count + 1)) - 1;
  for (VertexId& v : edges) v = static_cast<VertexId>(next() % n);
  std::vector<std::int64_t> point_markers(n), edge_markers(edges.size() / 2);
  for (std::int64_t& m : point_markers) m = static_cast<std::int64_t>(next() % 3);
  for (std::int64_t& m : edge_markers) m = static_cast<std::int64_t>(next() % 5);
  MeshFiles m;
  m.files.neighbors = m.files.off = true;
  m.points = points, m.triangles = triangles, m.edges = edges, m.neighbors = neighbors;
  m.point_markers = point_markers, m.edge_markers = edge_markers;
  m.edge_count = edges.size() / 2;
  m.first_index = 1;
  write_mesh_files(path("one.ele"), m, 1);
  for (const unsigned threads : {2u, 3u, 5u}) {
    const std::string name = std::to_string(threads) + "threads";
    write_mesh_files(path(name + ".ele"), m, threads);
    for (const std::string ext : {".ele", ".node", ".edge", ".neigh", ".off"})
      EXPECT_EQ(read_file(name + ext), read_file("one" + ext)) << ext << " " << threads;
  }
  fs::create_directory(path("in_way.edge"));
  const std::vector<std::string> before = listing();
  EXPECT_TRUE(Has(error_of([&] { write_mesh_files(path("in_way.ele"), m, 2); }), "in_way.edge"));
  EXPECT_EQ(listing(), before);
  // A point that cannot be written fails the points' lane while the triangles' goes on: neither
  // file is left, nor a temporary one.
  points[n / 2].x = std::numeric_limits<double>::infinity();
  for (const unsigned threads : {1u, 2u}) {
    EXPECT_TRUE(Has(error_of([&] { write_mesh_files(path("bad.ele"), m, threads); }), "bad.node")) << threads;
    EXPECT_EQ(listing(), before) << threads;
  }
}

TEST_F(IoTest, PointRoundTripEveryFormat) {
  const std::vector<Point> pts = tricky_points();
  for (const char* name : {"p.txt", "p.xy", "p.pts", "p.dat", "p.csv", "p.node", "p.bin", "noextension"}) {
    SCOPED_TRACE(name);
    write_points(path(name), pts);
    const PointFile back = read_points(path(name));
    EXPECT_EQ(back.first_index, 0);
    expect_same_bits(back.points, pts);
    EXPECT_TRUE(std::signbit(back.points[2].x));
  }
  EXPECT_EQ(fs::file_size(path("p.bin")), 16 * pts.size());
  EXPECT_EQ(listing(),
            (std::vector<std::string>{"noextension", "p.bin", "p.csv", "p.dat", "p.node", "p.pts", "p.txt", "p.xy"}));
}

// An extension that names a format is written in it, or refused: .csv and .ply were text.
TEST_F(IoTest, PointOutputExtensionsNameTheirFormat) {
  const std::vector<Point> pts = {{0.1, -2}, {1e-300, 3.5}};
  write_points(path("p.csv"), pts);
  EXPECT_EQ(read_file("p.csv"), "0.1,-2\n1e-300,3.5\n");
  write_points(path("p.ply"), pts);
  const std::string ply = read_file("p.ply");
  EXPECT_EQ(ply.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
  EXPECT_TRUE(Has(ply, "element vertex 2\n"));
  EXPECT_EQ(ply.size(), ply.find("end_header\n") + 11 + 2 * 24);
  for (const char* name : {"p.ele", "p.off", "p.svg", "p.json", "p.xyz"}) {
    SCOPED_TRACE(name);
    const std::string msg = error_of([&] { write_points(path(name), pts); });
    EXPECT_TRUE(Has(msg, "unknown point output extension"));
    EXPECT_TRUE(Has(msg, ".csv"));
    EXPECT_FALSE(fs::exists(path(name)));
  }
}

// A .bin file is mapped, not read: the points stay valid when the PointFile moves, they equal
// what the in-memory parser makes of the same bytes, and a file that cannot be mapped (a
// pipe) is read instead.
TEST_F(IoTest, BinPointsMappedOrRead) {
  const std::vector<Point> pts = tricky_points();
  write_points(path("m.bin"), pts);
  PointFile moved;
  {
    PointFile first = read_points(path("m.bin"));
    moved = std::move(first);
  }
  expect_same_bits(moved.points, pts);
  expect_same_bits(parse_points(read_file("m.bin"), "m.bin").points, pts);

  const std::string fifo = path("pipe.bin");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] {
    std::ofstream out(fifo, std::ios::binary);
    const std::string bytes = read_file("m.bin");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
  const PointFile piped = read_points(fifo);
  writer.join();
  expect_same_bits(piped.points, pts);
}

TEST_F(IoTest, WrittenPointFormats) {
  const std::vector<Point> pts = {{0.1, -2}, {1e-300, 3.5}};
  write_points(path("p.txt"), pts);
  EXPECT_EQ(read_file("p.txt"), "0.1 -2\n1e-300 3.5\n");
  write_points(path("p.node"), pts);
  EXPECT_EQ(read_file("p.node"), "2 2 0 0\n0 0.1 -2\n1 1e-300 3.5\n");
  write_points(path("p.bin"), pts);
  const std::string bin = read_file("p.bin");
  ASSERT_EQ(bin.size(), 32u);
  // Little-endian float64: the last byte of -2.0 (0xC000000000000000) is 0xC0.
  EXPECT_EQ(static_cast<unsigned char>(bin[15]), 0xC0);
  EXPECT_EQ(static_cast<unsigned char>(bin[8]), 0x00);
}

TEST_F(IoTest, EmptyPointFiles) {
  write_points(path("e.txt"), {});
  write_points(path("e.node"), {});
  write_points(path("e.bin"), {});
  EXPECT_EQ(read_file("e.node"), "0 2 0 0\n");
  for (const char* name : {"e.txt", "e.node", "e.bin"}) EXPECT_TRUE(read_points(path(name)).points.empty());
}

TEST_F(IoTest, TextCommasCommentsBlankLines) {
  write_file("c.txt",
             "# a header comment\n"
             "\n"
             "1,2\n"
             "  3 , 4  # trailing comment\n"
             "5 ,6\r\n"
             "\t7,\t8\n"
             "   \n"
             "+9 -1e3\n"
             "1.5e-3 .25");  // no final newline
  const PointFile f = read_points(path("c.txt"));
  EXPECT_EQ(f.first_index, 0);
  EXPECT_EQ(copy_of(f), (std::vector<Point>{{1, 2}, {3, 4}, {5, 6}, {7, 8}, {9, -1000}, {0.0015, 0.25}}));
}

TEST_F(IoTest, NodeFirstIndexOne) {
  write_file("one.node",
             "# Triangle's format\n"
             "3 2 1 1  # points, dimension, attributes, markers\n"
             "1 0.5 1.5 7.25 0\n"
             "\n"
             "2 -1 2 0 1\n"
             "3 4 5 1e3 0 # last\n");
  const PointFile f = read_points(path("one.node"));
  EXPECT_EQ(f.first_index, 1);
  EXPECT_EQ(copy_of(f), (std::vector<Point>{{0.5, 1.5}, {-1, 2}, {4, 5}}));
}

TEST_F(IoTest, NodeFirstIndexZeroAndShortHeader) {
  write_file("zero.node", "2 2\n0 1 2\n1 3 4\n");
  const PointFile f = read_points(path("zero.node"));
  EXPECT_EQ(f.first_index, 0);
  EXPECT_EQ(copy_of(f), (std::vector<Point>{{1, 2}, {3, 4}}));
  write_file("empty.node", "0 2 0 0\n");
  EXPECT_TRUE(read_points(path("empty.node")).points.empty());
}

TEST_F(IoTest, MissingFile) {
  const std::string msg = error_of([&] { read_points(path("nope.txt")); });
  EXPECT_TRUE(Has(msg, "cannot read " + path("nope.txt") + ": "));
  EXPECT_TRUE(Has(msg, std::strerror(ENOENT)));
  EXPECT_TRUE(Has(error_of([&] { read_triangles(path("nope.ele"), 0); }), "cannot read"));
  EXPECT_TRUE(Has(error_of([&] { read_points(dir_.string()); }), "cannot read"));
}

TEST_F(IoTest, MalformedTextLineNamesFileAndLine) {
  write_file("points.txt", "0 0\n# comment\n1.5 abc\n");
  EXPECT_EQ(error_of([&] { read_points(path("points.txt")); }),
            path("points.txt") + ":3: expected two numbers \"x y\" or \"x,y\", got \"1.5 abc\"");
  for (const char* bad :
       {"1", "1 2 3", "1,2,", ",1 2", "1,,2", "1;2", "1 2x", "0x1 2", "1 - 2", "1e 2", "+-1 2", "1..2 3"}) {
    SCOPED_TRACE(bad);
    write_file("bad.txt", std::string("0 0\n\n") + bad + "\n4 4\n");
    const std::string msg = error_of([&] { read_points(path("bad.txt")); });
    EXPECT_TRUE(Has(msg, "bad.txt:3: expected two numbers"));
    EXPECT_TRUE(Has(msg, std::string("\"") + bad + "\""));
  }
}

TEST_F(IoTest, NanAndInfinityRejectedInText) {
  write_file("n.txt", "0 0\n1 1\nnan 2\n");
  EXPECT_EQ(error_of([&] { read_points(path("n.txt")); }), path("n.txt") + ":3: coordinate is NaN");
  write_file("i.txt", "0 0\n1 -inf\n");
  EXPECT_EQ(error_of([&] { read_points(path("i.txt")); }), path("i.txt") + ":2: coordinate is infinite");
  write_file("r.txt", "1e400 0\n");
  EXPECT_EQ(error_of([&] { read_points(path("r.txt")); }), path("r.txt") + ":1: coordinate \"1e400\" is out of range");
  write_file("n.node", "2 2 0 0\n0 0 0\n1 NaN 1\n");
  EXPECT_TRUE(Has(error_of([&] { read_points(path("n.node")); }), "n.node:3: coordinate is NaN"));
  write_file("i.node", "1 2\n0 1 infinity\n");
  EXPECT_TRUE(Has(error_of([&] { read_points(path("i.node")); }), "i.node:2: coordinate is infinite"));
}

TEST_F(IoTest, NanAndInfinityRejectedInBin) {
  std::vector<Point> pts(20, Point{1, 2});
  pts[12].y = std::numeric_limits<double>::quiet_NaN();
  // The writer refuses them (nothing written); a file made otherwise is refused by the reader.
  EXPECT_TRUE(Has(error_of([&] { write_points(path("n.bin"), pts); }), "not finite"));
  EXPECT_TRUE(listing().empty());
  const auto raw = [&](const std::string& name) {
    write_file(name, std::string(reinterpret_cast<const char*>(pts.data()), pts.size() * sizeof(Point)));
  };
  raw("n.bin");
  EXPECT_EQ(error_of([&] { read_points(path("n.bin")); }), path("n.bin") + ": point 12 has a NaN coordinate");
  pts[12].y = 0;
  pts[3].x = -std::numeric_limits<double>::infinity();
  raw("i.bin");
  EXPECT_TRUE(Has(error_of([&] { read_points(path("i.bin")); }), "point 3 has an infinite coordinate"));
}

TEST_F(IoTest, BinSizeNotMultipleOf16) {
  write_file("odd.bin", std::string(17, '\0'));
  const std::string msg = error_of([&] { read_points(path("odd.bin")); });
  EXPECT_TRUE(Has(msg, path("odd.bin") + ": "));
  EXPECT_TRUE(Has(msg, "17"));
  EXPECT_TRUE(Has(msg, "multiple of 16"));
  write_file("eight.bin", std::string(8, '\0'));
  EXPECT_TRUE(Has(error_of([&] { read_points(path("eight.bin")); }), "multiple of 16"));
}

TEST_F(IoTest, NodeCountMismatch) {
  write_file("short.node", "5 2 0 0\n0 0 0\n1 1 0\n2 0 1\n");
  EXPECT_EQ(error_of([&] { read_points(path("short.node")); }),
            path("short.node") + ": header says 5 points but the file has 3");
  write_file("long.node", "1 2 0 0\n0 0 0\n1 1 0\n");
  EXPECT_TRUE(Has(error_of([&] { read_points(path("long.node")); }), "header says 1 points but the file has 2"));
}

TEST_F(IoTest, NodeBadIndices) {
  write_file("first.node", "2 2 0 0\n2 0 0\n3 1 0\n");
  EXPECT_TRUE(Has(error_of([&] { read_points(path("first.node")); }),
                  "first.node:2: the first point index must be 0 or 1, got 2"));
  write_file("gap.node", "# c\n3 2 0 0\n1 0 0\n2 1 0\n4 0 1\n");
  EXPECT_TRUE(Has(error_of([&] { read_points(path("gap.node")); }), "gap.node:5: expected point index 3, got 4"));
  write_file("notint.node", "1 2 0 0\n0.5 0 0\n");
  EXPECT_TRUE(Has(error_of([&] { read_points(path("notint.node")); }), "notint.node:2: "));
}

TEST_F(IoTest, NodeBadHeaderAndFieldCounts) {
  write_file("dim.node", "1 3 0 0\n0 0 0 0\n");
  EXPECT_TRUE(Has(error_of([&] { read_points(path("dim.node")); }), "dim.node:1: dimension is 3"));
  write_file("hdr.node", "1\n0 0 0\n");
  EXPECT_TRUE(Has(error_of([&] { read_points(path("hdr.node")); }), "hdr.node:1: expected a header"));
  write_file("none.node", "# only a comment\n\n");
  EXPECT_TRUE(Has(error_of([&] { read_points(path("none.node")); }), "none.node: "));
  write_file("markers.node", "1 2 0 2\n0 0 0 1\n");
  EXPECT_TRUE(Has(error_of([&] { read_points(path("markers.node")); }), "markers.node:1: "));
  // Header 1 attribute + marker: 5 fields a line, no more and no fewer.
  write_file("few.node", "2 2 1 1\n0 0 0 1.5 0\n1 1 1 2.5\n");
  EXPECT_TRUE(Has(error_of([&] { read_points(path("few.node")); }),
                  "few.node:3: expected 5 fields \"index x y attributes marker\", got \"1 1 1 2.5\""));
  write_file("many.node", "1 2 0 0\n0 0 0 9\n");
  EXPECT_TRUE(Has(error_of([&] { read_points(path("many.node")); }), "many.node:2: expected 3 fields"));
  write_file("word.node", "1 2 0 0\n0 1 abc\n");
  EXPECT_EQ(error_of([&] { read_points(path("word.node")); }),
            path("word.node") + ":2: coordinate \"abc\" is not a number");
  write_file("comma.node", "1 2 0 0\n0 1,2\n");
  EXPECT_TRUE(Has(error_of([&] { read_points(path("comma.node")); }), "comma.node:2: "));
}

TEST_F(IoTest, ReadTrianglesEle) {
  write_file("t.ele", "# triangles\n2 3 0\n1 1 2 3\n2 3 4 1  # c\n");
  EXPECT_EQ(read_triangles(path("t.ele"), 1), (std::vector<VertexId>{0, 1, 2, 2, 3, 0}));
  EXPECT_EQ(read_triangles(path("t.ele"), 0), (std::vector<VertexId>{1, 2, 3, 3, 4, 1}));
  write_file("attr.ele", "1 3 1\n0 0 1 2 0.5\n");
  EXPECT_EQ(read_triangles(path("attr.ele"), 0), (std::vector<VertexId>{0, 1, 2}));
  write_file("two.ele", "1 3\n0 5 6 7\n");
  EXPECT_EQ(read_triangles(path("two.ele"), 0), (std::vector<VertexId>{5, 6, 7}));
}

TEST_F(IoTest, ReadTrianglesEleErrors) {
  write_file("neg.ele", "2 3 0\n1 1 2 3\n2 3 0 1\n");
  EXPECT_TRUE(Has(error_of([&] { read_triangles(path("neg.ele"), 1); }),
                  "neg.ele:3: vertex index 0 is below the first index 1"));
  write_file("count.ele", "3 3 0\n0 0 1 2\n");
  EXPECT_TRUE(
      Has(error_of([&] { read_triangles(path("count.ele"), 0); }), "header says 3 triangles but the file has 1"));
  write_file("gap.ele", "2 3 0\n0 0 1 2\n2 0 1 2\n");
  EXPECT_TRUE(Has(error_of([&] { read_triangles(path("gap.ele"), 0); }), "gap.ele:3: "));
  write_file("six.ele", "1 6 0\n0 0 1 2 3 4 5\n");
  EXPECT_TRUE(Has(error_of([&] { read_triangles(path("six.ele"), 0); }), "six.ele:1: "));
  write_file("field.ele", "1 3 0\n0 0 1\n");
  EXPECT_TRUE(Has(error_of([&] { read_triangles(path("field.ele"), 0); }), "field.ele:2: expected 4 fields"));
  write_file("big.ele", "1 3 0\n0 0 1 99999999999\n");
  EXPECT_TRUE(Has(error_of([&] { read_triangles(path("big.ele"), 0); }), "big.ele:2: "));
}

TEST_F(IoTest, ReadTrianglesBinAndText) {
  const std::vector<VertexId> tris = {0, 1, 2, 4000000000u, 7, 3};
  {
    std::ofstream f(path("t.bin"), std::ios::binary);
    for (VertexId v : tris) {
      const unsigned char b[4] = {static_cast<unsigned char>(v), static_cast<unsigned char>(v >> 8),
                                  static_cast<unsigned char>(v >> 16), static_cast<unsigned char>(v >> 24)};
      f.write(reinterpret_cast<const char*>(b), 4);
    }
  }
  EXPECT_EQ(read_triangles(path("t.bin"), 0), tris);
  EXPECT_EQ(read_triangles(path("t.bin"), 1), tris);  // .bin is always 0-based
  write_file("odd.bin", std::string(13, '\0'));
  EXPECT_TRUE(Has(error_of([&] { read_triangles(path("odd.bin"), 0); }), "multiple of 12"));

  write_file("t.txt", "# a b c\n1 2 3\n\n4 5 6 # c\n");
  EXPECT_EQ(read_triangles(path("t.txt"), 1), (std::vector<VertexId>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(read_triangles(path("t.txt"), 0), (std::vector<VertexId>{1, 2, 3, 4, 5, 6}));
  write_file("bad.txt", "0 1 2\n0 1\n");
  EXPECT_TRUE(Has(error_of([&] { read_triangles(path("bad.txt"), 0); }),
                  "bad.txt:2: expected three vertex indices \"a b c\", got \"0 1\""));
  write_file("frac.txt", "0 1 2.5\n");
  EXPECT_TRUE(Has(error_of([&] { read_triangles(path("frac.txt"), 0); }), "frac.txt:1: "));
  write_file("neg.txt", "0 1 2\n");
  EXPECT_TRUE(Has(error_of([&] { read_triangles(path("neg.txt"), 1); }),
                  "neg.txt:1: vertex index 0 is below the first index 1"));
  write_file("minus.txt", "0 -1 2\n");
  EXPECT_TRUE(Has(error_of([&] { read_triangles(path("minus.txt"), 0); }), "minus.txt:1: "));
}

// Integers at the ends of the 64-bit range, in every field a reader parses as an integer. Each
// is refused with a message that states the value as written, and nothing is computed from it
// before its range is checked (UBSan reports any overflow in the sanitizer suite).

// fuzz_readers: the text triangle "-9223372036854775808,8,6" read 1-based. The reader
// subtracted the first index before comparing, so the index wrapped (undefined behaviour) and
// came out as "too large".
TEST_F(IoTest, VertexIndexAtInt64MinIsBelowTheFirstIndex) {
  write_file("min.txt", "-9223372036854775808,8,6\n");
  EXPECT_EQ(error_of([&] { read_triangles(path("min.txt"), 1); }),
            path("min.txt") + ":1: vertex index -9223372036854775808 is below the first index 1");
  EXPECT_EQ(error_of([&] { read_triangles(path("min.txt"), 0); }),
            path("min.txt") + ":1: vertex index -9223372036854775808 is below the first index 0");
  write_file("min.ele", "1 3 0\n1 2 -9223372036854775808 3\n");
  EXPECT_EQ(error_of([&] { read_triangles(path("min.ele"), 1); }),
            path("min.ele") + ":2: vertex index -9223372036854775808 is below the first index 1");
}

TEST_F(IoTest, VertexIndexAtInt64MaxIsTooLarge) {
  write_file("max.txt", "1 2 9223372036854775807\n");
  for (int first : {0, 1}) {
    EXPECT_EQ(error_of([&] { read_triangles(path("max.txt"), first); }),
              path("max.txt") + ":1: vertex index 9223372036854775807 is too large (at most " +
                  std::to_string(4294967295LL + first) + ")");
  }
  write_file("over.txt", "0 1 9223372036854775808\n");
  EXPECT_EQ(error_of([&] { read_triangles(path("over.txt"), 0); }),
            path("over.txt") + ":1: vertex index \"9223372036854775808\" is out of range");
}

// The largest vertex index that fits a 32-bit id is read, one more is refused, for both
// numberings; the validator then judges the index against the points.
TEST_F(IoTest, VertexIndexAtTheIdLimit) {
  write_file("top0.txt", "0 1 4294967295\n");
  EXPECT_EQ(read_triangles(path("top0.txt"), 0), (std::vector<VertexId>{0, 1, 4294967295u}));
  write_file("top1.txt", "1 2 4294967296\n");
  EXPECT_EQ(read_triangles(path("top1.txt"), 1), (std::vector<VertexId>{0, 1, 4294967295u}));
  write_file("past0.ele", "1 3\n0 0 1 4294967296\n");
  EXPECT_EQ(error_of([&] { read_triangles(path("past0.ele"), 0); }),
            path("past0.ele") + ":2: vertex index 4294967296 is too large (at most 4294967295)");
  write_file("past1.ele", "1 3\n1 1 2 4294967297\n");
  EXPECT_EQ(error_of([&] { read_triangles(path("past1.ele"), 1); }),
            path("past1.ele") + ":2: vertex index 4294967297 is too large (at most 4294967296)");
}

// Header counts at the limits: a negative count is refused at once, a huge one when the file
// ends (and it never sizes an allocation), one past the range is a range error.
TEST_F(IoTest, HeaderCountsAtInt64Limits) {
  write_file("huge.node", "9223372036854775807 2 0 0\n0 0 0\n");
  EXPECT_EQ(error_of([&] { read_points(path("huge.node")); }),
            path("huge.node") + ": header says 9223372036854775807 points but the file has 1");
  write_file("neg.node", "-9223372036854775808 2\n");
  EXPECT_EQ(error_of([&] { read_points(path("neg.node")); }),
            path("neg.node") + ":1: negative number of points -9223372036854775808");
  write_file("over.node", "9223372036854775808 2\n");
  EXPECT_EQ(error_of([&] { read_points(path("over.node")); }),
            path("over.node") + ":1: number of points \"9223372036854775808\" is out of range");
  write_file("huge.ele", "9223372036854775807 3\n0 0 1 2\n");
  EXPECT_EQ(error_of([&] { read_triangles(path("huge.ele"), 0); }),
            path("huge.ele") + ": header says 9223372036854775807 triangles but the file has 1");
  write_file("neg.ele", "-9223372036854775808 3\n");
  EXPECT_EQ(error_of([&] { read_triangles(path("neg.ele"), 0); }),
            path("neg.ele") + ":1: negative number of triangles -9223372036854775808");
  write_file("dim.node", "1 -9223372036854775808\n");
  EXPECT_EQ(error_of([&] { read_points(path("dim.node")); }),
            path("dim.node") + ":1: dimension is -9223372036854775808, must be 2");
  write_file("nodes.ele", "1 9223372036854775807\n");
  EXPECT_EQ(error_of([&] { read_triangles(path("nodes.ele"), 0); }),
            path("nodes.ele") + ":1: nodes per triangle is 9223372036854775807, must be 3");
}

// Attribute and marker counts size every line's field count: refused before they do.
TEST_F(IoTest, AttributeAndMarkerCountsAtInt64Limits) {
  for (const char* count : {"9223372036854775807", "-9223372036854775808", "1000001"}) {
    write_file("attr.node", std::string("1 2 ") + count + " 0\n0 0 0\n");
    EXPECT_EQ(error_of([&] { read_points(path("attr.node")); }),
              path("attr.node") + ":1: bad number of attributes " + count);
    write_file("attr.ele", std::string("1 3 ") + count + "\n0 0 1 2\n");
    EXPECT_EQ(error_of([&] { read_triangles(path("attr.ele"), 0); }),
              path("attr.ele") + ":1: bad number of attributes " + count);
  }
  for (const char* count : {"9223372036854775807", "-9223372036854775808"}) {
    write_file("markers.node", std::string("1 2 0 ") + count + "\n0 0 0 0\n");
    EXPECT_EQ(error_of([&] { read_points(path("markers.node")); }),
              path("markers.node") + ":1: number of boundary markers must be 0 or 1, got " + count);
  }
  // A marker's value is not limited, but it must be an integer in range.
  write_file("marker.node", "1 2 0 1\n0 0 0 -9223372036854775808\n");
  EXPECT_EQ(read_points(path("marker.node")).points.size(), 1u);
  write_file("bigmarker.node", "1 2 0 1\n0 0 0 9223372036854775808\n");
  EXPECT_EQ(error_of([&] { read_points(path("bigmarker.node")); }),
            path("bigmarker.node") + ":2: boundary marker \"9223372036854775808\" is out of range");
}

// The first index of a .node or .ele file, and each later index against the running count.
TEST_F(IoTest, RecordIndicesAtInt64Limits) {
  write_file("first.node", "1 2\n-9223372036854775808 0 0\n");
  EXPECT_EQ(error_of([&] { read_points(path("first.node")); }),
            path("first.node") + ":2: the first point index must be 0 or 1, got -9223372036854775808");
  write_file("next.node", "2 2\n1 0 0\n9223372036854775807 1 1\n");
  EXPECT_EQ(error_of([&] { read_points(path("next.node")); }),
            path("next.node") + ":3: expected point index 2, got 9223372036854775807 (indices must be consecutive)");
  write_file("first.ele", "1 3\n9223372036854775807 0 1 2\n");
  EXPECT_EQ(error_of([&] { read_triangles(path("first.ele"), 0); }),
            path("first.ele") + ":2: the first triangle index must be 0 or 1, got 9223372036854775807");
  write_file("next.ele", "2 3\n1 0 1 2\n-9223372036854775808 0 1 2\n");
  EXPECT_EQ(error_of([&] { read_triangles(path("next.ele"), 0); }),
            path("next.ele") + ":3: expected triangle index 2, got -9223372036854775808 (indices must be consecutive)");
}

/// The unit square split along 0-2, with a duplicate of point 0 at the end (not a vertex).
struct Square {
  std::vector<Point> points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
  Triangulation t;
  Square() {
    t.triangles = {0, 1, 2, 0, 2, 3};
    // Triangle 0 (0,1,2): across 0 is edge 1-2 (hull), across 1 is edge 2-0 (triangle 1),
    // across 2 is edge 0-1 (hull). Triangle 1 (0,2,3): across 2 is edge 0-2 (triangle 0).
    t.neighbors = {-1, 1, -1, -1, -1, 0};
    t.hull = {0, 1, 2, 3};
    t.duplicates = {{4, 0}};
  }
};

TEST_F(IoTest, WriteEleReadsBack) {
  const Square s;
  write_triangulation(path("z.ele"), s.points, s.t, 0);
  EXPECT_EQ(read_file("z.ele"), "2 3 0\n0 0 1 2\n1 0 2 3\n");
  EXPECT_EQ(read_triangles(path("z.ele"), 0), s.t.triangles);
  write_triangulation(path("o.ele"), s.points, s.t, 1);
  EXPECT_EQ(read_file("o.ele"), "2 3 0\n1 1 2 3\n2 1 3 4\n");
  EXPECT_EQ(read_triangles(path("o.ele"), 1), s.t.triangles);
}

TEST_F(IoTest, WriteBinReadsBack) {
  const Square s;
  write_triangulation(path("t.bin"), s.points, s.t, 1);  // first_index does not apply to .bin
  EXPECT_EQ(fs::file_size(path("t.bin")), 24u);
  EXPECT_EQ(read_triangles(path("t.bin"), 0), s.t.triangles);
  const std::string raw = read_file("t.bin");
  EXPECT_EQ(raw.substr(12, 4), std::string("\0\0\0\0", 4));
  EXPECT_EQ(raw.substr(16, 4), std::string("\x02\0\0\0", 4));
}

TEST_F(IoTest, WriteNeigh) {
  const Square s;
  write_triangulation(path("z.neigh"), s.points, s.t, 0);
  EXPECT_EQ(read_file("z.neigh"), "2 3\n0 -1 1 -1\n1 -1 -1 0\n");
  write_triangulation(path("o.neigh"), s.points, s.t, 1);
  EXPECT_EQ(read_file("o.neigh"), "2 3\n1 -1 2 -1\n2 -1 -1 1\n");
}

TEST_F(IoTest, WriteOffAndObj) {
  Square s;
  s.points[1] = {0.1, -0.0};
  write_triangulation(path("t.off"), s.points, s.t, 1);  // 0-based whatever the input numbering
  EXPECT_EQ(read_file("t.off"), "OFF\n5 2 0\n0 0 0\n0.1 -0 0\n1 1 0\n0 1 0\n0 0 0\n3 0 1 2\n3 0 2 3\n");
  write_triangulation(path("t.obj"), s.points, s.t, 0);  // always 1-based
  EXPECT_EQ(read_file("t.obj"), "v 0 0 0\nv 0.1 -0 0\nv 1 1 0\nv 0 1 0\nv 0 0 0\nf 1 2 3\nf 1 3 4\n");
}

// A square with a square hole, numbered from 1, with markers and comments.
const char* const kHoledSquare =
    "# outer, then inner\n8 2 0 1\n1 0 0 1\n2 10 0 1\n3 10 10 1\n4 0 10 1\n5 4 4 1\n6 6 4 1\n7 6 6 1\n8 4 6 1\n"
    "8 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n5 5 6 2\n6 6 7 2\n7 7 8 2\n8 8 5 2\n1\n1 5 5\n";

TEST_F(IoTest, ReadPoly) {
  write_file("sq.poly", kHoledSquare);
  const Pslg g = read_pslg(path("sq.poly"));
  EXPECT_EQ(g.points.size(), 8u);
  EXPECT_EQ(g.points[6], (Point{6, 6}));
  EXPECT_EQ(g.first_index, 1);
  EXPECT_EQ(g.segments, (std::vector<VertexId>{0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4}));
  EXPECT_EQ(g.holes, (std::vector<Point>{{5, 5}}));
  EXPECT_TRUE(g.regions.empty());
  // Its points as a point file too.
  EXPECT_EQ(read_points(path("sq.poly")).points.size(), 8u);
  // Vertices in the .node beside it, regions after the holes.
  write_file("n.node", "3 2\n0 0 0\n1 1 0\n2 0 1\n");
  write_file("n.poly", "0 2 0 0\n1 0\n0 0 1\n0\n1\n0 0.2 0.2 7 0.5\n");
  const Pslg n = read_pslg(path("n.poly"));
  EXPECT_EQ(n.points.size(), 3u);
  EXPECT_EQ(n.first_index, 0);
  EXPECT_EQ(n.segments, (std::vector<VertexId>{0, 1}));
  ASSERT_EQ(n.regions.size(), 1u);
  EXPECT_EQ(n.regions[0], (std::array<double, 4>{0.2, 0.2, 7, 0.5}));
}

TEST_F(IoTest, BadPolyFiles) {
  const std::pair<const char*, const char*> cases[] = {
      {"3 2\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 0 3\n0\n", "segment end 3 is not a vertex"},
      {"3 2\n0 0 0\n1 1 0\n2 0 1\n2 0\n0 0 1\n", "the file ends before its 2 segments"},
      {"3 2\n0 0 0\n1 1 0\n2 0 1\n1 0\n1 0 1\n0\n", "expected segment index 0"},
      {"3 2\n0 0 0\n1 1 0\n2 0 1\n0 0\n", "no hole count"},
      {"3 2\n0 0 0\n1 1 0\n2 0 1\n0 0\n1\n0 x 1\n", "is not a number"},
      {"3 3\n0 0 0\n1 1 0\n2 0 1\n0 0\n0\n", "dimension must be 2"},
      {"3 2\n0 0 0\n1 1 0\n2 0 1\n0 0\n0\n0\nextra\n", "unexpected line"},
      {"4 2\n0 0 0\n1 1 0\n2 0 1\n", "the file ends before its 4 vertices"},
      // A field too many, in a segment, a hole and the header.
      {"3 2\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 0 1 0 7\n0\n", "expected \"index a b [marker]\""},
      {"3 2\n0 0 0\n1 1 0\n2 0 1\n0 0\n1\n0 0.5 0.5 9\n", "expected \"index x y\""},
      {"3 2 0 0 5\n0 0 0\n1 1 0\n2 0 1\n0 0\n0\n", "expected a header"},
  };
  for (const auto& [text, wanted] : cases) {
    SCOPED_TRACE(text);
    write_file("bad.poly", text);
    EXPECT_TRUE(Has(error_of([&] { read_pslg(path("bad.poly")); }), wanted));
  }
  EXPECT_THROW(read_pslg(path("sq.node")), IoError);  // not a .poly
}

// Text large enough to be cut into pieces and parsed in ranges on threads reads as on one
// thread: the same numbers, and, wherever the errors lie, the same first one (by line).
TEST_F(IoTest, TextOnThreadsReadsAsOnOne) {
  constexpr int kPoints = 120000;
  std::string node = "\xEF\xBB\xBF# points\n" + std::to_string(kPoints) + " 2 0 1\n", ele, poly, txt;
  for (int i = 0; i < kPoints; ++i) {
    const std::string x = std::to_string(std::sin(i) * 1e3), y = std::to_string(i * 0.25);
    node += std::to_string(i + 1) + " " + x + " " + y + " 1" + (i % 1000 == 0 ? "  # a comment\r\n\n" : "\n");
    txt += x + "," + y + "\n";
  }
  poly = node + std::to_string(kPoints) + " 0\n";
  ele = std::to_string(kPoints - 2) + " 3\n";
  for (int i = 1; i <= kPoints; ++i)
    poly += std::to_string(i) + " " + std::to_string(i) + " " + std::to_string(i % kPoints + 1) + "\n";
  for (int i = 1; i <= kPoints - 2; ++i)
    ele += std::to_string(i) + " 1 " + std::to_string(i + 1) + " " + std::to_string(i + 2) + "\n";
  poly += "0\n";
  auto points_of = [&](const std::string& name, unsigned threads) { return copy_of(read_points(path(name), threads)); };
  bool spoiled = false;
  auto same = [&](const std::string& n, const std::string& p, const std::string& e, const std::string& t) {
    write_file("a.node", n), write_file("a.poly", p), write_file("a.ele", e), write_file("a.txt", t);
    for (const unsigned threads : {2u, 3u, 8u}) {
      SCOPED_TRACE(threads);
      auto error_or = [](auto&& f) {
        try {
          f();
        } catch (const IoError& x) {
          return std::string(x.what());
        }
        return std::string();
      };
      for (const char* name : {"a.node", "a.poly", "a.txt"}) {
        const std::string one = error_or([&] { points_of(name, 1); });
        EXPECT_EQ(one.empty(), !spoiled) << name;
        EXPECT_EQ(error_or([&] { points_of(name, threads); }), one) << name;
        if (one.empty()) {
          EXPECT_EQ(points_of(name, threads), points_of(name, 1)) << name;
        }
      }
      const std::string one = error_or([&] { read_triangles(path("a.ele"), 1, 1); });
      EXPECT_EQ(one.empty(), !spoiled);
      EXPECT_EQ(error_or([&] { read_triangles(path("a.ele"), 1, threads); }), one);
      if (one.empty()) {
        EXPECT_EQ(read_triangles(path("a.ele"), 1, threads), read_triangles(path("a.ele"), 1, 1));
        EXPECT_EQ(read_pslg(path("a.poly"), threads).segments, read_pslg(path("a.poly"), 1).segments);
      }
    }
  };
  same(node, poly, ele, txt);
  EXPECT_EQ(read_points(path("a.node"), 3).points.size(), std::size_t{kPoints});
  // One error, or two, anywhere: near the start, in the middle, near the end.
  auto spoil = [](std::string text, double at, const std::string& with) {
    std::size_t p = text.find('\n', static_cast<std::size_t>(text.size() * at)) + 1;
    return text.insert(p, with);
  };
  spoiled = true;
  for (const double at : {0.001, 0.3, 0.5, 0.97}) {
    SCOPED_TRACE(at);
    same(spoil(node, at, "7 1 x 1\n"), spoil(poly, at, "7 1 2\n"), spoil(ele, at, "7 1 2 3\n"),
         spoil(txt, at, "1 x\n"));
    same(spoil(spoil(node, at, "7 1 2\n"), 0.99, "1 nan 2 1\n"), spoil(spoil(poly, 0.99, "1 1\n"), at, "5 5 5 5 5\n"),
         spoil(spoil(ele, at, "1 2 3\n"), 0.98, "1 2 3 4\n"), spoil(spoil(txt, 0.99, "1e999 1\n"), at, "1 2 3\n"));
  }
}

TEST_F(IoTest, WriteEdges) {
  write_edges(path("e.edge"), std::vector<VertexId>{0, 1, 2, 5}, 1);
  EXPECT_EQ(read_file("e.edge"), "2 1\n1 1 2 1\n2 3 6 1\n");
}

TEST_F(IoTest, WritePly) {
  Square s;
  s.points[1] = {0.1, -0.0};
  write_triangulation(path("t.ply"), s.points, s.t, 1);  // 0-based whatever the input numbering
  const std::string ply = read_file("t.ply");
  const std::string header =
      "ply\nformat binary_little_endian 1.0\ncomment ridt: the Delaunay triangulation\nelement vertex 5\n"
      "property double x\nproperty double y\nproperty double z\nelement face 2\n"
      "property list uchar uint vertex_indices\nend_header\n";
  ASSERT_EQ(ply.substr(0, header.size()), header);
  ASSERT_EQ(ply.size(), header.size() + 5 * 24 + 2 * 13);
  const char* v = ply.data() + header.size();
  for (std::size_t i = 0; i < 5; ++i) {
    double x, y, z;
    std::memcpy(&x, v + 24 * i, 8), std::memcpy(&y, v + 24 * i + 8, 8), std::memcpy(&z, v + 24 * i + 16, 8);
    EXPECT_EQ(x, s.points[i].x) << i;
    EXPECT_EQ(std::signbit(y), std::signbit(s.points[i].y)) << i;
    EXPECT_EQ(y, s.points[i].y) << i;
    EXPECT_EQ(z, 0.0);
  }
  const char* f = v + 5 * 24;
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(f[13 * k], 3);
    for (int i = 0; i < 3; ++i) {
      std::uint32_t id;
      std::memcpy(&id, f + 13 * k + 1 + 4 * i, 4);
      EXPECT_EQ(id, s.t.triangles[3 * k + i]);
    }
  }
}

TEST_F(IoTest, WriteSvg) {
  const Square s;
  write_triangulation(path("t.svg"), s.points, s.t, 0);
  const std::string svg = read_file("t.svg");
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_TRUE(Has(svg, "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\""));
  EXPECT_TRUE(Has(svg, "</svg>\n"));
  EXPECT_TRUE(Has(svg, "<path "));
  EXPECT_TRUE(Has(svg, "<polygon "));
  std::size_t circles = 0;
  for (std::size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++circles;
  EXPECT_EQ(circles, s.points.size());
  // Each of the 5 edges is drawn once: 5 moves in the path.
  const std::size_t d = svg.find(" d=\"");
  ASSERT_NE(d, std::string::npos);
  const std::string path_data = svg.substr(d, svg.find('"', d + 4) - d);
  EXPECT_EQ(std::count(path_data.begin(), path_data.end(), 'M'), 5);
  // y is flipped: point (0, 1) is at the top (y = 0), point (0, 0) at the bottom (y = 1000).
  EXPECT_TRUE(Has(svg, "<circle cx=\"0\" cy=\"0\""));
  EXPECT_TRUE(Has(svg, "<circle cx=\"0\" cy=\"1000\""));
}

TEST_F(IoTest, WriteSvgDegenerateInputs) {
  Triangulation empty;
  write_triangulation(path("none.svg"), std::vector<Point>{}, empty, 0);
  EXPECT_TRUE(Has(read_file("none.svg"), "</svg>"));
  const double big = std::numeric_limits<double>::max();
  write_triangulation(path("wide.svg"), std::vector<Point>{{-big, -big}, {big, big}, {5, 5}}, empty, 0);
  EXPECT_EQ(read_file("wide.svg").find("inf"), std::string::npos);
  EXPECT_EQ(read_file("wide.svg").find("nan"), std::string::npos);
}

// Points 1e-310 apart: the scale 1000 / 1e-310 overflows, and the viewBox was "inf"; the box
// is brought near 1 by powers of two first, so the drawing is the unit square's.
TEST_F(IoTest, SvgOfATinyBoxIsTheUnitSquaresDrawing) {
  Square s;
  write_triangulation(path("one.svg"), s.points, s.t, 0);
  for (Point& p : s.points) p.x *= 1e-310, p.y *= 1e-310;
  write_triangulation(path("tiny.svg"), s.points, s.t, 0);
  const std::string tiny = read_file("tiny.svg");
  EXPECT_EQ(tiny.find("inf"), std::string::npos);
  EXPECT_EQ(tiny.find("nan"), std::string::npos);
  EXPECT_TRUE(Has(tiny, "viewBox=\"-20 -20 1040 1040\""));
  EXPECT_TRUE(Has(tiny, "<circle cx=\"0\" cy=\"1000\""));
}

// A NaN or an infinity is never written as a coordinate: the writer fails, naming the file, and
// leaves nothing; values (interpolate's fill) are written as "nan".
TEST_F(IoTest, NonFiniteCoordinatesAreNeverWritten) {
  Square s;
  s.points[2].x = std::numeric_limits<double>::quiet_NaN();
  for (const char* name : {"p.txt", "p.node", "p.bin"}) {
    SCOPED_TRACE(name);
    EXPECT_TRUE(Has(error_of([&] { write_points(path(name), s.points, 0, 2); }), "cannot write " + path(name)));
  }
  s.points[2].x = std::numeric_limits<double>::infinity();
  for (const char* name : {"t.off", "t.obj", "t.ply", "t.svg"}) {
    SCOPED_TRACE(name);
    EXPECT_TRUE(Has(error_of([&] { write_triangulation(path(name), s.points, s.t, 0); }), "not finite"));
  }
  EXPECT_TRUE(listing().empty());
  const std::vector<double> v = {1, std::numeric_limits<double>::quiet_NaN()};
  write_values(path("v.csv"), std::vector<Point>{{0, 0}, {1, 1}}, v, 1);
  EXPECT_EQ(read_file("v.csv"), "x,y,v0\n0,0,1\n1,1,nan\n");
}

TEST_F(IoTest, SvgRefusesTooManyTrianglesAndCreatesNothing) {
  Triangulation t;
  t.triangles.assign(3 * (kSvgMaxTriangles + 1), 0);
  const std::vector<Point> pts = {{0, 0}};
  const std::string msg = error_of([&] { write_triangulation(path("big.svg"), pts, t, 0); });
  EXPECT_EQ(msg,
            path("big.svg") + ": " + std::to_string(kSvgMaxTriangles + 1) +
                " triangles are too many to draw usefully (at most 200000); write .off or .ele "
                "instead");
  EXPECT_FALSE(fs::exists(path("big.svg")));
  EXPECT_TRUE(listing().empty());
  // An existing target is left untouched.
  write_file("big.svg", "keep");
  EXPECT_THROW(write_triangulation(path("big.svg"), pts, t, 0), IoError);
  EXPECT_EQ(read_file("big.svg"), "keep");
  EXPECT_EQ(listing(), std::vector<std::string>{"big.svg"});
}

TEST_F(IoTest, TriangulationExtensions) {
  // Only the formats that write the neighbours ask the triangulation for them; extensions in
  // any case.
  for (const std::string ok :
       {"a.ele", "a.neigh", "a.off", "a.ply", "a.obj", "a.svg", "a.bin", "dir.x/b.c.ele", "out.ELE", "a.Svg"})
    EXPECT_EQ(triangulation_needs_neighbors(ok), ok == "a.neigh" || ok == "a.svg" || ok == "a.Svg") << ok;
  EXPECT_EQ(error_of([] { triangulation_needs_neighbors("out.xyz"); }),
            "unknown output extension '.xyz' (use .ele, .neigh, .bin, .ply, .obj, .off or .svg)");
  for (const char* bad : {"out", "out.txt", "out.node", "ele", "dir.ele/out"}) {
    SCOPED_TRACE(bad);
    EXPECT_TRUE(Has(error_of([&] { triangulation_needs_neighbors(bad); }), "unknown output extension"));
  }
  const Square s;
  EXPECT_THROW(write_triangulation(path("t.xyz"), s.points, s.t, 0), IoError);
  EXPECT_TRUE(listing().empty());
}

TEST_F(IoTest, MissingDirectoryCreatesNothing) {
  const Square s;
  const std::string missing = path("no/such/dir");
  for (const char* name : {"t.ele", "t.neigh", "t.off", "t.ply", "t.obj", "t.svg", "t.bin"}) {
    SCOPED_TRACE(name);
    const std::string target = missing + "/" + name;
    const std::string msg = error_of([&] { write_triangulation(target, s.points, s.t, 0); });
    EXPECT_TRUE(Has(msg, "cannot write " + target + ": "));
    EXPECT_FALSE(fs::exists(target));
  }
  for (const char* name : {"p.txt", "p.node", "p.bin"}) {
    SCOPED_TRACE(name);
    const std::string target = missing + "/" + name;
    EXPECT_TRUE(Has(error_of([&] { write_points(target, s.points); }), "cannot write " + target));
  }
  EXPECT_TRUE(listing().empty());
}

TEST_F(IoTest, WriteReplacesTargetAndLeavesNoTemporary) {
  const Square s;
  write_file("t.ele", "old content that is longer than the new one ............................\n");
  write_triangulation(path("t.ele"), s.points, s.t, 0);
  EXPECT_EQ(read_file("t.ele"), "2 3 0\n0 0 1 2\n1 0 2 3\n");
  write_points(path("p.txt"), s.points);
  write_points(path("p.txt"), std::vector<Point>{{1, 2}});
  EXPECT_EQ(read_file("p.txt"), "1 2\n");
  EXPECT_EQ(listing(), (std::vector<std::string>{"p.txt", "t.ele"}));
}

TEST_F(IoTest, BadTriangulationsAreRefused) {
  Square s;
  Triangulation no_neighbors = s.t;
  no_neighbors.neighbors.clear();
  EXPECT_THROW(write_triangulation(path("t.neigh"), s.points, no_neighbors, 0), IoError);
  Triangulation out_of_range = s.t;
  out_of_range.triangles[4] = 9;
  for (const char* name : {"t.off", "t.ply", "t.obj", "t.svg"})
    EXPECT_THROW(write_triangulation(path(name), s.points, out_of_range, 0), IoError) << name;
  EXPECT_TRUE(listing().empty());
}

TEST_F(IoTest, LargeRoundTrip) {
  // A quarter of a million points and half a million triangles through every format.
  std::vector<Point> pts;
  std::uint64_t state = 12345;
  const auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * 0x1p-53 * 2000 - 1000;
  };
  for (int i = 0; i < 250000; ++i) pts.push_back({next(), next()});
  for (const char* name : {"big.txt", "big.node", "big.bin"}) {
    write_points(path(name), pts);
    EXPECT_EQ(copy_of(read_points(path(name))), pts) << name;
  }
  Triangulation t;
  for (VertexId k = 0; k < 500000; ++k) {
    t.triangles.insert(t.triangles.end(), {k % 250000, (k * 7 + 1) % 250000, (k * 13 + 2) % 250000});
  }
  for (int first : {0, 1}) {
    write_triangulation(path("big.ele"), pts, t, first);
    EXPECT_EQ(read_triangles(path("big.ele"), first), t.triangles);
  }
  write_triangulation(path("big.bin"), pts, t, 0);
  EXPECT_EQ(read_triangles(path("big.bin"), 0), t.triangles);
}

}  // namespace
}  // namespace ridt::io
