// Point and triangle files: the whole file is read into memory and parsed in place with
// std::from_chars; output is formatted with std::to_chars into a large buffer and written to a
// temporary file beside the target, which is renamed onto the target only when complete.
#include "io.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string_view>
#include <system_error>

namespace ridt::io {
namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// Small helpers.

std::string extension_of(const std::string& path) {
  return fs::path(path).extension().string();
}

[[noreturn]] void fail_file(const std::string& path, const std::string& why) {
  throw IoError(path + ": " + why);
}

[[noreturn]] void fail_line(const std::string& path, std::size_t line, const std::string& why) {
  throw IoError(path + ":" + std::to_string(line) + ": " + why);
}

std::string errno_text(int err) {
  return err != 0 ? std::string(std::strerror(err)) : std::string("unknown error");
}

/// A line (or a field) as it is shown in a message: quoted, printable, at most 80 characters.
std::string quoted(std::string_view s) {
  constexpr std::size_t kMax = 80;
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size() && i < kMax; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    out += (c >= 0x20 && c < 0x7f) || c >= 0x80 ? static_cast<char>(c) : '?';
  }
  if (s.size() > kMax) out += "...";
  out += '"';
  return out;
}

constexpr bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// ---------------------------------------------------------------------------------------------
// Reading.

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

/// The whole file, or IoError("cannot read FILE: <reason>").
std::string read_file(const std::string& path) {
  errno = 0;
  std::unique_ptr<std::FILE, FileCloser> f(std::fopen(path.c_str(), "rb"));
  if (!f) throw IoError("cannot read " + path + ": " + errno_text(errno));
  std::error_code ec;
  const std::uintmax_t hint = fs::file_size(path, ec);
  std::string data;
  // One byte more than the size, so that a regular file is read by one call that hits EOF.
  data.resize(!ec && hint < (std::uintmax_t{1} << 40) ? static_cast<std::size_t>(hint) + 1
                                                       : std::size_t{1} << 16);
  std::size_t used = 0;
  for (;;) {
    if (used == data.size()) data.resize(data.size() * 2);
    const std::size_t want = data.size() - used;
    errno = 0;
    const std::size_t got = std::fread(data.data() + used, 1, want, f.get());
    used += got;
    if (got < want) {
      if (std::ferror(f.get())) throw IoError("cannot read " + path + ": " + errno_text(errno));
      break;
    }
  }
  data.resize(used);
  return data;
}

/// Calls f(line_number, content) for every line that is not blank after removing its
/// comment ('#' to the end of the line) and surrounding white space. Line numbers count from 1.
template <class F>
void for_each_line(std::string_view text, F&& f) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // UTF-8 byte order mark
  const char* p = text.data();
  const char* const end = p + text.size();
  std::size_t line_no = 0;
  while (p < end) {
    const char* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    const char* line_end = nl ? nl : end;
    ++line_no;
    std::string_view line(p, static_cast<std::size_t>(line_end - p));
    p = nl ? nl + 1 : end;
    if (const void* hash = std::memchr(line.data(), '#', line.size()))
      line = line.substr(0, static_cast<std::size_t>(static_cast<const char*>(hash) - line.data()));
    line = trim(line);
    if (!line.empty()) f(line_no, line);
  }
}

/// Fields of a line, separated by white space, or (with allow_comma) by one comma with optional
/// white space around it. A leading, trailing or doubled comma sets `bad`.
struct Fields {
  std::string_view rest;
  bool allow_comma = false;
  bool first = true;
  bool bad = false;

  bool next(std::string_view& out) {
    skip_space();
    if (rest.empty()) return false;
    if (allow_comma && rest.front() == ',') {
      if (first) return bad = true, false;
      rest.remove_prefix(1);
      skip_space();
      if (rest.empty() || rest.front() == ',') return bad = true, false;
    }
    first = false;
    std::size_t n = 0;
    while (n < rest.size() && !is_space(rest[n]) && !(allow_comma && rest[n] == ',')) ++n;
    out = rest.substr(0, n);
    rest.remove_prefix(n);
    return true;
  }

  /// The number of fields left (consumes them).
  std::size_t count_rest() {
    std::size_t n = 0;
    std::string_view f;
    while (next(f)) ++n;
    return n;
  }

