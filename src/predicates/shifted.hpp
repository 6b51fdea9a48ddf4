// Exact predicates on copies of points moved by whole periods: p + (dx * width, dy * height),
// dx and dy integers, as the periodic triangulation (periodic/periodic.cpp) and its validator
// (check/check_periodic.cpp) place their vertices. A moved coordinate is rarely a double, so
// the tests cannot round it: they decide exactly what orient2d and incircle_sos would decide on
// the true moved points, perturbation included.
//
// Both determinants are unchanged by moving all their points by one amount, and so is the
// lexicographic order that keys the perturbation; so where every point has the same shift the
// plain predicates on the unmoved points answer. Otherwise a filter evaluates the rounded moved
// points with a bound that covers their rounding, and exact integers (predicates/bigint.hpp)
// decide what it cannot.
#pragma once

#include <cstdint>

#include "predicates/predicates.hpp"
#include "ridt/ridt.hpp"

namespace ridt::detail {

/// A point moved by whole periods: p + (dx * width, dy * height).
struct Shifted {
  Point p;
  std::int32_t dx = 0, dy = 0;
};

/// The periods by which Shifted points move.
struct Periods {
  double width = 1, height = 1;
};

inline bool same_shift(const Shifted& a, const Shifted& b) { return a.dx == b.dx && a.dy == b.dy; }

/// The moved point rounded to doubles (each coordinate within a few units in its last place).
inline Point rounded(const Shifted& s, const Periods& l) { return {s.p.x + s.dx * l.width, s.p.y + s.dy * l.height}; }

int orient_shifted_mixed(const Shifted& a, const Shifted& b, const Shifted& c, const Periods& l);
int incircle_shifted_mixed(const Shifted& a, const Shifted& b, const Shifted& c, const Shifted& d, const Periods& l);
bool lex_less_shifted_mixed(const Shifted& a, const Shifted& b, const Periods& l);

/// orient2d of the moved points, exactly: +1 counter-clockwise, -1 clockwise, 0 collinear.
inline int orient_shifted(const Shifted& a, const Shifted& b, const Shifted& c, const Periods& l) {
  if (same_shift(a, b) && same_shift(a, c)) return orient2d(a.p, b.p, c.p);
  return orient_shifted_mixed(a, b, c, l);
}

/// incircle_sos of the moved points, exactly and with the same perturbation: +1 when d lies
/// inside the circle of the counter-clockwise triangle (a, b, c), -1 outside, never 0 for
/// four distinct points.
inline int incircle_shifted(const Shifted& a, const Shifted& b, const Shifted& c, const Shifted& d, const Periods& l) {
  if (same_shift(a, b) && same_shift(a, c) && same_shift(a, d)) return incircle_sos(a.p, b.p, c.p, d.p);
  return incircle_shifted_mixed(a, b, c, d, l);
}

/// lex_less (x, then y) of the moved points, exactly.
inline bool lex_less_shifted(const Shifted& a, const Shifted& b, const Periods& l) {
  if (same_shift(a, b)) return lex_less(a.p, b.p);
  return lex_less_shifted_mixed(a, b, l);
}

}  // namespace ridt::detail
