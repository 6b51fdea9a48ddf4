// Deterministic fuzzing, for the test command: a driver for a fuzz target's
// LLVMFuzzerTestOneInput that runs every input of the committed corpus once, then a fixed
// number of mutations of those inputs drawn from a seeded generator.
//
// libFuzzer itself is the open-ended search (scripts/fuzz.sh): which inputs it tries depends on
// the coverage each run reaches, and the threaded methods reach a little more or less from run
// to run, so two runs of one commit differ, and a 30-second run may or may not meet a fault that
// is already there. Here the inputs depend only on the corpus (read in name order), the
// dictionary, the seed and the count: every run of a commit runs the same inputs, a failure
// repeats, and it means that the code under test changed. New coverage reaches the corpus
// through scripts/fuzz.sh with RIDT_FUZZ_MERGE=1.
//
// The mutations are those of a byte-level fuzzer: flip a bit, set a byte to a random or a
// boundary value, erase, insert or copy a stretch, splice two inputs, insert a dictionary
// token, and replace a number written in the input by one at a limit of its type (the class
// of input that found the overflow in the triangle reader).
//
// Usage: fuzz_replay_TARGET [--seed S] [--mutations N] [--max-len L] [--dict FILE]
//                           [--save DIR] [--only K] CORPUS_DIR...
//   Input k < corpus size is corpus file k; input corpus size + j is mutation j. On a finding
//   (the target aborts, crashes, runs for 120 s, or a sanitizer stops it) the input is written
//   to DIR/replay-<k> and its number printed; --only K runs input K alone (the same bytes).
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

// SplitMix64 (Steele, Lea and Flood, 2014), as the library's own seeded streams compute it, so
// that a seed replays the same mutations it always has; this program takes nothing from the
// library's sources.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Stream `stream` of a seed: value k is mix64 of the seed's key plus k steps.
class Rng {
 public:
  Rng(std::uint64_t seed, std::uint64_t stream) : state_(mix64(seed ^ mix64(stream + 0x632be59bd9b4e019ULL))) {}
  std::uint64_t next() { return mix64(state_ += 0x9e3779b97f4a7c15ULL); }
  // Uniform in [0, bound), without modulo bias (Lemire, 2019).
  std::uint64_t below(std::uint64_t bound) {
    unsigned __int128 m = static_cast<unsigned __int128>(next()) * bound;
    if (auto low = static_cast<std::uint64_t>(m); low < bound)
      for (const std::uint64_t threshold = (0 - bound) % bound; low < threshold; low = static_cast<std::uint64_t>(m))
        m = static_cast<unsigned __int128>(next()) * bound;
    return static_cast<std::uint64_t>(m >> 64);
  }

 private:
  std::uint64_t state_;
};

}  // namespace

// Defined by the sanitizer runtimes when linked in: a callback run before a sanitizer ends the
// process (ASan calls it; GCC's UBSan does not, hence abort_on_error below).
extern "C" void __sanitizer_set_death_callback(void (*callback)()) __attribute__((weak));

// The sanitizers' defaults in this program, read by their runtimes at start (the environment's
// options still apply on top): every report is a finding, and it ends in abort(), which the
// SIGABRT handler below turns into a saved input.
extern "C" const char* __asan_default_options() { return "abort_on_error=1"; }
extern "C" const char* __ubsan_default_options() { return "halt_on_error=1:abort_on_error=1:print_stacktrace=1"; }

namespace {

namespace fs = std::filesystem;
using Bytes = std::string;

[[noreturn]] void usage_error(const std::string& why) {
  std::fprintf(stderr, "fuzz_replay: %s\n", why.c_str());
  std::exit(2);
}

// --- the input being run, for the handlers that report a finding ---------------------------

// Written before each input runs; read only by the handlers, which use only
// async-signal-safe calls (open, write, close).
const Bytes* g_current = nullptr;
std::uint64_t g_current_number = 0;
char g_save_dir[4096] = ".";

void write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w <= 0) return;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
}

