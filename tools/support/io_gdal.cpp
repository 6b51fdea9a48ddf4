// GDAL's formats by extension, and the loading of the module that writes and reads them
// (tools/gdal/module.cpp, libridt_gdal.so; terrain_io.hpp's GdalModule). The module is looked
// for where RIDT_GDAL_MODULE (the environment) says, beside the build's own copy, then where an
// installed tool keeps it (../lib/ridt/ from the executable).
#include <dlfcn.h>

#include <mutex>

#include "io_common.hpp"
#include "temporaries.hpp"
#include "terrain_io.hpp"

namespace ridt::io {
namespace {

using detail::fail_file;

struct Driver {
  const char* extension;
  const char* name;
};
// The formats GIS people exchange points and TINs in, and DEMs.
constexpr Driver kVectorDrivers[] = {
    {".gpkg", "GPKG"},    {".shp", "ESRI Shapefile"}, {".geojson", "GeoJSON"},
    {".json", "GeoJSON"}, {".fgb", "FlatGeobuf"},     {".gml", "GML"},
    {".kml", "KML"},      {".sqlite", "SQLite"},
};
constexpr Driver kRasterDrivers[] = {{".tif", "GTiff"}, {".tiff", "GTiff"}, {".img", "HFA"}};

template <std::size_t N>
const char* driver_of(const std::string& path, const Driver (&drivers)[N]) {
  const std::string ext = detail::extension_of(path);
  for (const Driver& d : drivers)
    if (ext == d.extension) return d.name;
  return nullptr;
}

// The module, or why there is none.
struct Loaded {
  const detail::GdalModule* module = nullptr;
  std::string why;
};

Loaded load() {
#ifndef RIDT_GDAL_MODULE
  return {nullptr, "this build has no GDAL (apt-get install libgdal-dev, then build again)"};
#else
  std::vector<std::string> places;
  if (const char* env = std::getenv("RIDT_GDAL_MODULE")) places.emplace_back(env);
  places.emplace_back(RIDT_GDAL_MODULE);
  std::error_code ec;
  const detail::fs::path exe = detail::fs::read_symlink("/proc/self/exe", ec);
  if (!ec) places.push_back((exe.parent_path() / ".." / RIDT_GDAL_MODULE_INSTALLED).string());
  std::string why;
  for (const std::string& place : places) {
    if (!detail::fs::exists(place, ec)) continue;
    void* handle = ::dlopen(place.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      why = ::dlerror();
      continue;
    }
    using Entry = const detail::GdalModule* (*)();
    if (auto entry = reinterpret_cast<Entry>(::dlsym(handle, "ridt_gdal_module_2"))) {
      const detail::GdalModule* module = entry();
      also_remove_temporaries(module->remove_temporaries);  // its files too, on a signal
      return {module, ""};
    }
    why = place + " is not this version's GDAL module of ridt";
  }
  return {nullptr, why.empty() ? "ridt's GDAL module (libridt_gdal.so) is not installed" : why};
#endif
}

}  // namespace

const detail::GdalModule& detail::gdal_module(const std::string& path) {
  static const Loaded loaded = load();
  if (loaded.module == nullptr) fail_file(path, loaded.why);
  return *loaded.module;
}

bool have_gdal() {
#ifdef RIDT_GDAL_MODULE
  return true;
#else
  return false;
#endif
}

bool detail::is_gdal_vector(const std::string& path) { return driver_of(path, kVectorDrivers) != nullptr; }

Terrain detail::read_ogr(const std::string& path, const Columns& columns) {
  return gdal_module(path).read_ogr(path, columns);
}

void detail::write_tin_ogr(const std::string& path, const Terrain& terrain, const Triangulation& t) {
  gdal_module(path).write_tin(path, driver_of(path, kVectorDrivers), terrain, t);
}

void detail::write_dem_gdal(const std::string& path, const Dem& dem, const DemFile& file) {
  const char* driver = driver_of(path, kRasterDrivers);
  if (driver == nullptr)
    fail_file(path,
              "unknown DEM extension '" + detail::fs::path(path).extension().string() +
                  "' (use .tif, .img, or .png for a hillshade)");
  gdal_module(path).write_dem(path, driver, dem.grid(), dem.options().nodata, file, dem.band_rows(),
                              [&](std::size_t b, std::span<double> out) { dem.band(b, out); });
}

}  // namespace ridt::io
