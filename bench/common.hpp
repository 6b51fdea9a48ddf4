// What the benchmarks share: the median they quote, their numbers' format and their
// comma-separated arguments.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace ridt::bench {

/// Wall seconds that body() takes.
template <class Body>
double seconds(Body&& body) {
  const auto start = std::chrono::steady_clock::now();
  body();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

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

/// A table of in-process figures by size: `--sizes N,... --reps R --threads T --csv FILE`.
struct TableArgs {
  std::vector<std::size_t> sizes = {100000, 1000000};
  int reps = 5;
  unsigned threads = 2;
  std::string csv;
};

/// Parses the table's arguments into `a` (its defaults kept); false, with the usage on stderr,
/// for any other.
inline bool parse_table_args(int argc, char** argv, TableArgs& a) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string arg = argv[i];
    if (arg == "--sizes") {
      a.sizes.clear();
      for (const std::string& s : split(argv[i + 1])) a.sizes.push_back(std::stoul(s));
    } else if (arg == "--reps") {
      a.reps = std::atoi(argv[i + 1]);
    } else if (arg == "--csv") {
      a.csv = argv[i + 1];
    } else if (arg == "--threads") {
      a.threads = static_cast<unsigned>(std::atoi(argv[i + 1]));
    } else {
      std::fprintf(stderr, "usage: %s [--sizes N,...] [--reps R] [--threads T] [--csv FILE]\n", argv[0]);
      return false;
    }
  }
  return argc % 2 == 1 || (std::fprintf(stderr, "%s: an option without its value\n", argv[0]), false);
}

/// Writes the header line and then each row rows() gives (an empty row ends the table with
/// status 1), to stdout and to the --csv file; the process's exit status.
inline int write_table(const TableArgs& a, const std::string& header,
                       const std::function<bool(const std::function<void(const std::string&)>&)>& rows) {
  FILE* file = a.csv.empty() ? nullptr : std::fopen(a.csv.c_str(), "w");
  if (!a.csv.empty() && file == nullptr) {
    std::fprintf(stderr, "cannot write %s\n", a.csv.c_str());
    return 1;
  }
  auto line = [&](const std::string& text) {
    std::fputs(text.c_str(), stdout);
    if (file != nullptr) std::fputs(text.c_str(), file);
    std::fflush(stdout);
  };
  line(header);
  const bool ok = rows(line);
  if (file != nullptr) std::fclose(file);
  return ok ? 0 : 1;
}

}  // namespace ridt::bench