void write_text(int fd, const char* s) { write_all(fd, s, std::strlen(s)); }

/// Decimal form of `v` into `buf` (at least 21 bytes); returns the start.
char* format_u64(std::uint64_t v, char* buf) {
  char* p = buf + 20;
  *p = '\0';
  do {
    *--p = static_cast<char>('0' + v % 10);
    v /= 10;
  } while (v != 0);
  return p;
}

void save_current_input() {
  static volatile std::sig_atomic_t saved = 0;
  if (g_current == nullptr || saved) return;
  saved = 1;
  char number[21];
  const char* k = format_u64(g_current_number, number);
  char path[sizeof g_save_dir + 40];
  path[0] = '\0';
  std::strcat(path, g_save_dir);
  std::strcat(path, "/replay-");
  std::strcat(path, k);
  const int fd = ::open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0) {
    write_all(fd, g_current->data(), g_current->size());
    ::close(fd);
  }
  write_text(2, "fuzz_replay: finding on input ");
  write_text(2, k);
  write_text(2, ", saved as ");
  write_text(2, fd >= 0 ? path : "(could not be saved)");
  write_text(2, "; run it alone with --only ");
  write_text(2, k);
  write_text(2, "\n");
}

void on_fatal_signal(int sig) {
  save_current_input();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// An input that runs this long is a hang, not a slow input: libFuzzer ran none of the corpora's
// inputs for a second under the sanitizers. Generous, so that a loaded machine never trips it.
constexpr unsigned kHangSeconds = 120;

void on_hang(int) {
  write_text(2, "fuzz_replay: an input ran for 120 s\n");  // kHangSeconds
  save_current_input();
  std::signal(SIGABRT, SIG_DFL);
  std::abort();
}

// --- inputs ----------------------------------------------------------------------------------

Bytes read_file(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) usage_error("cannot read " + path.string());
  return Bytes(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

/// Every regular file under the corpus folders, in the order of their paths. A folder that is
/// missing or empty is an error: a replay of nothing would pass without testing anything.
std::vector<Bytes> read_corpus(const std::vector<std::string>& dirs) {
  std::vector<Bytes> corpus;
  for (const std::string& dir : dirs) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) usage_error("corpus folder " + dir + " is missing");
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
      if (e.is_regular_file()) files.push_back(e.path());
    if (files.empty()) usage_error("corpus folder " + dir + " is empty");
    std::sort(files.begin(), files.end());
    for (const fs::path& p : files) corpus.push_back(read_file(p));
  }
  return corpus;
}

/// Tokens of a libFuzzer dictionary: one quoted string a line (`name="..."` or `"..."`), with
/// \\, \" and \xNN escapes; '#' starts a comment line.
std::vector<Bytes> read_dictionary(const std::string& path) {
  std::vector<Bytes> tokens;
  std::ifstream f(path);
  if (!f) usage_error("cannot read dictionary " + path);
  std::string line;
  for (int line_no = 1; std::getline(f, line); ++line_no) {
    const std::size_t open = line.find('"');
    const std::size_t close = line.rfind('"');
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    if (open == std::string::npos || close <= open)
      usage_error(path + ":" + std::to_string(line_no) + ": expected a quoted token");
    Bytes token;
    for (std::size_t i = open + 1; i < close; ++i) {
      if (line[i] != '\\') {
        token += line[i];
      } else if (i + 1 < close && (line[i + 1] == '\\' || line[i + 1] == '"')) {
        token += line[++i];
      } else if (i + 3 < close && line[i + 1] == 'x') {
        token += static_cast<char>(std::stoi(line.substr(i + 2, 2), nullptr, 16));
        i += 3;
      } else {
        usage_error(path + ":" + std::to_string(line_no) + ": bad escape");
      }
    }
    tokens.push_back(token);
  }
  return tokens;
}

// --- mutations -------------------------------------------------------------------------------