 private:
  void skip_space() {
    while (!rest.empty() && is_space(rest.front())) rest.remove_prefix(1);
  }
};

enum class Parse { Ok, Bad, Range };

/// A leading '+' is accepted (from_chars does not), "+-1" is not.
std::string_view strip_plus(std::string_view s) {
  if (s.size() > 1 && s[0] == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
  return s;
}

/// The whole field as a double; nan and inf are parsed (and rejected by the caller).
Parse parse_double(std::string_view s, double& v) {
  s = strip_plus(s);
  if (s.empty()) return Parse::Bad;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec == std::errc::result_out_of_range && ptr == s.data() + s.size()) return Parse::Range;
  if (ec != std::errc() || ptr != s.data() + s.size()) return Parse::Bad;
  return Parse::Ok;
}

/// The whole field as an integer.
Parse parse_int(std::string_view s, std::int64_t& v) {
  s = strip_plus(s);
  if (s.empty()) return Parse::Bad;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec == std::errc::result_out_of_range && ptr == s.data() + s.size()) return Parse::Range;
  if (ec != std::errc() || ptr != s.data() + s.size()) return Parse::Bad;
  return Parse::Ok;
}

std::string not_a_number(std::string_view field) {
  return "coordinate " + quoted(field) + " is not a number";
}

/// A coordinate: the field must be a finite number; `format_error()` is the message for a
/// field that is not a number at all (built only when needed).
template <class Message>
double coordinate(const std::string& path, std::size_t line, std::string_view field,
                  Message&& format_error) {
  double v = 0;
  switch (parse_double(field, v)) {
    case Parse::Ok:
      break;
    case Parse::Bad:
      fail_line(path, line, format_error());
    case Parse::Range:
      fail_line(path, line, "coordinate " + quoted(field) + " is out of range");
  }
  if (std::isnan(v)) fail_line(path, line, "coordinate is NaN");
  if (std::isinf(v)) fail_line(path, line, "coordinate is infinite");
  return v;
}

/// An integer field with a name for messages.
std::int64_t integer(const std::string& path, std::size_t line, std::string_view field,
                     const char* what) {
  std::int64_t v = 0;
  switch (parse_int(field, v)) {
    case Parse::Ok:
      return v;
    case Parse::Bad:
      fail_line(path, line, std::string("expected an integer ") + what + ", got " + quoted(field));
    case Parse::Range:
      fail_line(path, line, std::string(what) + " " + quoted(field) + " is out of range");
  }
  return v;
}

std::size_t count_lines(std::string_view text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
}

std::uint32_t load_u32_le(const char* p) {
  std::uint32_t v;
  std::memcpy(&v, p, 4);
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap32(v);
  return v;
}

double load_f64_le(const char* p) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap64(v);
  return std::bit_cast<double>(v);
}

// --- points ---

PointFile read_text_points(const std::string& path, std::string_view text) {
  PointFile out;
  out.points.reserve(count_lines(text));
  for_each_line(text, [&](std::size_t line_no, std::string_view line) {
    Fields f{line, true};
    std::string_view a, b, extra;
    const bool two = f.next(a) && f.next(b) && !f.next(extra) && !f.bad;
    const auto format_error = [&] {
      return "expected two numbers \"x y\" or \"x,y\", got " + quoted(line);
    };
    if (!two) fail_line(path, line_no, format_error());
    // Both fields' syntax first, so that "1e999 abc" is a format error, not a range one.
    double x = 0, y = 0;
    const Parse px = parse_double(a, x), py = parse_double(b, y);
    if (px != Parse::Ok || py != Parse::Ok) {
      if (px == Parse::Bad || py == Parse::Bad) fail_line(path, line_no, format_error());
      const std::string_view bad = px != Parse::Ok ? a : b;
      fail_line(path, line_no, "coordinate " + quoted(bad) + " is out of range");
    }
    if (std::isnan(x) || std::isnan(y)) fail_line(path, line_no, "coordinate is NaN");
    if (std::isinf(x) || std::isinf(y)) fail_line(path, line_no, "coordinate is infinite");
    out.points.push_back({x, y});
  });
  return out;
}

