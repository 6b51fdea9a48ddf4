// Triangle's switch string (ridt/triangle.hpp): each letter, and the number after q, a and S.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

#include "ridt/triangle.hpp"

namespace ridt::triangle {
namespace {

// The number that follows switch `at` (digits and '.', then an exponent: 'e', an optional sign
// and digits; an 'e' not followed so is the next switch, as in "q30e"), or "" where none does;
// `at` moves past it.
std::string number_after(std::string_view s, std::size_t& at) {
  auto digit = [&s](std::size_t i) { return i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); };
  std::size_t end = at + 1;
  while (digit(end) || (end < s.size() && s[end] == '.')) ++end;
  if (end > at + 1 && end < s.size() && s[end] == 'e') {
    const std::size_t sign = end + 1 < s.size() && (s[end + 1] == '-' || s[end + 1] == '+') ? 1 : 0;
    if (digit(end + 1 + sign)) {
      end += 1 + sign;
      while (digit(end)) ++end;
    }
  }
  std::string n(s.substr(at + 1, end - at - 1));
  at = end - 1;
  return n;
}

// A switch's number; one that strtod takes only by rounding it to 0 or to infinity (1e-400,
// 1e400) is refused, as an area bound that is not positive is: 0 would mean no bound at all.
double parse_number(const std::string& text, char sw) {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  const std::string what = std::string("switch '") + sw + "': ";
  if (text.empty() || *end != '\0') throw InputError(what + "bad number '" + text + "'");
  if (errno == ERANGE || !std::isfinite(v)) throw InputError(what + "'" + text + "' is out of range of a double");
  if (sw == 'a' && !(v > 0)) throw InputError(what + "an area bound is positive, got '" + text + "'");
  return v;
}

// The switches that only set a flag.
constexpr std::pair<char, bool Switches::*> kFlags[] = {
    {'p', &Switches::pslg},        {'r', &Switches::refine},     {'A', &Switches::attributes},
    {'c', &Switches::convex_hull}, {'D', &Switches::conforming}, {'Y', &Switches::no_boundary_steiner},
    {'n', &Switches::neighbors},   {'O', &Switches::no_holes},   {'z', &Switches::zero_based},
    {'B', &Switches::no_markers},  {'N', &Switches::no_node},    {'E', &Switches::no_ele},
    {'P', &Switches::no_poly},     {'e', &Switches::all_edges},  {'j', &Switches::jettison},
    {'C', &Switches::check},       {'g', &Switches::off},        {'v', &Switches::voronoi}};

// Taken and ignored: quiet and verbose, and Triangle's choice of algorithm (i, F, l), its exact
// arithmetic off (X) and its iteration numbers in file names (I).
constexpr std::string_view kIgnored = "QViFlXI";

// A switch with a number, or one of two letters (o2, YY); false where c is neither.
bool numbered(std::string_view s, std::size_t& i, Switches& w) {
  const char c = s[i];
  if (c == 'q') {
    const std::string n = number_after(s, i);
    w.min_angle = n.empty() ? 20 : parse_number(n, c);
    w.quality = true;
  } else if (c == 'a') {
    const std::string n = number_after(s, i);
    if (n.empty())
      w.region_areas = true;
    else
      w.max_area = parse_number(n, c);
  } else if (c == 'S') {
    const std::string n = number_after(s, i);
    const double v = n.empty() ? -1 : parse_number(n, c);
    if (!(v >= 0 && v == std::floor(v) && v < 0x1p53))
      throw InputError("switch 'S': give the most points refinement may add, a whole number (got '" + n + "')");
    w.limit_steiner = true;
    w.max_steiner = static_cast<std::size_t>(v);
  } else if (c == 'o') {
    if (i + 1 >= s.size() || s[i + 1] != '2')
      throw InputError("switch 'o' is taken as o2 only (six-node triangles: Triangle's -o2)");
    w.second_order = true;
    ++i;
  } else if (c == 'Y' && i + 1 < s.size() && s[i + 1] == 'Y') {
    w.no_boundary_steiner = w.no_segment_steiner = true;
    ++i;
  } else {
    return false;
  }
  return true;
}

}  // namespace

std::string_view switches_taken() {
  return "p, r, q, a, A, c, D, Y, YY, S, e, n, j, z, o2, O, B, N, E, P, g, v, C, Q, V, i, F, l, X, I";
}

Switches parse_switches(std::string_view s) {
  if (!s.empty() && s.front() == '-') s.remove_prefix(1);
  Switches w;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (numbered(s, i, w) || kIgnored.find(c) != std::string_view::npos) continue;
    const auto flag = std::find_if(std::begin(kFlags), std::end(kFlags), [c](auto f) { return f.first == c; });
    if (flag != std::end(kFlags)) {
      w.*(flag->second) = true;
    } else if (c == 'u') {
      throw InputError(
          "switch 'u' (a test compiled into Triangle) is not taken here: give it to the library "
          "(Quality::unsuitable) or to Python (unsuitable=)");
    } else {
      throw InputError(std::string("unknown or unsupported switch '") + c + "' (ridt takes " +
                       std::string(switches_taken()) + ")");
    }
  }
  if (w.conforming && w.no_segment_steiner)
    throw InputError(
        "a conforming Delaunay mesh splits segments until every edge is Delaunay: it cannot keep them whole "
        "(switches D and YY)");
  return w;
}

Quality Switches::quality_bounds() const {
  Quality q;
  if (limit_steiner && max_steiner == 0) return q;  // S0: nothing refined (crossings, which the graph needs, stay)
  q.min_angle = quality ? min_angle : 0;
  q.max_area = max_area;
  q.split_boundary = !no_boundary_steiner;
  q.split_segments = !no_segment_steiner;
  q.conforming = conforming;
  q.max_steiner = max_steiner;
  return q;
}

}  // namespace ridt::triangle
