// The paper's four test distributions, bit-identical on every machine for a given seed: only
// +, -, *, / and sqrt (all correctly rounded by IEEE 754) and a seeded counter-based generator.
//   uniform:  x, y uniform in [0, 1)
//   normal:   x, y independent standard normal (mean 0, deviation 1), Marsaglia's polar method
//   grid:     the first n points, row by row, of the integer grid 0..s-1 x 0..s-1, s = ceil(sqrt n)
//   clusters: 10 centres uniform in [0, 1)^2; each point picks a centre uniformly and adds a
//             normal offset of deviation 0.01 in x and y
#pragma once

#include <cstdint>
#include <vector>

#include "ridt/ridt.hpp"

namespace ridt {

enum class Distribution { Uniform, Normal, Grid, Clusters };

template <>
struct OptionNames<Distribution> {
  static constexpr std::string_view option = "distribution";
  static constexpr Named<Distribution> values[] = {
      {"uniform", Distribution::Uniform, "x, y uniform in [0, 1)"},
      {"normal", Distribution::Normal, "x, y standard normal"},
      {"grid", Distribution::Grid, "the integer grid, row by row"},
      {"clusters", Distribution::Clusters, "10 normal clusters of deviation 0.01"},
  };
};

/// n points of distribution d from `seed`.
std::vector<Point> generate(Distribution d, std::uint32_t n, std::uint64_t seed);

}  // namespace ridt