PointFile read_node(const std::string& path, std::string_view text) {
  PointFile out;
  bool have_header = false;
  std::int64_t n = 0, attrs = 0, markers = 0;
  std::size_t fields_per_line = 3;
  std::size_t count = 0;
  std::string layout;  // "index x y ..." for messages
  for_each_line(text, [&](std::size_t line_no, std::string_view line) {
    if (!have_header) {
      Fields f{line, false};
      std::string_view v[4];
      std::size_t k = 0;
      std::string_view field;
      while (f.next(field)) {
        if (k == 4) {
          fail_line(path, line_no,
                    "expected a header \"points 2 [attributes [markers]]\", got " + quoted(line));
        }
        v[k++] = field;
      }
      if (k < 2) {
        fail_line(path, line_no,
                  "expected a header \"points 2 [attributes [markers]]\", got " + quoted(line));
      }
      n = integer(path, line_no, v[0], "number of points");
      const std::int64_t dim = integer(path, line_no, v[1], "dimension");
      if (k > 2) attrs = integer(path, line_no, v[2], "number of attributes");
      if (k > 3) markers = integer(path, line_no, v[3], "number of boundary markers");
      if (n < 0) fail_line(path, line_no, "negative number of points " + std::to_string(n));
      if (dim != 2) fail_line(path, line_no, "dimension is " + std::to_string(dim) + ", must be 2");
      if (attrs < 0 || attrs > 1000000)
        fail_line(path, line_no, "bad number of attributes " + std::to_string(attrs));
      if (markers != 0 && markers != 1) {
        fail_line(path, line_no,
                  "number of boundary markers must be 0 or 1, got " + std::to_string(markers));
      }
      fields_per_line = 3 + static_cast<std::size_t>(attrs) + static_cast<std::size_t>(markers);
      layout = "index x y";
      if (attrs > 0) layout += " attributes";
      if (markers > 0) layout += " marker";
      // Never trust the header for a huge allocation: a point takes at least 6 bytes.
      out.points.reserve(std::min(static_cast<std::size_t>(n), text.size() / 6 + 1));
      have_header = true;
      return;
    }
    Fields f{line, false};
    std::string_view idx, xs, ys;
    const auto count_error = [&] {
      return "expected " + std::to_string(fields_per_line) + " fields \"" + layout + "\", got " +
             quoted(line);
    };
    if (!f.next(idx) || !f.next(xs) || !f.next(ys)) fail_line(path, line_no, count_error());
    // The remaining fields: attributes (numbers), then the marker (an integer).
    std::string_view field;
    std::size_t k = 3;
    while (f.next(field)) {
      if (k >= fields_per_line) fail_line(path, line_no, count_error());
      if (k < 3 + static_cast<std::size_t>(attrs)) {
        double a = 0;
        if (parse_double(field, a) != Parse::Ok)
          fail_line(path, line_no, "attribute " + quoted(field) + " is not a number");
      } else {
        integer(path, line_no, field, "boundary marker");
      }
      ++k;
    }
    if (k != fields_per_line) fail_line(path, line_no, count_error());
    const std::int64_t i = integer(path, line_no, idx, "point index");
    if (count == 0) {
      if (i != 0 && i != 1) {
        fail_line(path, line_no, "the first point index must be 0 or 1, got " + std::to_string(i));
      }
      out.first_index = static_cast<int>(i);
    } else if (i != out.first_index + static_cast<std::int64_t>(count)) {
      fail_line(path, line_no,
                "expected point index " + std::to_string(out.first_index + count) + ", got " +
                    std::to_string(i) + " (indices must be consecutive)");
    }
    const double x = coordinate(path, line_no, xs, [&] { return not_a_number(xs); });
    const double y = coordinate(path, line_no, ys, [&] { return not_a_number(ys); });
    out.points.push_back({x, y});
    ++count;
  });
  if (!have_header) fail_file(path, "no header line \"points 2 [attributes [markers]]\"");
  if (count != static_cast<std::size_t>(n)) {
    fail_file(path, "header says " + std::to_string(n) + " points but the file has " +
                        std::to_string(count));
  }
  return out;
}

