// Files mapped into memory that shrink while they are read (tools/support/mapped.cpp): an
// error that names the file, never SIGBUS, and nothing written from what was read.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io.hpp"
#include "io_common.hpp"
#include "tools/scratch_dir.hpp"

namespace ridt::io {
namespace {

namespace fs = std::filesystem;

TEST(MappedFiles, ATextFileTruncatedWhileReadIsAnError) {
  const fs::path dir = test::fresh_test_dir("ridt_mapped");
  const std::string node = (dir / "big.node").string();
  {
    std::ofstream f(node);
    f << "200000 2 0 0\n";
    for (int i = 0; i < 200000; ++i) f << i << ' ' << i * 0.5 << ' ' << i * 0.25 << '\n';
  }
  const detail::FileText text(node);  // mapped: a regular file
  ASSERT_EQ(::truncate(node.c_str(), 4096), 0);
  try {
    text.parse([&](std::string_view t) { return parse_points(t, node, 1); });
    ADD_FAILURE() << "a file truncated under its mapping was read";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("shrank while it was read"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("big.node"), std::string::npos) << e.what();
  }
  detail::forget_shrunk_mappings();
  fs::remove_all(dir);
}

TEST(MappedFiles, NothingIsWrittenFromABinFileThatShrank) {
  const fs::path dir = test::fresh_test_dir("ridt_mapped");
  const std::string bin = (dir / "points.bin").string(), out = (dir / "out.bin").string();
  std::vector<Point> points(100000);
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = {double(i), double(i % 7)};
  write_points(bin, points, 0, 1);
  const PointFile p = read_points(bin, 1);  // mapped, used where it lies
  ASSERT_EQ(::truncate(bin.c_str(), 0), 0);
  double sum = 0;
  for (const Point& q : p.points) sum += q.x;  // zeros past the new end, where SIGBUS was
  EXPECT_EQ(sum, 0);
  EXPECT_TRUE(detail::any_mapping_shrank());
  EXPECT_THROW(write_points(out, points, 0, 1), IoError);
  EXPECT_FALSE(fs::exists(out));
  detail::forget_shrunk_mappings();
  write_points(out, points, 0, 1);  // a fresh run writes again
  EXPECT_TRUE(fs::exists(out));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ridt::io
