// Triangulates the corners of a square and its centre through the installed package.
#include <ridt/check.hpp>
#include <ridt/ridt.hpp>

#include <cstdio>
#include <vector>

int main() {
  const std::vector<ridt::Point> pts = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  const ridt::Triangulation t = ridt::triangulate(pts);
  const ridt::CheckResult r = ridt::check(pts, t.triangles);
  std::printf("consumer: %zu triangles, %s\n", t.size(), r.message.c_str());
  return r.valid && t.size() == 4 ? 0 : 1;
}