PointFile read_bin_points(const std::string& path, std::string_view data) {
  if (data.size() % 16 != 0) {
    fail_file(path, "size " + std::to_string(data.size()) +
                        " bytes is not a multiple of 16 (pairs of float64 x, y)");
  }
  PointFile out;
  const std::size_t n = data.size() / 16;
  out.points.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = load_f64_le(data.data() + 16 * i);
    const double y = load_f64_le(data.data() + 16 * i + 8);
    if (std::isnan(x) || std::isnan(y))
      fail_file(path, "point " + std::to_string(i) + " has a NaN coordinate");
    if (std::isinf(x) || std::isinf(y))
      fail_file(path, "point " + std::to_string(i) + " has an infinite coordinate");
    out.points[i] = {x, y};
  }
  return out;
}

// --- triangles ---

/// A vertex field of a triangle file, renumbered from `first_index` to 0.
VertexId vertex(const std::string& path, std::size_t line, std::string_view field,
                int first_index) {
  const std::int64_t v = integer(path, line, field, "vertex index");
  // Both bounds are compared before anything is subtracted: v is any 64-bit value, and
  // v - first_index overflows near either end of that range. The largest index stays within
  // 64 bits: first_index is an int and the id limit is 2^32 - 1.
  const std::int64_t lowest = first_index;
  const std::int64_t highest = lowest + std::numeric_limits<VertexId>::max();
  if (v < lowest) {
    fail_line(path, line,
              "vertex index " + std::to_string(v) + " is below the first index " +
                  std::to_string(first_index));
  }
  if (v > highest) {
    fail_line(path, line,
              "vertex index " + std::to_string(v) + " is too large (at most " +
                  std::to_string(highest) + ")");
  }
  return static_cast<VertexId>(v - lowest);
}

std::vector<VertexId> read_text_triangles(const std::string& path, std::string_view text,
                                          int first_index) {
  std::vector<VertexId> out;
  out.reserve(3 * count_lines(text));
  for_each_line(text, [&](std::size_t line_no, std::string_view line) {
    Fields f{line, true};
    std::string_view a, b, c, extra;
    if (!(f.next(a) && f.next(b) && f.next(c) && !f.next(extra) && !f.bad)) {
      fail_line(path, line_no, "expected three vertex indices \"a b c\", got " + quoted(line));
    }
    out.push_back(vertex(path, line_no, a, first_index));
    out.push_back(vertex(path, line_no, b, first_index));
    out.push_back(vertex(path, line_no, c, first_index));
  });
  return out;
}

