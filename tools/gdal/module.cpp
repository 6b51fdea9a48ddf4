// libridt_gdal.so: GDAL's formats for the terrain commands (terrain_io.hpp's GdalModule),
// loaded by tools/support/io_gdal.cpp on first use. Point layers in through OGR, a TIN out as a
// layer of PolygonZ triangles, a DEM out band by band through a raster driver. Each output is
// written under a temporary name beside the target (with its side files, as a Shapefile has) and
// renamed when GDAL has closed it without error, so a failure leaves nothing; a device or a pipe
// gets the finished file's bytes.
#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <mutex>

#include "io_common.hpp"
#include "temporaries.hpp"
#include "terrain_io.hpp"

namespace ridt::io {

namespace {

using detail::fail_file;

void register_gdal() {
  static std::once_flag once;
  std::call_once(once, [] {
    GDALAllRegister();
    CPLSetErrorHandler(CPLQuietErrorHandler);  // errors come back as IoError, not on stderr
  });
}

std::string gdal_error() {
  const char* m = CPLGetLastErrorMsg();
  return m != nullptr && *m != '\0' ? m : "GDAL gave no reason";
}

struct Close {
  void operator()(GDALDataset* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, Close>;

// Copies the file `from` into `to`, which is not a regular file (a device, a pipe), in order.
void copy_in_place(const std::string& from, const std::string& to, const std::string& path) {
  const std::string bytes = detail::read_file_whole(from);
  const int fd = ::open(to.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) throw IoError("cannot write " + path + ": " + detail::errno_text(errno));
  for (std::size_t at = 0; at < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + at, bytes.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : ENOSPC;
      ::close(fd);
      throw IoError("cannot write " + path + ": " + detail::errno_text(err));
    }
    at += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) throw IoError("cannot write " + path + ": " + detail::errno_text(errno));
}

// The files of one output: written under `temp` (the target's stem + ".tmp-PID-N" + its
// extension, so the driver sees the extension), renamed onto the target's stem by commit(), all
// removed otherwise: a Shapefile's .shx, .dbf and .prj go with its .shp. The target is the
// path's with symbolic links followed (output_target); one that is not a regular file (a device,
// a pipe) is made in the temporary directory and copied into it, if it is one file.
class Output {
 public:
  explicit Output(const std::string& path) : path_(path), target_(output_target(path)) {
    static std::atomic<unsigned> counter{0};
    const detail::fs::path p(target_.path);
    dir_ = target_.in_place       ? detail::fs::temp_directory_path()
        : p.parent_path().empty() ? detail::fs::path(".")
                                  : p.parent_path();
    stem_ = p.stem().string();
    temp_stem_ = stem_ + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
    temp_ = (dir_ / (temp_stem_ + detail::fs::path(path).extension().string())).string();
    // For a signal that ends the tool (temporaries.hpp): the file, the side files GDAL's drivers
    // write beside it (a Shapefile's, a GeoPackage's journals, GML's schema, an .aux.xml, HFA's
    // .ige, FlatGeobuf's unsorted features), named before any exists.
    for (const char* side : {"", "-journal", "-wal", "-shm", ".aux.xml"}) names_.emplace_back(temp_ + side);
    for (const char* ext : {".shx", ".dbf", ".prj", ".cpg", ".xsd", ".ige", "_temp.fgb"})
      names_.emplace_back((dir_ / (temp_stem_ + ext)).string());
  }
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;
  ~Output() {
    if (!committed_ || target_.in_place)
      for (const auto& f : mine()) std::remove(f.c_str());
    names_.clear();
  }

  const std::string& temp() const { return temp_; }

  void commit() {
    const std::vector<std::string> files = mine();
    if (target_.in_place) {
      if (files.size() != 1)
        throw IoError("cannot write " + path_ + ": the format makes " + std::to_string(files.size()) + " files, and " +
                      path_ + " is not a regular file");
      copy_in_place(files[0], target_.path, path_);
      committed_ = true;  // the destructor removes the file made in the temporary directory
      return;
    }
    for (const auto& f : files) {
      const std::string name = detail::fs::path(f).filename().string();
      // The file itself keeps the target's name (a link's target may have another extension).
      const std::string target = f == temp_ ? target_.path : (dir_ / (stem_ + name.substr(temp_stem_.size()))).string();
      if (std::rename(f.c_str(), target.c_str()) != 0)
        throw IoError("cannot write " + target + ": " + detail::errno_text(errno));
    }
    committed_ = true;
    names_.clear();
  }

 private:
  std::vector<std::string> mine() const {
    std::vector<std::string> files;
    std::error_code ec;
    for (const auto& e : detail::fs::directory_iterator(dir_, ec))
      if (e.path().filename().string().starts_with(temp_stem_ + ".")) files.push_back(e.path().string());
    return files;
  }

