// Shared test helpers: canonical triangle sets and the exact validator.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ridt/check.hpp"
#include "ridt/ridt.hpp"

namespace ridt::test {

using TriangleSet = std::vector<std::array<VertexId, 3>>;

/// Triangles rotated to start at their smallest index, sorted.
inline TriangleSet canonical(const std::vector<VertexId>& tris) {
  TriangleSet out;
  for (std::size_t i = 0; i + 2 < tris.size(); i += 3) {
    std::array<VertexId, 3> t{tris[i], tris[i + 1], tris[i + 2]};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Triangulates and asserts the exact validator accepts the result.
inline Triangulation triangulate_checked(const std::vector<Point>& pts, Options o = {}) {
  Triangulation t = triangulate(pts, o);
  const CheckResult r = check(pts, t.triangles);
  EXPECT_TRUE(r.valid) << r.message;
  return t;
}

/// A JSON array of [x, y] pairs, as in the delaunator fixtures.
inline std::vector<Point> read_json_points(const std::string& path) {
  std::ifstream f(path);
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

}  // namespace ridt::test