std::vector<VertexId> read_ele(const std::string& path, std::string_view text, int first_index) {
  std::vector<VertexId> out;
  bool have_header = false;
  std::int64_t n = 0, attrs = 0;
  std::size_t fields_per_line = 4;
  std::size_t count = 0;
  std::int64_t first_triangle = 0;
  const char* const header_form = "expected a header \"triangles 3 [attributes]\", got ";
  for_each_line(text, [&](std::size_t line_no, std::string_view line) {
    if (!have_header) {
      Fields f{line, false};
      std::string_view v[3];
      std::size_t k = 0;
      std::string_view field;
      while (f.next(field)) {
        if (k == 3) fail_line(path, line_no, header_form + quoted(line));
        v[k++] = field;
      }
      if (k < 2) fail_line(path, line_no, header_form + quoted(line));
      n = integer(path, line_no, v[0], "number of triangles");
      const std::int64_t nodes = integer(path, line_no, v[1], "nodes per triangle");
      if (k > 2) attrs = integer(path, line_no, v[2], "number of attributes");
      if (n < 0) fail_line(path, line_no, "negative number of triangles " + std::to_string(n));
      if (nodes != 3) {
        fail_line(path, line_no,
                  "nodes per triangle is " + std::to_string(nodes) + ", must be 3");
      }
      if (attrs < 0 || attrs > 1000000)
        fail_line(path, line_no, "bad number of attributes " + std::to_string(attrs));
      fields_per_line = 4 + static_cast<std::size_t>(attrs);
      out.reserve(3 * std::min(static_cast<std::size_t>(n), text.size() / 8 + 1));
      have_header = true;
      return;
    }
    Fields f{line, false};
    std::string_view idx, a, b, c, field;
    const auto count_error = [&] {
      return "expected " + std::to_string(fields_per_line) + " fields \"index a b c" +
             (attrs > 0 ? " attributes" : "") + "\", got " + quoted(line);
    };
    if (!(f.next(idx) && f.next(a) && f.next(b) && f.next(c))) fail_line(path, line_no, count_error());
    std::size_t k = 4;
    while (f.next(field)) {
      if (k >= fields_per_line) fail_line(path, line_no, count_error());
      double attr = 0;
      if (parse_double(field, attr) != Parse::Ok)
        fail_line(path, line_no, "attribute " + quoted(field) + " is not a number");
      ++k;
    }
    if (k != fields_per_line) fail_line(path, line_no, count_error());
    const std::int64_t i = integer(path, line_no, idx, "triangle index");
    if (count == 0) {
      if (i != 0 && i != 1) {
        fail_line(path, line_no,
                  "the first triangle index must be 0 or 1, got " + std::to_string(i));
      }
      first_triangle = i;
    } else if (i != first_triangle + static_cast<std::int64_t>(count)) {
      fail_line(path, line_no,
                "expected triangle index " + std::to_string(first_triangle + count) + ", got " +
                    std::to_string(i) + " (indices must be consecutive)");
    }
    out.push_back(vertex(path, line_no, a, first_index));
    out.push_back(vertex(path, line_no, b, first_index));
    out.push_back(vertex(path, line_no, c, first_index));
    ++count;
  });
  if (!have_header) fail_file(path, "no header line \"triangles 3 [attributes]\"");
  if (count != static_cast<std::size_t>(n)) {
    fail_file(path, "header says " + std::to_string(n) + " triangles but the file has " +
                        std::to_string(count));
  }
  return out;
}

std::vector<VertexId> read_bin_triangles(const std::string& path, std::string_view data) {
  if (data.size() % 12 != 0) {
    fail_file(path, "size " + std::to_string(data.size()) +
                        " bytes is not a multiple of 12 (triples of uint32 vertex indices)");
  }
  std::vector<VertexId> out(data.size() / 4);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = load_u32_le(data.data() + 4 * i);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Writing.

/// Buffered output to a temporary file beside `path`, renamed onto `path` by commit(). If the
/// writer is destroyed without a successful commit the temporary file is removed.
class Writer {
 public:
  explicit Writer(const std::string& path) : path_(path), tmp_(temp_name(path)) {
    errno = 0;
    out_.open(tmp_, std::ios::binary | std::ios::trunc);
    if (!out_) fail(errno);
    opened_ = true;
  }

  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  ~Writer() {
    if (opened_ && !committed_) {
      out_.close();
      std::remove(tmp_.c_str());
    }
  }

  void put(std::string_view s) {
    if (s.size() > kCapacity - pos_) {
      flush();
      if (s.size() > kCapacity) {
        write_through(s.data(), s.size());
        return;
      }
    }
    std::memcpy(buf_.get() + pos_, s.data(), s.size());
    pos_ += s.size();
  }

  void put(char c) {
    room(1);
    buf_[pos_++] = c;
  }

  /// Shortest decimal form that reads back to exactly `v`.
  void put_double(double v) {
    room(kNumberRoom);
    const auto r = std::to_chars(buf_.get() + pos_, buf_.get() + kCapacity, v);
    pos_ = static_cast<std::size_t>(r.ptr - buf_.get());
  }

  /// `v` with at most `decimals` digits after the point, trailing zeros removed.
  void put_fixed(double v, int decimals) {
    room(kNumberRoom + 320);  // fixed notation of a huge double is long
    char* const begin = buf_.get() + pos_;
    const auto r = std::to_chars(begin, buf_.get() + kCapacity, v, std::chars_format::fixed, decimals);
    char* end = r.ptr;
    if (std::memchr(begin, '.', static_cast<std::size_t>(end - begin))) {
      while (end[-1] == '0') --end;
      if (end[-1] == '.') --end;
    }
    if (end - begin == 2 && begin[0] == '-' && begin[1] == '0') {  // "-0" -> "0"
      begin[0] = '0';
      end = begin + 1;
    }
    pos_ = static_cast<std::size_t>(end - buf_.get());
  }

  void put_int(std::int64_t v) {
    room(kNumberRoom);
    const auto r = std::to_chars(buf_.get() + pos_, buf_.get() + kCapacity, v);
    pos_ = static_cast<std::size_t>(r.ptr - buf_.get());
  }

  void put_u32_le(std::uint32_t v) {
    if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap32(v);
    room(4);
    std::memcpy(buf_.get() + pos_, &v, 4);
    pos_ += 4;
  }

  void put_f64_le(double d) {
    std::uint64_t v = std::bit_cast<std::uint64_t>(d);
    if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap64(v);
    room(8);
    std::memcpy(buf_.get() + pos_, &v, 8);
    pos_ += 8;
  }

  void commit() {
    flush();
    errno = 0;
    out_.close();
    if (out_.fail()) fail(errno);
    errno = 0;
    if (std::rename(tmp_.c_str(), path_.c_str()) != 0) fail(errno);
    committed_ = true;
  }

 private:
  static constexpr std::size_t kCapacity = std::size_t{1} << 20;
  static constexpr std::size_t kNumberRoom = 48;

  static std::string temp_name(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    return path + ".tmp-" + std::to_string(static_cast<long long>(::getpid())) + "-" +
           std::to_string(counter.fetch_add(1));
  }

  [[noreturn]] void fail(int err) const {
    throw IoError("cannot write " + path_ + ": " + errno_text(err));
  }

  void room(std::size_t n) {
    if (kCapacity - pos_ < n) flush();
  }

  void flush() {
    if (pos_ == 0) return;
    write_through(buf_.get(), pos_);
    pos_ = 0;
  }

  void write_through(const char* p, std::size_t n) {
    errno = 0;
    out_.write(p, static_cast<std::streamsize>(n));
    if (!out_) fail(errno);
  }

  std::string path_;
  std::string tmp_;
  std::ofstream out_;
  std::unique_ptr<char[]> buf_{new char[kCapacity]};
  std::size_t pos_ = 0;
  bool opened_ = false;
  bool committed_ = false;
};

/// IoError unless every index of `ids` names one of `n` points.
void check_indices(const std::string& path, std::span<const VertexId> ids, std::size_t n,
                   const char* what) {
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] >= n) {
      fail_file(path, std::string(what) + " refers to vertex " + std::to_string(ids[i]) +
                          " but there are only " + std::to_string(n) + " points");
    }
  }
}

