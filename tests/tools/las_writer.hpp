// LAS files written by the tests themselves, byte by byte after the ASPRS specifications of
// LAS 1.0 to 1.4: any version, any point format 0 to 10, the CRS as an OGC WKT record or
// GeoTIFF keys, in a VLR or (1.4) an EVLR, extra bytes after each record.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace ridt::test {

struct LasPoint {
  double x = 0, y = 0, z = 0;
  int cls = 1, ret = 1, of = 1;
  bool withheld = false;
};

struct LasSpec {
  int minor = 2, format = 0;
  double scale[3] = {0.01, 0.01, 0.01}, offset[3] = {0, 0, 0};
  std::string wkt;  ///< an OGC WKT record (2112)
  int epsg = 0;  ///< GeoTIFF keys (34735) with this projected system
  bool evlr = false;  ///< the CRS record as a 1.4 extended record after the points
  std::size_t extra = 0;  ///< bytes after each record
};

inline constexpr std::size_t kLasRecord[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
inline constexpr std::size_t kLasHeader[] = {227, 227, 227, 235, 375};

template <class T>
void put_at(std::string& s, std::size_t at, T v) {
  std::memcpy(s.data() + at, &v, sizeof v);
}

// A record (VLR, or EVLR when `extended`) of user "LASF_Projection".
inline std::string las_record(std::uint16_t id, const std::string& body, bool extended) {
  std::string r(extended ? 60 : 54, '\0');
  std::memcpy(r.data() + 2, "LASF_Projection", 15);
  put_at<std::uint16_t>(r, 18, id);
  if (extended)
    put_at<std::uint64_t>(r, 20, body.size());
  else
    put_at<std::uint16_t>(r, 20, static_cast<std::uint16_t>(body.size()));
  return r + body;
}

inline std::string las_crs_records(const LasSpec& s, bool extended) {
  std::string out;
  if (!s.wkt.empty()) out += las_record(2112, s.wkt + '\0', extended);
  if (s.epsg != 0) {
    std::string keys(16, '\0');  // version 1.1.0, one key: ProjectedCSTypeGeoKey = epsg
    const std::uint16_t k[8] = {1, 1, 0, 1, 3072, 0, 1, static_cast<std::uint16_t>(s.epsg)};
    std::memcpy(keys.data(), k, 16);
    out += las_record(34735, keys, extended);
  }
  return out;
}

inline std::string las_file(const LasSpec& s, const std::vector<LasPoint>& points) {
  const std::size_t header = kLasHeader[s.minor], record = kLasRecord[s.format] + s.extra;
  const bool ext = s.evlr && s.minor >= 4;
  const std::string vlrs = ext ? std::string() : las_crs_records(s, false);
  std::string f(header, '\0');
  std::memcpy(f.data(), "LASF", 4);
  f[24] = 1, f[25] = static_cast<char>(s.minor);
  std::memcpy(f.data() + 26, "ridt tests", 10);
  put_at<std::uint16_t>(f, 94, static_cast<std::uint16_t>(header));
  put_at<std::uint32_t>(f, 96, static_cast<std::uint32_t>(header + vlrs.size()));
  put_at<std::uint32_t>(f, 100, (s.wkt.empty() ? 0u : 1u) + (s.epsg == 0 ? 0u : 1u));
  if (ext) put_at<std::uint32_t>(f, 100, 0);
  f[104] = static_cast<char>(s.format);
  put_at<std::uint16_t>(f, 105, static_cast<std::uint16_t>(record));
  // 1.4 with formats 6 to 10: the legacy count is 0 and only the 64-bit one counts.
  put_at<std::uint32_t>(f, 107, s.minor >= 4 && s.format >= 6 ? 0u : static_cast<std::uint32_t>(points.size()));
  for (int k = 0; k < 3; ++k) put_at<double>(f, 131 + 8 * k, s.scale[k]), put_at<double>(f, 155 + 8 * k, s.offset[k]);
  if (s.minor >= 4) put_at<std::uint64_t>(f, 247, points.size());
  f += vlrs;
  for (const LasPoint& p : points) {
    std::string r(record, '\0');
    const double v[3] = {p.x, p.y, p.z};
    for (int k = 0; k < 3; ++k)
      put_at<std::int32_t>(r, 4 * k, static_cast<std::int32_t>(std::lround((v[k] - s.offset[k]) / s.scale[k])));
    if (s.format >= 6) {
      r[14] = static_cast<char>(p.ret | (p.of << 4));
      r[15] = static_cast<char>(p.withheld ? 4 : 0);
      r[16] = static_cast<char>(p.cls);
    } else {
      r[14] = static_cast<char>(p.ret | (p.of << 3));
      r[15] = static_cast<char>(p.cls | (p.withheld ? 128 : 0));
    }
    f += r;
  }
  if (ext) {
    const std::string evlrs = las_crs_records(s, true);
    put_at<std::uint64_t>(f, 235, f.size());
    put_at<std::uint32_t>(f, 243, (s.wkt.empty() ? 0u : 1u) + (s.epsg == 0 ? 0u : 1u));
    f += evlrs;
  }
  return f;
}

}  // namespace ridt::test
