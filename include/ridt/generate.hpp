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

namespace ridt {

/// A planar straight-line graph: points, segments between them (pairs of indices, flat) and
/// the seeds of holes, as Triangle's .poly holds them.
struct Pslg {
  std::vector<Point> points;
  std::vector<VertexId> segments;
  std::vector<Point> holes;
};

/// A coastline-like test polygon of n vertices with `lakes` holes, bit-identical on every
/// machine for a seed: an island whose radius from the origin is a periodic fractal (midpoint
/// displacement, roughness 0.6 an octave) between 0.7 and 1.3, and, where lakes > 0, half of
/// the vertices in lakes of the same making, each star-shaped about its centre (its hole's
/// seed) in its own cell of a grid inside radius 0.65. Every polygon is simple, none touches
/// another. Needs n >= 3 + 8 lakes.
Pslg generate_coastline(std::uint32_t n, std::uint32_t lakes, std::uint64_t seed);

}  // namespace ridt