void write_svg(const std::string& path, std::span<const Point> points, const Triangulation& t) {
  const std::size_t nt = t.size();
  if (nt > kSvgMaxTriangles) {
    fail_file(path, std::to_string(nt) + " triangles are too many to draw usefully (at most " +
                        std::to_string(kSvgMaxTriangles) + "); write .off or .ele instead");
  }
  check_indices(path, std::span(t.triangles).first(3 * nt), points.size(), "a triangle");
  check_indices(path, t.hull, points.size(), "the hull");

  // Box of the points, mapped to [0, 1000] along its longer side, y flipped so up is up.
  // Halved coordinates keep the differences finite even for a box wider than the largest double.
  double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
  if (!points.empty()) {
    min_x = max_x = points[0].x;
    min_y = max_y = points[0].y;
    for (const Point& p : points) {
      min_x = std::min(min_x, p.x);
      max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y);
      max_y = std::max(max_y, p.y);
    }
  }
  constexpr double kSide = 1000;
  constexpr double kMargin = 20;
  const double half_w = max_x * 0.5 - min_x * 0.5, half_h = max_y * 0.5 - min_y * 0.5;
  const double half_box = std::max(half_w, half_h);
  const double scale = half_box > 0 ? kSide / half_box : 1;  // per halved unit
  const auto sx = [&](double x) { return (x * 0.5 - min_x * 0.5) * scale; };
  const auto sy = [&](double y) { return (max_y * 0.5 - y * 0.5) * scale; };
  const double width = half_w * scale + 2 * kMargin, height = half_h * scale + 2 * kMargin;
  // Line widths from the mean edge length of a triangulation of this size in the box.
  const double edge = kSide / std::sqrt(static_cast<double>(nt) / 2 + 1);
  const double thin = std::clamp(edge / 25, 0.05, 1.0);
  const double thick = std::max(3 * thin, 1.5);
  const double radius = std::clamp(edge / 10, 0.3, 3.0);

  Writer out(path);
  const auto xy = [&](VertexId v) {
    out.put_fixed(sx(points[v].x), 3);
    out.put(' ');
    out.put_fixed(sy(points[v].y), 3);
  };
  out.put("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"");
  out.put(" viewBox=\"");
  out.put_fixed(-kMargin, 3);
  out.put(' ');
  out.put_fixed(-kMargin, 3);
  out.put(' ');
  out.put_fixed(width, 3);
  out.put(' ');
  out.put_fixed(height, 3);
  out.put("\" width=\"");
  out.put_fixed(width, 0);
  out.put("\" height=\"");
  out.put_fixed(height, 0);
  out.put("\">\n<rect x=\"");
  out.put_fixed(-kMargin, 3);
  out.put("\" y=\"");
  out.put_fixed(-kMargin, 3);
  out.put("\" width=\"100%\" height=\"100%\" fill=\"white\"/>\n");

  if (nt > 0) {
    out.put("<path fill=\"none\" stroke=\"#555\" stroke-linecap=\"round\" stroke-width=\"");
    out.put_fixed(thin, 3);
    out.put("\" d=\"");
    const bool have_neighbors = t.neighbors.size() >= 3 * nt;
    for (std::size_t k = 0; k < nt; ++k) {
      const VertexId* v = &t.triangles[3 * k];
      if (!have_neighbors) {
        out.put('M');
        xy(v[0]);
        out.put('L');
        xy(v[1]);
        out.put('L');
        xy(v[2]);
        out.put('Z');
        continue;
      }
      // Edge v[i] -> v[i+1] lies across from vertex i+2: draw an interior edge once.
      for (int i = 0; i < 3; ++i) {
        const std::int32_t nb = t.neighbors[3 * k + (i + 2) % 3];
        if (nb >= 0 && static_cast<std::size_t>(nb) < k) continue;
        out.put('M');
        xy(v[i]);
        out.put('L');
        xy(v[(i + 1) % 3]);
      }
    }
    out.put("\"/>\n");
  }

  if (!t.hull.empty()) {
    out.put("<polygon fill=\"none\" stroke=\"#c22\" stroke-linejoin=\"round\" stroke-width=\"");
    out.put_fixed(thick, 3);
    out.put("\" points=\"");
    for (std::size_t i = 0; i < t.hull.size(); ++i) {
      if (i > 0) out.put(' ');
      xy(t.hull[i]);
    }
    out.put("\"/>\n");
  }

  if (points.size() <= 20000 && !points.empty()) {
    out.put("<g fill=\"#15c\">\n");
    for (std::size_t i = 0; i < points.size(); ++i) {
      out.put("<circle cx=\"");
      out.put_fixed(sx(points[i].x), 3);
      out.put("\" cy=\"");
      out.put_fixed(sy(points[i].y), 3);
      out.put("\" r=\"");
      out.put_fixed(radius, 3);
      out.put("\"/>\n");
    }
    out.put("</g>\n");
  }
  out.put("</svg>\n");
  out.commit();
}

}  // namespace

