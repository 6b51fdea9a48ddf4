// What the subcommands share (command.hpp).
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <thread>

#include "command.hpp"

namespace ridt::tool {

// CLI11 2.1 converts with strtoull, which takes "-1" as 2^64 - 1 and any larger number as
// 2^64 - 1 too, so the text is checked before it is converted.
const CLI::Validator kSeed(
    [](std::string& text) -> std::string {
      std::uint64_t v = 0;
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (ec == std::errc() && end == text.data() + text.size()) return "";
      return "a seed is an integer from 0 to 18446744073709551615, got '" + text + "'";
    },
    "SEED");

CLI::Validator non_negative(const char* what) {
  return CLI::Validator(
      [what](std::string& text) -> std::string {
        double v = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec == std::errc() && end == text.data() + text.size() && std::isfinite(v) && v >= 0) return "";
        return std::string(what) + " is a finite number >= 0, got '" + text + "'";
      },
      "NUMBER");
}

std::vector<double> numbers(const std::string& text, const char* what) {
  std::vector<double> out;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    double v = 0;
    const char* first = text.data() + at;
    const char* last = text.data() + comma;
    const auto r = std::from_chars(first, last, v);
    if (r.ec != std::errc() || r.ptr != last || !std::isfinite(v))
      throw InputError(std::string(what) + ": '" + text + "' is not a list of finite numbers apart by commas");
    out.push_back(v);
    at = comma + 1;
  }
  return out;
}

std::size_t byte_size(const std::string& text, const char* what) {
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  const std::string unit(end, text.data() + text.size());
  const std::string units = "KMGT";
  const std::size_t k = unit.size() == 1 ? units.find(static_cast<char>(std::toupper(unit[0]))) : std::string::npos;
  if (ec != std::errc() || !(v > 0) || !std::isfinite(v) || (!unit.empty() && k == std::string::npos))
    throw InputError(std::string(what) + ": '" + text + "' is not a size (bytes, or a number with K, M, G or T)");
  const double bytes = v * std::pow(1024.0, unit.empty() ? 0 : static_cast<double>(k + 1));
  if (bytes >= 1.8e19) throw InputError(std::string(what) + ": '" + text + "' is too large");
  return static_cast<std::size_t>(bytes);
}

void check_memory(const std::string& what, std::size_t needed, std::size_t limit) {
  if (limit == 0) limit = available_memory();
  if (limit == 0 || needed <= limit) return;  // 0: the system does not say
  const auto gb = [](std::size_t bytes) {
    char text[32];
    if (bytes >= 1000000000)
      std::snprintf(text, sizeof text, "%.1f GB", static_cast<double>(bytes) / 1e9);
    else
      std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / 1e6);
    return std::string(text);
  };
  throw MemoryError(what + " needs about " + gb(needed) + "; " + gb(limit) + " is available", needed, limit);
}

io::Box box_option(const std::string& text, std::span<const Point> points) {
  if (text.empty()) return io::box_around(points, 0.1);
  const std::vector<double> b = numbers(text, "--box");
  if (b.size() != 4 || !(b[0] < b[2]) || !(b[1] < b[3]))
    throw InputError("--box: give x0,y0,x1,y1 with x0 < x1 and y0 < y1");
  return {b[0], b[1], b[2], b[3]};
}

void refuse_overwriting(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs) {
  namespace fs = std::filesystem;
  for (const std::string& in : inputs) {
    std::error_code ec;
    // A device or a pipe may be read and written at once (/dev/stdin and /dev/stdout of a
    // terminal are one device); a regular file would be replaced.
    if (in.empty() || !fs::is_regular_file(in, ec)) continue;
    for (const std::string& out : outputs)
      if (!out.empty() && fs::equivalent(in, out, ec))
        throw InputError("the output " + out + " is the input " + in + ": it would be overwritten; give another name");
  }
}

void refuse_ignored(bool given, const std::string& option, const std::string& why) {
  if (given) throw InputError(option + " " + why);
}

unsigned thread_count(unsigned asked) { return asked != 0 ? asked : std::max(1u, std::thread::hardware_concurrency()); }

long long peak_rss_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<long long>(u.ru_maxrss) * 1024;  // Linux reports kilobytes
}

ProgressLine::ProgressLine() : on_(isatty(STDERR_FILENO) == 1), start_(std::chrono::steady_clock::now()) {}

void ProgressLine::show(const char* phase, double fraction) {
  if (!on_) return;
  const double now = seconds_since(start_);
  if (now < 0.5 || (shown_ && now - last_ < 0.1 && phase == phase_)) return;
  if (fraction >= 0 && fraction < 1)
    std::fprintf(stderr, "\r\033[Kridt: %s %3.0f%%", phase, 100 * fraction);
  else
    std::fprintf(stderr, "\r\033[Kridt: %s", phase);
  std::fflush(stderr);
  shown_ = true, last_ = now, phase_ = phase;
}

void ProgressLine::clear() {
  if (!shown_) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
  shown_ = false;
}

}  // namespace ridt::tool
