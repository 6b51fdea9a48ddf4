// Shared test helpers: triangulation with the whole result checked, and the fixtures' format.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "audit.hpp"
#include "ridt/check.hpp"
#include "ridt/generate.hpp"
#include "ridt/ridt.hpp"

namespace ridt::test {

/// Triangulates and asserts that the whole result is sound (audit.hpp: the exact validator,
/// neighbours, hull, duplicates).
inline Triangulation triangulate_checked(const std::vector<Point>& pts, Options o = {}) {
  Triangulation t = triangulate(pts, o);
  EXPECT_EQ(audit(pts, t), "");
  return t;
}

/// A JSON array of [x, y] pairs, as in the delaunator fixtures.
/// delaunator's robustness fixtures (tests/fixtures/delaunator, RIDT_FIXTURES).
inline constexpr const char* kDelaunatorFixtures[] = {"ukraine",     "robustness1", "robustness2", "robustness3",
                                                      "robustness4", "issue13",     "issue43",     "issue44"};

/// The path of fixture `name`.
inline std::string fixture_path(const std::string& name) { return std::string(RIDT_FIXTURES) + "/" + name + ".json"; }

/// The [x, y] pairs of a JSON file; a missing or unreadable file throws, so the test fails.
inline std::vector<Point> read_json_points(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("cannot read the test input " + path);
  std::stringstream ss;
  ss << f.rdbuf();
  std::string s = ss.str();
  for (char& c : s)
    if (c == '[' || c == ']' || c == ',') c = ' ';
  std::istringstream in(s);
  std::vector<Point> pts;
  double x, y;
  while (in >> x >> y) pts.push_back({x, y});
  return pts;
}

/// The paper's four distributions as a test parameter, and each instance named after its own.
inline auto every_distribution() {
  return ::testing::Values(Distribution::Uniform, Distribution::Normal, Distribution::Grid, Distribution::Clusters);
}
inline std::string distribution_name(const ::testing::TestParamInfo<Distribution>& info) {
  return std::string(to_string(info.param));
}

}  // namespace ridt::test