// Numbers at the limits of the types a reader converts to, and text a number may become.
constexpr std::string_view kNumbers[] = {"0",
                                         "-0",
                                         "1",
                                         "-1",
                                         "2147483647",
                                         "-2147483648",
                                         "4294967295",
                                         "4294967296",
                                         "9223372036854775807",
                                         "-9223372036854775808",
                                         "9223372036854775808",
                                         "18446744073709551615",
                                         "18446744073709551616",
                                         "1e308",
                                         "-1e309",
                                         "4.9e-324",
                                         "2.2250738585072014e-308",
                                         "nan",
                                         "inf",
                                         "-inf",
                                         "0x10",
                                         "1e",
                                         "+",
                                         "-"};

// Bytes at the edges of their classes: control, space, digits, signs, punctuation, high bit.
constexpr unsigned char kBytes[] = {0x00, 0x01, 0x09, 0x0a, 0x0d, 0x20, '#',  '+',  ',',  '-',
                                    '.',  '0',  '1',  '9',  'e',  'x',  0x7f, 0x80, 0xef, 0xff};

class Mutator {
 public:
  Mutator(std::vector<Bytes> corpus, std::vector<Bytes> dictionary, std::size_t max_len, std::uint64_t seed)
      : corpus_(std::move(corpus)), dictionary_(std::move(dictionary)), max_len_(max_len), seed_(seed) {}

  const std::vector<Bytes>& corpus() const { return corpus_; }

  /// Mutation j: a function of (seed, j) alone, so that --only reproduces it without
  /// generating the ones before it.
  Bytes make(std::uint64_t j) const {
    Rng rng(seed_, j);
    Bytes b = corpus_[rng.below(corpus_.size())];
    const std::uint64_t steps = 1 + rng.below(4);
    for (std::uint64_t s = 0; s < steps; ++s) mutate(b, rng);
    if (b.size() > max_len_) b.resize(max_len_);
    return b;
  }

 private:
  static std::size_t pick(Rng& rng, std::size_t n) { return static_cast<std::size_t>(rng.below(n)); }

  void mutate(Bytes& b, Rng& rng) const {
    switch (rng.below(9)) {
      case 0:  // flip a bit
        if (!b.empty()) b[pick(rng, b.size())] ^= static_cast<char>(1u << rng.below(8));
        break;
      case 1:  // a random byte
        if (!b.empty()) b[pick(rng, b.size())] = static_cast<char>(rng.below(256));
        break;
      case 2:  // a byte at the edge of its class
        if (!b.empty()) b[pick(rng, b.size())] = static_cast<char>(kBytes[pick(rng, std::size(kBytes))]);
        break;
      case 3:  // erase a stretch
        if (!b.empty()) {
          const std::size_t at = pick(rng, b.size());
          b.erase(at, 1 + pick(rng, std::min<std::size_t>(b.size() - at, 16)));
        }
        break;
      case 4: {  // insert random bytes
        Bytes ins(1 + pick(rng, 8), '\0');
        for (char& c : ins) c = static_cast<char>(rng.below(256));
        b.insert(pick(rng, b.size() + 1), ins);
        break;
      }
      case 5:  // copy a stretch of the input elsewhere into it
        if (!b.empty()) {
          const std::size_t from = pick(rng, b.size());
          const std::size_t length = 1 + pick(rng, std::min<std::size_t>(b.size() - from, 64));
          const Bytes part = b.substr(from, length);
          b.insert(pick(rng, b.size() + 1), part);
        }
        break;
      case 6: {  // splice: this input's head, another's tail
        const Bytes& other = corpus_[pick(rng, corpus_.size())];
        b.resize(pick(rng, b.size() + 1));
        b += other.substr(pick(rng, other.size() + 1));
        break;
      }
      case 7:  // a dictionary token
        if (!dictionary_.empty()) b.insert(pick(rng, b.size() + 1), dictionary_[pick(rng, dictionary_.size())]);
        break;
      case 8:  // a number in the text replaced by one at a limit
        replace_number(b, rng);
        break;
    }
  }

