// Shared test helpers: triangulation with the whole result checked, and the fixtures' format.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <numeric>
#include <random>
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

/// The same triangles in another order, each stored from another corner, as another run on
/// threads may give them.
inline Triangulation shuffled(const Triangulation& t, unsigned seed) {
  const std::size_t n = t.size();
  std::vector<std::uint32_t> place(n);
  std::iota(place.begin(), place.end(), 0u);
  std::mt19937_64 rng(seed);
  std::shuffle(place.begin(), place.end(), rng);
  Triangulation s = t;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t to = place[k], turn = rng() % 3;
    for (std::size_t j = 0; j < 3; ++j) {
      const std::size_t from = 3 * k + (j + turn) % 3;
      s.triangles[3 * to + j] = t.triangles[from];
      s.neighbors[3 * to + j] = t.neighbors[from] < 0 ? -1 : static_cast<std::int32_t>(place[t.neighbors[from]]);
    }
  }
  return s;
}

}  // namespace ridt::test