// ---------------------------------------------------------------------------------------------

PointFile read_points(const std::string& path) { return parse_points(read_file(path), path); }

PointFile parse_points(std::string_view data, const std::string& name) {
  const std::string ext = extension_of(name);
  if (ext == ".node") return read_node(name, data);
  if (ext == ".bin") return read_bin_points(name, data);
  return read_text_points(name, data);
}

void write_points(const std::string& path, std::span<const Point> points) {
  const std::string ext = extension_of(path);
  Writer out(path);
  if (ext == ".bin") {
    for (const Point& p : points) {
      out.put_f64_le(p.x);
      out.put_f64_le(p.y);
    }
  } else if (ext == ".node") {
    out.put_int(static_cast<std::int64_t>(points.size()));
    out.put(" 2 0 0\n");
    for (std::size_t i = 0; i < points.size(); ++i) {
      out.put_int(static_cast<std::int64_t>(i));
      out.put(' ');
      out.put_double(points[i].x);
      out.put(' ');
      out.put_double(points[i].y);
      out.put('\n');
    }
  } else {
    for (const Point& p : points) {
      out.put_double(p.x);
      out.put(' ');
      out.put_double(p.y);
      out.put('\n');
    }
  }
  out.commit();
}

std::vector<VertexId> read_triangles(const std::string& path, int first_index) {
  return parse_triangles(read_file(path), path, first_index);
}

