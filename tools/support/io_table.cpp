// Tables of points with heights (terrain_io.hpp): CSV and its relatives, with or without a
// header (the registry, formats.cpp, gives them every extension no other terrain format has).
#include "formats.hpp"
#include "io_common.hpp"
#include "terrain_io.hpp"

namespace ridt::io {
namespace {

using detail::fail_file;
using detail::fail_line;

// The fields of a line: apart by `delimiter`, or by white space where it is ' '; each trimmed,
// a name's surrounding double quotes removed.
void split(std::string_view line, char delimiter, std::vector<std::string_view>& out) {
  out.clear();
  if (delimiter == ' ') {
    detail::Fields f{line, false};
    for (std::string_view x; f.next(x);) out.push_back(x);
    return;
  }
  for (std::size_t at = 0;;) {
    const std::size_t end = std::min(line.find(delimiter, at), line.size());
    std::string_view x = detail::trim(line.substr(at, end - at));
    if (x.size() >= 2 && x.front() == '"' && x.back() == '"') x = x.substr(1, x.size() - 2);
    out.push_back(x);
    if (end == line.size()) return;
    at = end + 1;
  }
}

bool is_number(std::string_view s) {
  double v = 0;
  return detail::parse_double(s, v) == detail::Parse::Ok;
}

// The 0-based column that `spec` names among `names` (a name in any case, or a 1-based
// number), or, for an empty spec, the first of `known` found (else `fallback`).
std::size_t column(const std::string& path, const std::string& spec, const std::vector<std::string>& names,
                   std::initializer_list<const char*> known, std::size_t fallback, const char* axis) {
  if (!spec.empty()) {
    std::int64_t k = 0;
    if (detail::parse_int(spec, k) == detail::Parse::Ok) {
      if (k < 1 || static_cast<std::size_t>(k) > names.size())
        fail_file(path, std::string(axis) + " column " + spec + " is not one of the " + std::to_string(names.size()));
      return static_cast<std::size_t>(k - 1);
    }
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == detail::lower_case(spec)) return i;
  } else {
    for (const char* name : known)
      for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return i;
    if (fallback < names.size()) return fallback;
  }
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  fail_file(path,
            "no " + std::string(axis) + " column" + (spec.empty() ? "" : " '" + spec + "'") + " (the columns: " + list +
                "); name it, e.g. --columns x,y,z");
}

}  // namespace

namespace {

// The first line's fields that are coordinates: those --columns numbers, else the first three;
// none where --columns names a column (then the line must be a header that has the name).
std::vector<std::size_t> coordinate_fields(const Columns& columns, bool& named) {
  std::vector<std::size_t> at;
  named = false;
  std::size_t fallback = 0;
  for (const std::string* spec : {&columns.x, &columns.y, &columns.z}) {
    std::int64_t k = 0;
    if (spec->empty())
      at.push_back(fallback);
    else if (detail::parse_int(*spec, k) == detail::Parse::Ok && k >= 1)
      at.push_back(static_cast<std::size_t>(k - 1));
    else
      named = true;
    ++fallback;
  }
  return at;
}

// Whether the first line (its fields) is a header: where its coordinate fields are all not
// numbers, or --columns names a column. Where some are numbers and some not, it is neither.
bool is_header(const std::string& path, std::size_t line, std::string_view content,
               const std::vector<std::string_view>& fields, const Columns& columns) {
  bool named = false;
  std::size_t numbers = 0, texts = 0, text_at = 0;
  for (const std::size_t c : coordinate_fields(columns, named)) {
    if (c >= fields.size()) continue;
    if (is_number(fields[c]))
      ++numbers;
    else if (texts++ == 0)
      text_at = c;
  }
  if (named || numbers == 0) return true;
  if (texts == 0) return false;
  fail_line(
      path, line,
      "field " + std::to_string(text_at + 1) + " " + detail::quoted(fields[text_at]) +
          " is not a number, others are: neither a header (names) nor a row of numbers: " + detail::quoted(content));
}

}  // namespace

Terrain parse_table(std::string_view text, const std::string& name, const Columns& columns) {
  Terrain out;
  char delimiter = 0;
  std::size_t cx = 0, cy = 0, cz = 0, width = 0, first = 0;
  std::vector<std::string_view> fields;
  detail::for_each_line(text, [&](std::size_t line, std::string_view content) {
    if (delimiter == 0) {  // the first line: the delimiter, and a header or not
      delimiter = content.find(',') != content.npos ? ','
          : content.find(';') != content.npos       ? ';'
          : content.find('\t') != content.npos      ? '\t'
                                                    : ' ';
      split(content, delimiter, fields);
      width = fields.size(), first = line;
      const bool header = is_header(name, line, content, fields, columns);
      std::vector<std::string> names;
      for (std::size_t i = 0; i < width; ++i)
        names.push_back(header ? detail::lower_case(fields[i]) : std::to_string(i + 1));
      cx = column(name, columns.x, names, {"x", "easting", "east", "lon", "long", "longitude"}, 0, "x");
      cy = column(name, columns.y, names, {"y", "northing", "north", "lat", "latitude"}, 1, "y");
      cz = column(name, columns.z, names, {"z", "elevation", "elev", "height", "h", "alt", "altitude"}, 2, "z");
      if (header) return;
    } else {
      split(content, delimiter, fields);
    }
    if (fields.size() != width)  // a ragged table is a broken one: its columns cannot be trusted
      fail_line(name, line,
                "expected " + std::to_string(width) + " fields, as line " + std::to_string(first) + " has, got " +
                    std::to_string(fields.size()) + ": " + detail::quoted(content));
    const auto value = [&](std::size_t c) {
      return detail::coordinate(name, line, fields[c], [&] {
        return "field " + std::to_string(c + 1) + " " + detail::quoted(fields[c]) + " is not a number";
      });
    };
    out.points.push_back({value(cx), value(cy)});
    out.z.push_back(value(cz));
  });
  return out;
}

Terrain detail::read_table(const std::string& path, const PointFilter& /*filter*/, const Columns& columns) {
  return parse_table(detail::read_file_whole(path), path, columns);
}

}  // namespace ridt::io
