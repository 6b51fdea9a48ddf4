// GDAL's formats (the registry's rows with a driver), and the loading of the module that writes and reads them
// (tools/gdal/module.cpp, libridt_gdal.so; terrain_io.hpp's GdalModule). The module is looked
// for where RIDT_GDAL_MODULE (the environment) says, beside the build's own copy, then where an
// installed tool keeps it (../lib/ridt/ from the executable).
#include <dlfcn.h>

#include <mutex>

#include "formats.hpp"
#include "io_common.hpp"
#include "temporaries.hpp"
#include "terrain_io.hpp"

namespace ridt::io {
namespace {

using detail::fail_file;

// GDAL's name of the format of `path` (the registry's, formats.cpp), for `role`.
template <class Fn>
std::string driver_of(const std::string& path, const detail::RoleName<Fn>& role) {
  const std::string_view driver = detail::format_of(path, role).gdal_driver;
  if (driver.empty()) fail_file(path, "not a format ridt reads or writes through GDAL");
  return std::string(driver);
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
    if (auto entry = reinterpret_cast<Entry>(::dlsym(handle, "ridt_gdal_module_3"))) {
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

Terrain detail::read_ogr(const std::string& path, const Columns& columns) {
  return gdal_module(path).read_ogr(path, columns);
}

void detail::write_tin_ogr(const std::string& path, const Terrain& terrain, const Triangulation& t) {
  gdal_module(path).write_tin(path, driver_of(path, detail::kTinOut).c_str(), terrain, t);
}

void detail::write_dem_gdal(const std::string& path, const Dem& dem, const DemFile& file) {
  const std::string driver = driver_of(path, detail::kDemOut);
  gdal_module(path).write_dem(path, driver.c_str(), dem.grid(), dem.options().nodata, file, dem.band_rows(),
                              [&](std::size_t b, std::span<double> out) { dem.band(b, out); });
}

}  // namespace ridt::io