std::vector<VertexId> parse_triangles(std::string_view data, const std::string& name,
                                      int first_index) {
  const std::string ext = extension_of(name);
  if (ext == ".ele") return read_ele(name, data, first_index);
  if (ext == ".bin") return read_bin_triangles(name, data);
  return read_text_triangles(name, data, first_index);
}

void check_triangulation_extension(const std::string& path) {
  const std::string ext = extension_of(path);
  for (const char* known : {".ele", ".neigh", ".off", ".obj", ".svg", ".bin"})
    if (ext == known) return;
  throw IoError("unknown output extension '" + ext +
                "' (use .ele, .neigh, .off, .obj, .svg or .bin)");
}

void write_triangulation(const std::string& path, std::span<const Point> points,
                         const Triangulation& t, int first_index) {
  check_triangulation_extension(path);
  const std::string ext = extension_of(path);
  const std::size_t nt = t.size();
  const std::span<const VertexId> tris = std::span(t.triangles).first(3 * nt);
  const std::int64_t fi = first_index;

  if (ext == ".svg") {
    write_svg(path, points, t);
    return;
  }
  if (ext == ".neigh" && t.neighbors.size() < 3 * nt) {
    fail_file(path, "the triangulation has " + std::to_string(t.neighbors.size()) +
                        " neighbour entries for " + std::to_string(nt) + " triangles");
  }
  if (ext == ".off" || ext == ".obj") check_indices(path, tris, points.size(), "a triangle");

  Writer out(path);
  if (ext == ".ele") {
    out.put_int(static_cast<std::int64_t>(nt));
    out.put(" 3 0\n");
    for (std::size_t k = 0; k < nt; ++k) {
      out.put_int(static_cast<std::int64_t>(k) + fi);
      for (int i = 0; i < 3; ++i) {
        out.put(' ');
        out.put_int(static_cast<std::int64_t>(tris[3 * k + i]) + fi);
      }
      out.put('\n');
    }
  } else if (ext == ".neigh") {
    out.put_int(static_cast<std::int64_t>(nt));
    out.put(" 3\n");
    for (std::size_t k = 0; k < nt; ++k) {
      out.put_int(static_cast<std::int64_t>(k) + fi);
      for (int i = 0; i < 3; ++i) {
        const std::int32_t nb = t.neighbors[3 * k + i];
        out.put(' ');
        out.put_int(nb < 0 ? -1 : static_cast<std::int64_t>(nb) + fi);
      }
      out.put('\n');
    }
  } else if (ext == ".off") {
    out.put("OFF\n");
    out.put_int(static_cast<std::int64_t>(points.size()));
    out.put(' ');
    out.put_int(static_cast<std::int64_t>(nt));
    out.put(" 0\n");
    for (const Point& p : points) {
      out.put_double(p.x);
      out.put(' ');
      out.put_double(p.y);
      out.put(" 0\n");
    }
    for (std::size_t k = 0; k < nt; ++k) {
      out.put('3');
      for (int i = 0; i < 3; ++i) {
        out.put(' ');
        out.put_int(tris[3 * k + i]);
      }
      out.put('\n');
    }
  } else if (ext == ".obj") {
    for (const Point& p : points) {
      out.put("v ");
      out.put_double(p.x);
      out.put(' ');
      out.put_double(p.y);
      out.put(" 0\n");
    }
    for (std::size_t k = 0; k < nt; ++k) {
      out.put('f');
      for (int i = 0; i < 3; ++i) {
        out.put(' ');
        out.put_int(static_cast<std::int64_t>(tris[3 * k + i]) + 1);
      }
      out.put('\n');
    }
  } else {  // .bin
    for (const VertexId v : tris) out.put_u32_le(v);
  }
  out.commit();
}

}  // namespace ridt::io