  /// Replaces the run of digits (with its sign) around a random position, or inserts a number
  /// there if there is none.
  static void replace_number(Bytes& b, Rng& rng) {
    const std::string_view number = kNumbers[pick(rng, std::size(kNumbers))];
    const auto digit = [&](std::size_t i) { return b[i] >= '0' && b[i] <= '9'; };
    std::size_t at = pick(rng, b.size() + 1), end = at;
    while (at > 0 && digit(at - 1)) --at;
    while (end < b.size() && digit(end)) ++end;
    if (at > 0 && (b[at - 1] == '-' || b[at - 1] == '+')) --at;
    b.replace(at, end - at, number);
  }

  std::vector<Bytes> corpus_;
  std::vector<Bytes> dictionary_;
  std::size_t max_len_;
  std::uint64_t seed_;
};

std::uint64_t parse_count(const std::string& option, const char* value) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(value, &end, 10);
  if (errno != 0 || end == value || *end != '\0' || value[0] == '-')
    usage_error(option + " needs a non-negative integer, got '" + value + "'");
  return v;
}

void run(const Bytes& input, std::uint64_t number) {
  g_current = &input;
  g_current_number = number;
  ::alarm(kHangSeconds);
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
  ::alarm(0);
  g_current = nullptr;
}

// The command line.
struct Args {
  std::uint64_t seed = 1, mutations = 0, max_len = 4096;
  std::optional<std::uint64_t> only;
  std::string dictionary_path;
  std::vector<std::string> dirs;
};

Args parse_args(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> const char* {
      if (i + 1 >= argc) usage_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--seed")
      a.seed = parse_count(arg, value());
    else if (arg == "--mutations")
      a.mutations = parse_count(arg, value());
    else if (arg == "--max-len")
      a.max_len = parse_count(arg, value());
    else if (arg == "--only")
      a.only = parse_count(arg, value());
    else if (arg == "--dict")
      a.dictionary_path = value();
    else if (arg == "--save") {
      const std::string dir = value();
      if (dir.size() >= sizeof g_save_dir) usage_error("--save folder name too long");
      std::strcpy(g_save_dir, dir.c_str());
    } else if (arg.starts_with("--"))
      usage_error("unknown option " + arg);
    else
      a.dirs.push_back(arg);
  }
  if (a.dirs.empty()) usage_error("no corpus folder given");
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  const Args a = parse_args(argc, argv);
  std::vector<Bytes> dictionary;
  if (!a.dictionary_path.empty()) dictionary = read_dictionary(a.dictionary_path);
  const Mutator mutator(read_corpus(a.dirs), std::move(dictionary), a.max_len, a.seed);
  const std::vector<Bytes>& corpus = mutator.corpus();
  std::error_code ec;
  fs::create_directories(g_save_dir, ec);

  if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(save_current_input);
  for (int sig : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) std::signal(sig, on_fatal_signal);
  std::signal(SIGALRM, on_hang);

  const auto input = [&](std::uint64_t k) { return k < corpus.size() ? corpus[k] : mutator.make(k - corpus.size()); };
  if (a.only) {  // any number is well defined: past the corpus, it is a mutation
    run(input(*a.only), *a.only);
    std::printf("fuzz_replay: input %llu ran without a finding\n", static_cast<unsigned long long>(*a.only));
    return 0;
  }
  // A digest of every input run, printed so that two runs can be seen to run the same inputs.
  std::uint64_t digest = 0xcbf29ce484222325ULL;
  const std::uint64_t total = corpus.size() + a.mutations;
  for (std::uint64_t k = 0; k < total; ++k) {
    const Bytes in = input(k);
    for (const char c : in) digest = (digest ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
    digest = mix64(digest ^ in.size());  // FNV-1a bytes, then the length
    run(in, k);
  }
  std::printf(
      "fuzz_replay: %zu corpus inputs and %llu mutations (seed %llu, inputs' digest "
      "%016llx) ran without a finding\n",
      corpus.size(), static_cast<unsigned long long>(a.mutations), static_cast<unsigned long long>(a.seed),
      static_cast<unsigned long long>(digest));
  return 0;
}
