// ASPRS LAS 1.0 to 1.4 (terrain_io.hpp): the public header block, the variable-length records
// (VLR, and the 1.4 extended ones) for the CRS, and the point records of formats 0 to 10, read
// in place from a mapping of the file. Every offset is checked against the file's size before it
// is read, so a truncated or inconsistent file is an IoError that says what is wrong.
#include "formats.hpp"
#include "io_common.hpp"
#include "terrain_io.hpp"

namespace ridt::io {
namespace {

using detail::fail_file;

template <class T>
T load(std::string_view d, std::size_t at) {
  T v;
  std::memcpy(&v, d.data() + at, sizeof v);  // LAS is little-endian, as the machines ridt builds for
  return v;
}

// The shortest record of each point format (extra bytes may follow, as the header's length says).
constexpr std::size_t kRecordLength[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
// The header's size in each minor version of 1.x.
constexpr std::size_t kHeaderSize[] = {227, 227, 227, 235, 375};

std::string cut(std::string_view d, std::size_t at, std::size_t n) {
  std::string s(d.substr(at, n));
  s.resize(std::strlen(s.c_str()));  // NUL-padded
  return s;
}

// The EPSG code of GeoTIFF's key directory (LAS's record 34735): the projected system's (key
// 3072), else the geographic one's (2048); empty when neither is an EPSG code.
std::string epsg_of_keys(std::string_view rec) {
  if (rec.size() < 8) return {};
  const std::size_t keys = load<std::uint16_t>(rec, 6);
  std::uint16_t projected = 0, geographic = 0;
  for (std::size_t k = 0; k < keys && 8 + 8 * k + 8 <= rec.size(); ++k) {
    const std::size_t at = 8 + 8 * k;
    const auto id = load<std::uint16_t>(rec, at), where = load<std::uint16_t>(rec, at + 2),
               value = load<std::uint16_t>(rec, at + 6);
    if (where != 0 || value == 0 || value == 32767) continue;  // elsewhere, undefined, user-defined
    if (id == 3072) projected = value;
    if (id == 2048) geographic = value;
  }
  const std::uint16_t code = projected != 0 ? projected : geographic;
  return code != 0 ? "EPSG:" + std::to_string(code) : std::string();
}

// The CRS of the records from `at` on: `count` of them, each a header of `head` bytes (54 for
// a VLR, 60 for an EVLR) whose length field is `wide` (64-bit) or not, ending by `end`.
std::string crs_of_records(std::string_view d, const std::string& name, std::size_t at, std::uint64_t count,
                           std::size_t end, bool extended) {
  const std::size_t head = extended ? 60 : 54;
  std::string wkt, keys;
  for (std::uint64_t k = 0; k < count; ++k) {
    if (at > end || end - at < head)
      fail_file(name,
                std::string(extended ? "extended " : "") + "variable-length record " + std::to_string(k) +
                    " runs past " + (extended ? "the end of the file" : "the start of the point data"));
    const std::string user = cut(d, at + 2, 16);
    const auto id = load<std::uint16_t>(d, at + 18);
    const std::uint64_t length = extended ? load<std::uint64_t>(d, at + 20) : load<std::uint16_t>(d, at + 20);
    at += head;
    if (length > end - at)
      fail_file(name,
                "variable-length record " + std::to_string(k) + " (" + user + " " + std::to_string(id) + ") says " +
                    std::to_string(length) + " bytes, more than the file holds");
    if (user == "LASF_Projection" && id == 2112) wkt = cut(d, at, static_cast<std::size_t>(length));
    if (user == "LASF_Projection" && id == 34735) keys = epsg_of_keys(d.substr(at, static_cast<std::size_t>(length)));
    at += static_cast<std::size_t>(length);
  }
  return !wkt.empty() ? wkt : keys;
}

// Whether a record's return and class pass the filter.
struct Keep {
  const PointFilter& filter;
  bool wide;  // formats 6 to 10
  bool classes[256] = {};

  Keep(const PointFilter& f, bool formats_6_to_10) : filter(f), wide(formats_6_to_10) {
    for (const int c : f.classes)
      if (c >= 0 && c < 256) classes[c] = true;
  }

  bool operator()(const char* r) const {
    const auto b14 = static_cast<unsigned char>(r[14]), b15 = static_cast<unsigned char>(r[15]);
    const unsigned ret = wide ? b14 & 15u : b14 & 7u, of = wide ? b14 >> 4 : (b14 >> 3) & 7u;
    const unsigned cls = wide ? static_cast<unsigned char>(r[16]) : b15 & 31u;
    const bool withheld = wide ? (b15 & 4u) != 0 : (b15 & 128u) != 0;
    if (withheld && !filter.withheld) return false;
    if (!filter.classes.empty() && !classes[cls]) return false;
    switch (filter.returns) {
      case Returns::First:
        return ret <= 1;
      case Returns::Last:
        return ret >= of;
      case Returns::Single:
        return of <= 1;
      default:
        return true;
    }
  }
};

// The CRS of LAS 1.4's extended records, which follow the points.
std::string crs_of_extended(std::string_view d, const std::string& name, const LasHeader& h) {
  const auto at = load<std::uint64_t>(d, 235);
  const auto count = load<std::uint32_t>(d, 243);
  if (count == 0) return {};
  if (at < h.data_offset + h.count * h.record_length || at > d.size())
    fail_file(name, "the extended records' offset " + std::to_string(at) + " lies outside the file");
  return crs_of_records(d, name, static_cast<std::size_t>(at), count, d.size(), true);
}

}  // namespace

LasHeader parse_las_header(std::string_view d, const std::string& name) {
  if (d.size() < 4 || d.substr(0, 4) != "LASF") fail_file(name, "not a LAS file (no \"LASF\" signature)");
  if (d.size() < 227)
    fail_file(name, "truncated: " + std::to_string(d.size()) + " bytes, less than a LAS header's 227");
  LasHeader h;
  h.major = static_cast<unsigned char>(d[24]);
  h.minor = static_cast<unsigned char>(d[25]);
  if (h.major != 1 || h.minor > 4)
    fail_file(
        name,
        "LAS version " + std::to_string(h.major) + "." + std::to_string(h.minor) + " is not read (1.0 to 1.4 are)");
  const std::size_t header_size = load<std::uint16_t>(d, 94);
  h.data_offset = load<std::uint32_t>(d, 96);
  const std::uint32_t vlrs = load<std::uint32_t>(d, 100);
  const auto format_byte = static_cast<unsigned char>(d[104]);
  if (format_byte >= 64)
    fail_file(name,
              "compressed (LAZ) points are not read; decompress the file first, e.g. "
              "\"laszip -i IN.laz -o OUT.las\" or \"pdal translate IN.laz OUT.las\"");
  h.format = format_byte;
  if (h.format > 10) fail_file(name, "point format " + std::to_string(h.format) + " is not one of LAS's 0 to 10");
  h.record_length = load<std::uint16_t>(d, 105);
  if (h.record_length < kRecordLength[h.format])
    fail_file(name,
              "point records of " + std::to_string(h.record_length) + " bytes, less than format " +
                  std::to_string(h.format) + "'s " + std::to_string(kRecordLength[h.format]));
  if (header_size < kHeaderSize[h.minor] || header_size > d.size())
    fail_file(name,
              "a header of " + std::to_string(header_size) + " bytes (LAS 1." + std::to_string(h.minor) +
                  "'s is at least " + std::to_string(kHeaderSize[h.minor]) + ", the file " + std::to_string(d.size()) +
                  ")");
  if (h.data_offset < header_size || h.data_offset > d.size())
    fail_file(name, "the point data's offset " + std::to_string(h.data_offset) + " lies outside the file");
  h.count = load<std::uint32_t>(d, 107);
  if (h.minor >= 4 && load<std::uint64_t>(d, 247) != 0) h.count = load<std::uint64_t>(d, 247);  // 1.4's own count
  for (int k = 0; k < 3; ++k) {
    h.scale[k] = load<double>(d, 131 + 8 * k);
    h.offset[k] = load<double>(d, 155 + 8 * k);
    // Any 32-bit integer times the scale plus the offset must be a finite double.
    if (h.scale[k] == 0 || !std::isfinite(std::abs(h.scale[k]) * 2147483648.0 + std::abs(h.offset[k])))
      fail_file(name, std::string("the ") + "xyz"[k] + " scale factor is zero, or it and the offset overflow");
  }
  const std::uint64_t room = (d.size() - h.data_offset) / h.record_length;
  if (h.count > room)
    fail_file(name,
              "truncated: the header says " + std::to_string(h.count) + " points of " +
                  std::to_string(h.record_length) + " bytes from byte " + std::to_string(h.data_offset) +
                  ", the file holds " + std::to_string(room));
  h.crs = crs_of_records(d, name, header_size, vlrs, h.data_offset, false);
  if (h.minor >= 4) {
    const std::string crs = crs_of_extended(d, name, h);
    if (!crs.empty()) h.crs = crs;
  }
  return h;
}

Terrain parse_las(std::string_view d, const std::string& name, const PointFilter& filter) {
  const LasHeader h = parse_las_header(d, name);
  Terrain out;
  out.crs = h.crs;
  out.points.reserve(h.count);
  out.z.reserve(h.count);
  const Keep keep(filter, h.format >= 6);
  const char* r = d.data() + h.data_offset;
  for (std::uint64_t k = 0; k < h.count; ++k, r += h.record_length) {
    if (!keep(r)) continue;
    std::int32_t xyz[3];
    std::memcpy(xyz, r, sizeof xyz);
    out.points.push_back({xyz[0] * h.scale[0] + h.offset[0], xyz[1] * h.scale[1] + h.offset[1]});
    out.z.push_back(xyz[2] * h.scale[2] + h.offset[2]);
  }
  return out;
}

Terrain read_las(const std::string& path, const PointFilter& filter) {
  return detail::FileText(path).parse([&](std::string_view text) { return parse_las(text, path, filter); });
}

Terrain detail::read_las_terrain(const std::string& path, const PointFilter& filter, const Columns& /*columns*/) {
  return read_las(path, filter);
}

Terrain detail::read_laz(const std::string& path, const PointFilter& /*filter*/, const Columns& /*columns*/) {
  fail_file(path,
            "compressed LAS (LAZ) is not read; decompress it first, e.g. \"laszip -i " + path +
                " -o OUT.las\" or \"pdal translate " + path + " OUT.las\"");
}

}  // namespace ridt::io
