// ridt-mpi's command line: POINTS.bin -o OUT.ele [--merge] [--threads T] [--stats].
#pragma once

#include "mpi.hpp"

namespace ridt::mpi {

struct Args {
  std::string input, output;
  bool merge = false, stats = false;
  unsigned threads = 1;
};

inline void usage() {
  std::fprintf(stderr,
               "usage: mpirun -np P ridt-mpi POINTS.bin -o OUT.ele [--merge] [--threads T] [--stats]\n"
               "  POINTS.bin  raw little-endian float64 x, y pairs (ridt generate -o FILE.bin writes one)\n"
               "  -o OUT.ele  each rank writes OUT.r-of-P.ele and rank 0 the index OUT.parts\n"
               "  --merge     write one OUT.ele instead (canonical order; for sets that fit one machine)\n"
               "  --threads T threads for each rank's triangulation (default 1)\n"
               "  --stats     print each rank's points, rounds, traffic and time\n");
}

inline std::optional<Args> parse(int argc, char** argv, std::string& error) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw Failure(s + " needs a value");
      return argv[++i];
    };
    try {
      if (s == "-h" || s == "--help") return std::nullopt;
      if (s == "-o" || s == "--output") {
        a.output = value();
      } else if (s == "--merge") {
        a.merge = true;
      } else if (s == "--stats") {
        a.stats = true;
      } else if (s == "--threads") {
        const std::string v = value();
        const unsigned long t = std::stoul(v);
        if (t < 1 || t > 1024 || std::to_string(t) != v) throw Failure("--threads must be 1 to 1024, not " + v);
        a.threads = static_cast<unsigned>(t);
      } else if (!s.empty() && s[0] == '-') {
        throw Failure("unknown option " + s);
      } else if (a.input.empty()) {
        a.input = s;
      } else {
        throw Failure("one input file only (got " + a.input + " and " + s + ")");
      }
    } catch (const Failure& f) {
      error = f.message;
      return a;
    } catch (const std::exception&) {
      error = "bad value for " + s;
      return a;
    }
  }
  if (a.input.empty())
    error = "no input file";
  else if (a.output.empty())
    error = "no output (-o OUT.ele)";
  else if (ridt::io::extension(a.input) != ".bin")
    error = a.input + ": ridt-mpi reads .bin files (float64 x, y pairs); ridt generate -o FILE.bin writes one";
  else if (ridt::io::extension(a.output) != ".ele")
    error = a.output + ": ridt-mpi writes .ele files";
  return a;
}

}  // namespace ridt::mpi
