// What the readers and writers of every format share (io.hpp): messages, the parsing of
// lines and fields, little-endian loads, and the Writer that makes a file appear whole or not
// at all.
#pragma once

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cctype>
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
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "io.hpp"
#include "writer.hpp"

namespace ridt::io::detail {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// Small helpers.

/// `s` in lower case (ASCII): for names and extensions compared in any case.
inline std::string lower_case(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

/// A file's extension in lower case: formats are chosen by extension in any case (.TIF, .Ele).
inline std::string extension_of(const std::string& path) { return lower_case(fs::path(path).extension().string()); }

[[noreturn]] inline void fail_file(const std::string& path, const std::string& why) {
  throw IoError(path + ": " + why);
}

[[noreturn]] inline void fail_line(const std::string& path, std::size_t line, const std::string& why) {
  throw IoError(path + ":" + std::to_string(line) + ": " + why);
}

inline std::string errno_text(int err) {
  return err != 0 ? std::string(std::strerror(err)) : std::string("unknown error");
}

/// A line (or a field) as it is shown in a message: quoted, printable, at most 80 characters.
inline std::string quoted(std::string_view s) {
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

constexpr bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

inline std::string_view trim(std::string_view s) {
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
inline std::string read_file_whole(const std::string& path) {
  errno = 0;
  std::unique_ptr<std::FILE, FileCloser> f(std::fopen(path.c_str(), "rb"));
  if (!f) throw IoError("cannot read " + path + ": " + errno_text(errno));
  std::error_code ec;
  const std::uintmax_t hint = fs::file_size(path, ec);
  std::string data;
  // One byte more than the size, so that a regular file is read by one call that hits EOF.
  data.resize(!ec && hint < (std::uintmax_t{1} << 40) ? static_cast<std::size_t>(hint) + 1 : std::size_t{1} << 16);
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

/// What a reader says of a file that shrank while it was read.
inline IoError shrank_error(const std::string& path) {
  return IoError(path + ": the file shrank while it was read (truncated or rewritten by another process)");
}

/// A regular file's bytes mapped into memory: the page cache's own pages, shared, never
/// copied, kept while `owner` lives, and watched while they are (watch_mapping).
struct Mapping {
  std::shared_ptr<const void> owner;
  std::string_view bytes;
  int watch = -1;
  /// Whether the file shrank under the mapping (the bytes past its end read as zeros).
  bool shrank() const { return mapping_shrank(watch); }
};

/// `path` mapped, or none where it is not a regular file with some bytes (a pipe, a device) or
/// cannot be mapped: then it is to be read. IoError where it cannot be opened.
inline std::optional<Mapping> map_file(const std::string& path) {
  // Asked before opening it, which would take the writer's end of a pipe from the reader that
  // follows.
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_size == 0) return std::nullopt;
  errno = 0;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw IoError("cannot read " + path + ": " + errno_text(errno));
  void* at = MAP_FAILED;
  std::size_t bytes = 0;
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    bytes = static_cast<std::size_t>(st.st_size);
    at = ::mmap(nullptr, bytes, PROT_READ, MAP_PRIVATE, fd, 0);
  }
  ::close(fd);
  if (at == MAP_FAILED) return std::nullopt;
  const int watch = watch_mapping(at, bytes);
  return Mapping{std::shared_ptr<const void>(at,
                                             [bytes, watch](const void* p) {
                                               unwatch_mapping(watch);
                                               ::munmap(const_cast<void*>(p), bytes);
                                             }),
                 std::string_view(static_cast<const char*>(at), bytes), watch};
}

/// A file's bytes: mapped where it is a regular file (map_file), else read whole; IoError as
/// read_file_whole.
class FileText {
 public:
  explicit FileText(const std::string& path) : path_(path) {
    if (std::optional<Mapping> m = map_file(path)) {
      map_ = std::move(*m);
      ::madvise(const_cast<char*>(map_.bytes.data()), map_.bytes.size(), MADV_SEQUENTIAL);  // read ahead from a disk
    } else {
      read_ = read_file_whole(path);
    }
  }

  std::string_view view() const { return map_.owner ? map_.bytes : std::string_view(read_); }

  /// parse(view()), or IoError (shrank_error) where the file shrank while it was read, what the
  /// parse made of the zeros in its place, or threw on them, then set aside.
  template <class Parse>
  auto parse(Parse&& parse) const {
    try {
      auto result = parse(view());
      if (map_.shrank()) throw shrank_error(path_);
      return result;
    } catch (const IoError&) {
      if (map_.shrank()) throw shrank_error(path_);
      throw;
    }
  }

 private:
  std::string path_;
  Mapping map_;
  std::string read_;
};

/// A line's content: without its comment ('#' to the end of the line) and the white space
/// around.
inline std::string_view content_of(std::string_view line) {
  if (const void* hash = std::memchr(line.data(), '#', line.size()))
    line = line.substr(0, static_cast<std::size_t>(static_cast<const char*>(hash) - line.data()));
  return trim(line);
}

/// `text` without a UTF-8 byte order mark at its start.
inline std::string_view without_bom(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  return text;
}

/// for_each_line's scan, with no byte order mark taken off; returns how many lines `text` has
/// (a last one without a line end counted).
template <class F>
inline std::size_t lines_of(std::string_view text, F&& f) {
  const char* p = text.data();
  const char* const end = p + text.size();
  std::size_t line_no = 0;
  while (p < end) {
    const char* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    const char* line_end = nl ? nl : end;
    ++line_no;
    const std::string_view line = content_of(std::string_view(p, static_cast<std::size_t>(line_end - p)));
    p = nl ? nl + 1 : end;
    if (!line.empty()) f(line_no, line);
  }
  return line_no;
}

/// Calls f(line_number, content) for every line that is not blank after removing its
/// comment ('#' to the end of the line) and surrounding white space. Line numbers count from 1.
template <class F>
inline void for_each_line(std::string_view text, F&& f) {
  lines_of(without_bom(text), f);
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

/// The white-space fields of a header or record line: at least `least`, at most `most`, else
/// "expected EXPECTED, got LINE".
inline std::vector<std::string_view> fields_of(const std::string& path, std::size_t line_no, std::string_view line,
                                               std::size_t least, std::size_t most, const std::string& expected) {
  Fields f{line, false};
  std::vector<std::string_view> out;
  std::string_view x;
  while (out.size() < most && f.next(x)) out.push_back(x);
  if (out.size() < least || f.next(x)) fail_line(path, line_no, "expected " + expected + ", got " + quoted(line));
  return out;
}

enum class Parse { Ok, Bad, Range };

/// A leading '+' is accepted (from_chars does not), "+-1" is not.
inline std::string_view strip_plus(std::string_view s) {
  if (s.size() > 1 && s[0] == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
  return s;
}

/// The whole field as a double; nan and inf are parsed (and rejected by the caller).
inline Parse parse_double(std::string_view s, double& v) {
  s = strip_plus(s);
  if (s.empty()) return Parse::Bad;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec == std::errc::result_out_of_range && ptr == s.data() + s.size()) return Parse::Range;
  if (ec != std::errc() || ptr != s.data() + s.size()) return Parse::Bad;
  return Parse::Ok;
}

/// The whole field as an integer.
inline Parse parse_int(std::string_view s, std::int64_t& v) {
  s = strip_plus(s);
  if (s.empty()) return Parse::Bad;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec == std::errc::result_out_of_range && ptr == s.data() + s.size()) return Parse::Range;
  if (ec != std::errc() || ptr != s.data() + s.size()) return Parse::Bad;
  return Parse::Ok;
}

inline std::string not_a_number(std::string_view field) { return "coordinate " + quoted(field) + " is not a number"; }

/// A coordinate: the field must be a finite number; `format_error()` is the message for a
/// field that is not a number at all (built only when needed).
template <class Message>
inline double coordinate(const std::string& path, std::size_t line, std::string_view field, Message&& format_error) {
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
inline std::int64_t integer(const std::string& path, std::size_t line, std::string_view field, const char* what) {
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

inline std::uint32_t load_u32_le(const char* p) {
  std::uint32_t v;
  std::memcpy(&v, p, 4);
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap32(v);
  return v;
}

inline double load_f64_le(const char* p) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap64(v);
  return std::bit_cast<double>(v);
}

/// A vertex field of a triangle file, renumbered from `first_index` to 0.
inline VertexId vertex(const std::string& path, std::size_t line, std::string_view field, int first_index) {
  const std::int64_t v = integer(path, line, field, "vertex index");
  // Both bounds are compared before anything is subtracted: v is any 64-bit value, and
  // v - first_index overflows near either end of that range. The largest index stays within
  // 64 bits: first_index is an int and the id limit is 2^32 - 1.
  const std::int64_t lowest = first_index;
  const std::int64_t highest = lowest + std::numeric_limits<VertexId>::max();
  if (v < lowest) {
    fail_line(path, line,
              "vertex index " + std::to_string(v) + " is below the first index " + std::to_string(first_index));
  }
  if (v > highest) {
    fail_line(path, line,
              "vertex index " + std::to_string(v) + " is too large (at most " + std::to_string(highest) + ")");
  }
  return static_cast<VertexId>(v - lowest);
}

// ---------------------------------------------------------------------------------------------
// Writing.

using io::Writer;

/// A drawing's map of the box [x0, x1] x [y0, y1] onto [0, side] along its longer side, y down.
/// The box is brought near 1 by exact powers of two before the one rounded multiplication, so
/// that every box of finite corners maps to finite numbers: one 1e-310 wide (whose side / width
/// overflows) as well as one wider than the largest double (whose width does).
class ViewMap {
 public:
  ViewMap(double x0, double y0, double x1, double y1, double side) : x0_(x0), y1_(y1) {
    // Halving is exact for the large coordinates that need it; differences of halves are finite.
    shift_ = std::max({std::fabs(x0), std::fabs(y0), std::fabs(x1), std::fabs(y1)}) > 0x1p1000 ? 1 : 0;
    const double w = dx(x1), h = dy(y0), longer = std::max(w, h);
    exponent_ = longer > 0 ? std::ilogb(longer) : 0;
    factor_ = side / std::ldexp(longer > 0 ? longer : 1, -exponent_);  // longer scaled into [1, 2)
    width = x(x1), height = y(y0);
  }
  double x(double c) const { return std::ldexp(dx(c), -exponent_) * factor_; }
  double y(double c) const { return std::ldexp(dy(c), -exponent_) * factor_; }
  double width = 0, height = 0;  ///< of the box, in the drawing's units

 private:
  double dx(double c) const { return std::ldexp(c, -shift_) - std::ldexp(x0_, -shift_); }
  double dy(double c) const { return std::ldexp(y1_, -shift_) - std::ldexp(c, -shift_); }
  double x0_, y1_;
  int shift_ = 0, exponent_ = 0;
  double factor_ = 1;
};

/// IoError unless every index of `ids` names one of `n` points.
inline void check_indices(const std::string& path, std::span<const VertexId> ids, std::size_t n, const char* what) {
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] >= n) {
      fail_file(path,
                std::string(what) + " refers to vertex " + std::to_string(ids[i]) + " but there are only " +
                    std::to_string(n) + " points");
    }
  }
}

/// A picture of nx by ny pixels (row 0 at the top) of `channels` bytes each, 4 (RGBA) or 2
/// (grey and alpha), encoded as PNG; IoError where the build has no libpng.
std::string png_bytes(const std::string& path, const unsigned char* pixels, std::size_t nx, std::size_t ny,
                      int channels);

// ---------------------------------------------------------------------------------------------
// The formats, each in its own file.

// Text (io_text.cpp): one point or triangle a line.
PointFile read_text_points(const std::string& path, std::string_view text, unsigned threads = 1);
std::vector<VertexId> read_text_triangles(const std::string& path, std::string_view text, int first_index,
                                          unsigned threads = 1);
void write_text_points(Writer& out, std::span<const Point> points, int first_index, unsigned threads = 1);
/// "x,y" a line (read back as text).
void write_csv_points(Writer& out, std::span<const Point> points, int first_index, unsigned threads = 1);

// Triangle's formats (io_triangle.cpp): .node, .ele, .neigh.
PointFile read_node(const std::string& path, std::string_view text, unsigned threads = 1);
std::vector<VertexId> read_ele(const std::string& path, std::string_view text, int first_index, unsigned threads);
/// The same; `attributes`, where not null, takes each triangle's first attribute (none where the
/// file has none); `middles`, where not null, lets a six-node file (-o2) be read: the corners
/// returned, the other three nodes of each triangle into it (none for a three-node file).
std::vector<VertexId> read_ele(const std::string& path, std::string_view text, int first_index, unsigned threads,
                               std::vector<double>* attributes, std::vector<VertexId>* middles = nullptr);
void write_node(Writer& out, std::span<const Point> points, int first_index, unsigned threads = 1);
/// Attributes to write beside points: `count` a point, row by row.
struct NodeAttributes {
  std::span<const double> values;
  std::size_t count = 0;
};
/// The same with a boundary marker column (`markers` one a point, or none) and attributes.
void write_node(Writer& out, std::span<const Point> points, int first_index, unsigned threads,
                std::span<const std::int64_t> markers, NodeAttributes attributes = {});
/// With `attributes` (one a triangle), Triangle's one attribute column (-A); `nodes` a triangle:
/// 3, or 6 (-o2: the corners, then the middles of the edges across from them). The lines are
/// formatted on `threads` threads.
void write_ele(Writer& out, std::span<const VertexId> triangles, int first_index,
               std::span<const double> attributes = {}, unsigned threads = 1, int nodes = 3);
void write_neigh(Writer& out, std::span<const std::int32_t> neighbors, int first_index, unsigned threads = 1);

// Raw little-endian binary (io_binary.cpp): float64 pairs, uint32 triples.
PointFile read_bin_points(const std::string& path, std::string_view data, unsigned threads = 1);
/// A regular .bin file mapped into memory and checked, or nothing where it cannot be mapped
/// (not a regular file, a big-endian machine): then read it. Throws IoError as the reader.
std::optional<PointFile> map_bin_points(const std::string& path);
std::vector<VertexId> read_bin_triangles(const std::string& path, std::string_view data);
void write_bin_points(Writer& out, std::span<const Point> points, int first_index, unsigned threads = 1);
void write_bin_triangles(Writer& out, std::span<const VertexId> triangles);
/// Triangles first, first + 1, ... of a .bin triangle file at their place in it.
void put_bin_sorted(Writer& out, std::size_t first, std::span<const VertexId> triangles);

// Surface meshes for viewers (io_mesh.cpp): .off (0-based), .obj (1-based), z = 0.
void write_off(Writer& out, std::span<const Point> points, std::span<const VertexId> triangles, std::size_t edges = 0);
void write_obj(Writer& out, std::span<const Point> points, std::span<const VertexId> triangles);

// A drawing (io_svg.cpp), of at most kSvgMaxTriangles triangles.
/// Segments (pairs of indices), where given, are drawn apart from the other edges.
void write_svg(const std::string& path, std::span<const Point> points, const Triangulation& t,
               std::span<const VertexId> segments = {});

// io_voronoi.cpp and io_values.cpp (their Out records: formats.hpp).
struct VoronoiOut;
struct ValuesOut;
void write_voronoi_json(Writer& out, const VoronoiOut& v);
void write_voronoi_off(Writer& out, const VoronoiOut& v);
void write_voronoi_svg(Writer& out, const VoronoiOut& v);
void write_values_csv(Writer& out, const ValuesOut& v);
void write_values_bin(Writer& out, const ValuesOut& v);
void write_values_png(Writer& out, const ValuesOut& v);

}  // namespace ridt::io::detail
