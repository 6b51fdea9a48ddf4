// What the benchmarks share: the median they quote, their numbers' format and their
// comma-separated arguments.
#pragma once

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace ridt::bench {

/// The median of v (the upper one of an even count); 0 when v is empty.
inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

/// v printed with a printf format for one double ("%.4f").
inline std::string format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

/// "a,b,c" -> {"a", "b", "c"}.
inline std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> parts;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) parts.push_back(item);
  return parts;
}

}  // namespace ridt::bench
