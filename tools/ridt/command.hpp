// The tool's subcommands and what they share. Each subcommand is a file: it adds its options
// to the app and returns what runs when it is chosen (main.cpp).
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "io.hpp"
#include "ridt/ridt.hpp"

namespace ridt::tool {

inline constexpr int kExitInvalid = 1;  ///< check: the triangulation is not valid
inline constexpr int kExitUsage = 2;  ///< bad input or usage

/// A subcommand: its CLI11 app, and what runs when it is chosen (returns the exit status).
struct Command {
  CLI::App* app;
  std::function<int()> run;
};

Command add_triangulate(CLI::App& app);
Command add_generate(CLI::App& app);
Command add_check(CLI::App& app);
Command add_voronoi(CLI::App& app);
Command add_formats(CLI::App& app);
Command add_interpolate(CLI::App& app);
Command add_mesh(CLI::App& app);
Command add_tin(CLI::App& app);
Command add_dem(CLI::App& app);
Command add_sphere(CLI::App& app);
Command add_regular(CLI::App& app);
Command add_periodic(CLI::App& app);

/// A seed as text: the whole of it a decimal integer that fits 64 bits.
extern const CLI::Validator kSeed;

/// A finite number >= 0 as text (`what` names it in the message).
CLI::Validator non_negative(const char* what);

/// Numbers apart by commas, e.g. "200,100" or "0,0,1,1"; `what` names them in a message.
std::vector<double> numbers(const std::string& text, const char* what);

/// A size in bytes: a number with an optional K, M, G or T (powers of 1024), e.g. "800M";
/// `what` names it in a message.
std::size_t byte_size(const std::string& text, const char* what);

/// MemoryError, before anything is allocated, where `needed` bytes (for `what`, e.g. "writing N
/// points") are more than `limit` (a --memory-limit; 0: what the system can give now,
/// ridt::available_memory()).
void check_memory(const std::string& what, std::size_t needed, std::size_t limit);

/// The help of a --memory-limit option.
inline constexpr const char* kMemoryLimitHelp =
    "the most memory the run may take, e.g. 800M or 12G (default: what the system can give); a run that needs "
    "more is refused before it starts";

/// The box of --box ("x0,y0,x1,y1"), or the points' box and 10 % around when `text` is empty.
io::Box box_option(const std::string& text, std::span<const Point> points);

/// InputError where an output is the same regular file as an input (another name or a link to
/// it too): writing it would destroy what is read. Asked before anything is written.
void refuse_overwriting(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs);

/// InputError naming `option` and `why` where `given` (an option given that the run would
/// ignore).
void refuse_ignored(bool given, const std::string& option, const std::string& why);

/// The threads a --threads value asks for: itself, or every hardware thread for 0.
unsigned thread_count(unsigned asked);

/// The process's peak resident memory in bytes.
long long peak_rss_bytes();

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// "name: help; ..." for an option whose values are E's (ridt::names), its default first.
template <class E>
std::string choices_help(const std::string& intro, E fallback) {
  std::string help = intro + (intro.empty() ? "" : ": ");
  for (const Named<E>& n : names<E>()) {
    help += std::string(n.name) + (n.value == fallback ? " (default)" : "") + ": " + std::string(n.help) + "; ";
  }
  return help.substr(0, help.size() - 2);
}

/// One line on stderr that says how far a long run is, only when stderr is a terminal: never
/// in a pipe or a file, and never on stdout, where --stats goes. It appears once the run has
/// taken half a second, changes at most ten times a second, and is erased when done.
class ProgressLine {
 public:
  ProgressLine();
  ~ProgressLine() { clear(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  bool on() const { return on_; }
  /// "ridt: PHASE" and, for a fraction in [0, 1), its percentage.
  void show(const char* phase, double fraction = -1);
  /// Erases the line (before a message, and at the end).
  void clear();

 private:
  bool on_, shown_ = false;
  std::chrono::steady_clock::time_point start_;
  double last_ = 0;
  const char* phase_ = nullptr;
};

}  // namespace ridt::tool