  std::string path_;
  OutputTarget target_;
  std::string stem_, temp_stem_, temp_;
  detail::fs::path dir_;
  std::vector<TemporaryName> names_;
  bool committed_ = false;
};

// The CRS of `text` (WKT, "EPSG:n", PROJ), with x east and y north whatever the authority says.
std::unique_ptr<OGRSpatialReference> spatial_reference(const std::string& path, const std::string& text) {
  if (text.empty()) return nullptr;
  auto srs = std::make_unique<OGRSpatialReference>();
  srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  if (srs->SetFromUserInput(text.c_str()) != OGRERR_NONE)
    fail_file(path, "the coordinate reference system is not understood: " + detail::quoted(text));
  return srs;
}

void add_point(const std::string& path, Terrain& out, const OGRPoint& p, const OGRFeature& f, int z_field) {
  if (z_field < 0 && !p.Is3D())
    fail_file(path,
              "point " + std::to_string(f.GetFID()) + " has no z; name the field of the heights (--columns x,y,NAME)");
  const double x = p.getX(), y = p.getY(), z = z_field >= 0 ? f.GetFieldAsDouble(z_field) : p.getZ();
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
    fail_file(path, "point " + std::to_string(f.GetFID()) + " has a coordinate that is not finite");
  out.points.push_back({x, y});
  out.z.push_back(z);
}

Terrain points_in(const std::string& path, const Columns& columns) {
  register_gdal();
  const Dataset ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  if (!ds) fail_file(path, "cannot open: " + gdal_error());
  if (ds->GetLayerCount() < 1) fail_file(path, "no layer");
  OGRLayer* layer = ds->GetLayer(0);
  const int z_field = columns.z.empty() ? -1 : layer->GetLayerDefn()->GetFieldIndex(columns.z.c_str());
  if (!columns.z.empty() && z_field < 0) fail_file(path, "no field '" + columns.z + "' in layer " + layer->GetName());
  Terrain out;
  if (const OGRSpatialReference* srs = layer->GetSpatialRef()) {
    char* wkt = nullptr;
    if (srs->exportToWkt(&wkt) == OGRERR_NONE && wkt != nullptr) out.crs = wkt;
    CPLFree(wkt);
  }
  for (const auto& feature : *layer) {
    const OGRGeometry* g = feature->GetGeometryRef();
    if (g == nullptr) continue;
    const OGRwkbGeometryType type = wkbFlatten(g->getGeometryType());
    if (type == wkbPoint) {
      add_point(path, out, *g->toPoint(), *feature, z_field);
    } else if (type == wkbMultiPoint) {
      for (const OGRPoint* p : *g->toMultiPoint()) add_point(path, out, *p, *feature, z_field);
    } else {
      fail_file(path,
                std::string("layer ") + layer->GetName() + " holds " + OGRGeometryTypeToName(type) +
                    " geometries; ridt reads points");
    }
  }
  return out;
}

void tin_out(const std::string& path, const char* name, const Terrain& terrain, const Triangulation& t) {
  register_gdal();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(name);
  if (driver == nullptr) fail_file(path, std::string("this GDAL has no ") + name + " driver");
  const auto srs = spatial_reference(path, terrain.crs);
  Output file(path);
  {
    const Dataset ds(driver->Create(file.temp().c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    if (!ds) fail_file(path, "cannot create: " + gdal_error());
    OGRLayer* layer = ds->CreateLayer("tin", srs.get(), wkbPolygon25D, nullptr);
    if (layer == nullptr) fail_file(path, "cannot create the layer: " + gdal_error());
    const bool batches = ds->TestCapability(ODsCTransactions) != 0;
    OGRFeature feature(layer->GetLayerDefn());
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (batches && k % 65536 == 0 && ds->StartTransaction() != OGRERR_NONE) fail_file(path, gdal_error());
      OGRLinearRing ring;
      for (int i = 0; i <= 3; ++i) {
        const VertexId v = t.triangles[3 * k + i % 3];
        ring.addPoint(terrain.points[v].x, terrain.points[v].y, terrain.z[v]);
      }
      OGRPolygon triangle;
      triangle.addRing(&ring);
      feature.SetGeometry(&triangle);
      feature.SetFID(OGRNullFID);
      if (layer->CreateFeature(&feature) != OGRERR_NONE)
        fail_file(path, "cannot write triangle " + std::to_string(k) + ": " + gdal_error());
      if (batches && (k % 65536 == 65535 || k + 1 == t.size()) && ds->CommitTransaction() != OGRERR_NONE)
        fail_file(path, gdal_error());
    }
    CPLErrorReset();
  }  // closed: written out
  if (CPLGetLastErrorType() >= CE_Failure) fail_file(path, gdal_error());
  file.commit();
}

void dem_out(const std::string& path, const char* name, const RasterGrid& g, double nodata, const DemFile& how,
             std::size_t band_rows, const std::function<void(std::size_t, std::span<double>)>& fill) {
  register_gdal();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(name);
  if (driver == nullptr) fail_file(path, std::string("this GDAL has no ") + name + " driver");
  if (g.nx > 0x7fffffff || g.ny > 0x7fffffff) fail_file(path, "a raster of more than 2^31 cells a side");
  const auto srs = spatial_reference(path, how.crs);
  char** options = nullptr;
  if (std::string(name) == "GTiff") {
    options = CSLSetNameValue(options, "TILED", "YES");
    options = CSLSetNameValue(options, "COMPRESS", "DEFLATE");
    options = CSLSetNameValue(options, "PREDICTOR", "3");  // floating-point differences: smaller files
    options = CSLSetNameValue(options, "BIGTIFF", "IF_SAFER");
  }
  Output file(path);
  {
    const Dataset ds(driver->Create(file.temp().c_str(), static_cast<int>(g.nx), static_cast<int>(g.ny), 1,
                                    how.float32 ? GDT_Float32 : GDT_Float64, options));
    CSLDestroy(options);
    if (!ds) fail_file(path, "cannot create: " + gdal_error());
    double transform[6] = {g.x0, g.cell, 0, g.y1, 0, -g.cell};
    ds->SetGeoTransform(transform);
    if (srs) ds->SetSpatialRef(srs.get());
    GDALRasterBand* band = ds->GetRasterBand(1);
    band->SetNoDataValue(nodata);
    std::vector<double> rows;
    const std::size_t bands = (g.ny + band_rows - 1) / band_rows;
    for (std::size_t b = 0; b < bands; ++b) {
      const std::size_t r0 = b * band_rows, h = std::min(g.ny - r0, band_rows);
      rows.resize(h * g.nx);
      fill(b, rows);
      if (band->RasterIO(GF_Write, 0, static_cast<int>(r0), static_cast<int>(g.nx), static_cast<int>(h), rows.data(),
                         static_cast<int>(g.nx), static_cast<int>(h), GDT_Float64, 0, 0, nullptr) != CE_None)
        fail_file(path, "cannot write rows " + std::to_string(r0) + ": " + gdal_error());
      if (how.progress) how.progress(static_cast<double>(b + 1) / static_cast<double>(bands));
    }
    CPLErrorReset();
  }
  if (CPLGetLastErrorType() >= CE_Failure) fail_file(path, gdal_error());
  file.commit();
}

// A north-up raster's first band, its cells' centres from the geotransform.
void raster_in(const std::string& path, detail::RasterIn& out) {
  register_gdal();
  const Dataset ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!ds) fail_file(path, "cannot open as a raster: " + gdal_error());
  if (ds->GetRasterCount() < 1) fail_file(path, "has no band");
  double t[6] = {0, 1, 0, 0, 0, 1};
  if (ds->GetGeoTransform(t) != CE_None) fail_file(path, "has no geotransform: where its cells lie is not known");
  if (t[2] != 0 || t[4] != 0) fail_file(path, "is rotated or sheared: ridt reads north-up rasters");
  const auto nx = static_cast<std::size_t>(ds->GetRasterXSize()), ny = static_cast<std::size_t>(ds->GetRasterYSize());
  out.values.resize(nx * ny);
  GDALRasterBand* band = ds->GetRasterBand(1);
  if (band->RasterIO(GF_Read, 0, 0, static_cast<int>(nx), static_cast<int>(ny), out.values.data(), static_cast<int>(nx),
                     static_cast<int>(ny), GDT_Float64, 0, 0, nullptr) != CE_None)
    fail_file(path, "cannot read its band: " + gdal_error());
  int has = 0;
  const double nodata = band->GetNoDataValue(&has);
  if (has != 0)
    for (std::size_t k = 0; k < out.values.size(); ++k)
      if (out.values[k] == nodata || (std::isnan(nodata) && std::isnan(out.values[k])))
        fail_file(path,
                  "has no value (nodata) at column " + std::to_string(k % nx) + ", row " + std::to_string(k / nx) +
                      ": a size is needed everywhere");
  out.nx = nx, out.ny = ny;
  out.x0 = t[0] + 0.5 * t[1], out.x1 = t[0] + (static_cast<double>(nx) - 0.5) * t[1];
  out.y0 = t[3] + 0.5 * t[5], out.y1 = t[3] + (static_cast<double>(ny) - 0.5) * t[5];
}

}  // namespace

}  // namespace ridt::io

// The entry's name carries the GdalModule layout's version: a module built for another layout is
// not found, rather than misread.
extern "C" const ridt::io::detail::GdalModule* ridt_gdal_module_3() {
  static const ridt::io::detail::GdalModule module{ridt::io::points_in, ridt::io::tin_out, ridt::io::dem_out,
                                                   ridt::io::raster_in, ridt::io::remove_temporaries};
  return &module;
}
