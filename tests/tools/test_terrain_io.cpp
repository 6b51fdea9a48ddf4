// Terrain files: LAS of every version and point format written by the tests (las_writer.hpp),
// filters, CRS records, truncated and inconsistent files; tables with and without headers; and
// GDAL's formats, every output read back with GDAL itself: a TIN's triangles and heights, a
// DEM's cells equal to the library's Dem, the CRS carried.
#include <gtest/gtest.h>

#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "las_writer.hpp"
#include "ridt/terrain.hpp"
#include "terrain_io.hpp"
#include "tools/scratch_dir.hpp"

namespace ridt::io {
namespace {

namespace fs = std::filesystem;
using test::las_file;
using test::LasPoint;
using test::LasSpec;

class TerrainIo : public ::testing::Test {
 protected:
  void SetUp() override {
    GDALAllRegister();
    dir_ = test::fresh_test_dir("ridt_terrain");
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string put(const std::string& name, const std::string& bytes) const {
    std::ofstream(path(name), std::ios::binary) << bytes;
    return path(name);
  }
  std::size_t files() const { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {})); }

  fs::path dir_;
};

std::vector<LasPoint> some_points() {
  std::vector<LasPoint> p;
  for (int k = 0; k < 40; ++k)
    p.push_back({1000.25 + k * 0.5, 2000.75 - k * 0.25, 10.5 + k, k % 3 == 0 ? 2 : 5, 1 + k % 2, 2, k == 7});
  return p;
}

TEST_F(TerrainIo, LasEveryVersionAndPointFormat) {
  const std::vector<LasPoint> pts = some_points();
  for (int minor = 0; minor <= 4; ++minor)
    for (int format = 0; format <= 10; ++format) {
      if (format >= 6 && minor < 4) continue;  // formats 6 to 10 came with 1.4
      if (format >= 4 && format <= 5 && minor < 3) continue;  // waveforms came with 1.3
      if (format >= 2 && format <= 3 && minor < 2) continue;
      LasSpec s;
      s.minor = minor, s.format = format, s.extra = format == 3 ? 5 : 0;
      s.offset[0] = 1000, s.offset[1] = 2000, s.scale[2] = 0.001;
      const Terrain t = parse_las(las_file(s, pts), "t.las", {});
      ASSERT_EQ(t.points.size(), pts.size() - 1) << minor << " " << format;  // one withheld
      EXPECT_EQ(t.points[0].x, 1000.25);
      EXPECT_EQ(t.points[0].y, 2000.75);
      EXPECT_NEAR(t.z[0], 10.5, 1e-12);
      EXPECT_NEAR(t.points[38].x, 1000.25 + 39 * 0.5, 1e-9);  // the 39th after the withheld one
    }
}

TEST_F(TerrainIo, LasFiltersByClassAndReturn) {
  const std::vector<LasPoint> pts = some_points();
  for (const int format : {1, 6}) {
    LasSpec s;
    s.minor = 4, s.format = format;
    const std::string f = las_file(s, pts);
    PointFilter ground;
    ground.classes = {2};
    EXPECT_EQ(parse_las(f, "t.las", ground).points.size(), 14u);  // k = 0, 3, ..., 39
    PointFilter first, last, single, all;
    first.returns = Returns::First, last.returns = Returns::Last, single.returns = Returns::Single;
    all.withheld = true;
    EXPECT_EQ(parse_las(f, "t.las", first).points.size(), 20u);  // even k (the withheld 7 is a second)
    EXPECT_EQ(parse_las(f, "t.las", last).points.size(), 19u);
    EXPECT_EQ(parse_las(f, "t.las", single).points.size(), 0u);
    EXPECT_EQ(parse_las(f, "t.las", all).points.size(), 40u);
  }
}

TEST_F(TerrainIo, LasCoordinateReferenceSystem) {
  const std::string wkt = "PROJCS[\"test\"]";
  for (const bool evlr : {false, true}) {
    LasSpec s;
    s.minor = 4, s.format = 6, s.wkt = wkt, s.evlr = evlr;
    EXPECT_EQ(parse_las(las_file(s, some_points()), "t.las").crs, wkt) << evlr;
  }
  LasSpec keys;
  keys.epsg = 32633;
  EXPECT_EQ(parse_las(las_file(keys, some_points()), "t.las").crs, "EPSG:32633");
  EXPECT_EQ(parse_las(las_file(LasSpec{}, some_points()), "t.las").crs, "");
}

// Each damage gives an IoError whose message says what is wrong.
TEST_F(TerrainIo, LasDamagedFilesSayWhy) {
  LasSpec s;
  s.minor = 2, s.wkt = "GEOGCS[\"x\"]";
  const std::string good = las_file(s, some_points());
  const auto fails = [](const std::string& bytes, const std::string& why) {
    try {
      parse_las(bytes, "bad.las");
      ADD_FAILURE() << "no error for " << why;
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  fails("", "not a LAS file");
  fails(good.substr(0, 100), "truncated");
  fails(good.substr(0, good.size() - 3), "truncated: the header says 40 points");
  std::string v = good;
  v[25] = 7;
  fails(v, "LAS version 1.7");
  std::string laz = good;
  laz[104] = static_cast<char>(0x80 | 3);
  fails(laz, "LAZ");
  std::string fmt = good;
  fmt[104] = 11;
  fails(fmt, "point format 11");
  std::string rec = good;
  test::put_at<std::uint16_t>(rec, 105, 10);
  fails(rec, "less than format 0's 20");
  std::string off = good;
  test::put_at<std::uint32_t>(off, 96, 1u << 30);
  fails(off, "outside the file");
  std::string vlr = good;
  test::put_at<std::uint32_t>(vlr, 100, 5);
  fails(vlr, "variable-length record 1");
  std::string scale = good;
  test::put_at<double>(scale, 131, 0.0);
  fails(scale, "scale factor");
  std::string huge = good;  // found by fuzz_terrain: 2^31 times 1e300 is not a double
  test::put_at<double>(huge, 147, 1e300);
  fails(huge, "overflow");
}

TEST_F(TerrainIo, LazIsRefusedByNameWithTheWayOut) {
  const std::string f = put("tile.laz", "LASF");
  try {
    read_terrain(f);
    FAIL();
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("laszip"), std::string::npos) << e.what();
  }
}

TEST_F(TerrainIo, LasFromAFileEqualsFromMemory) {
  LasSpec s;
  s.minor = 3, s.format = 1;
  const std::string bytes = las_file(s, some_points());
  const Terrain a = read_las(put("t.las", bytes)), b = parse_las(bytes, "t.las");
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.z, b.z);
  EXPECT_THROW(read_las(path("missing.las")), IoError);
}

TEST_F(TerrainIo, TablesWithAndWithoutHeaders) {
  const Terrain a = parse_table("X,Y,Z\n1,2,3\n4,5,6.5\n", "a.csv");
  ASSERT_EQ(a.points.size(), 2u);
  EXPECT_EQ(a.points[1].x, 4);
  EXPECT_EQ(a.z[1], 6.5);
  // Columns recognised by name in another order, with quotes, semicolons, extra columns.
  const Terrain b = parse_table("\"id\";\"Elevation\";\"Northing\";\"Easting\"\n7;3.5;20;10\n", "b.csv");
  EXPECT_EQ(b.points[0].x, 10);
  EXPECT_EQ(b.points[0].y, 20);
  EXPECT_EQ(b.z[0], 3.5);
  // Chosen columns, by name and by number; whitespace without a header.
  const Terrain c = parse_table("a b c d\n1 2 3 4\n", "c.txt", Columns{"d", "2", "a"});
  EXPECT_EQ(c.points[0].x, 4);
  EXPECT_EQ(c.points[0].y, 2);
  EXPECT_EQ(c.z[0], 1);
  const Terrain d = parse_table("1\t2\t3\n4\t5\t6\n", "d.xyz");
  EXPECT_EQ(d.points.size(), 2u);
  EXPECT_EQ(d.z[1], 6);
  EXPECT_THROW(parse_table("x,y\n1,2\n", "e.csv"), IoError);  // no z
  EXPECT_THROW(parse_table("x,y,z\n1,2\n", "e.csv"), IoError);  // a short row
  EXPECT_THROW(parse_table("x,y,z\n1,2,nan\n", "e.csv"), IoError);
  EXPECT_THROW(parse_table("x,y,z\n1,2,q\n", "e.csv"), IoError);
  EXPECT_THROW(parse_table("x,y,z\n1,2,3\n", "e.csv", Columns{"x", "y", "w"}), IoError);
  EXPECT_THROW(parse_table("x,y,z\n1,2,3\n", "e.csv", Columns{"x", "y", "9"}), IoError);
}

// The first line is a header only where its coordinate fields are not numbers: a row with
// another field that is not a number is a row, not a header lost; a first line of both is
// refused, as is a row of another width than the first line, naming its line.
TEST_F(TerrainIo, TableHeaderAndWidthRules) {
  const Terrain a = parse_table("12.1 55.2 3.4 99 junk\n13 56 4 98 more\n", "a.txt");
  ASSERT_EQ(a.points.size(), 2u);
  EXPECT_EQ(a.points[0].x, 12.1);
  EXPECT_EQ(a.z[0], 3.4);
  const Terrain b = parse_table("id,x,y,z\n1,2,3,4\n", "b.csv", Columns{"2", "3", "4"});
  ASSERT_EQ(b.points.size(), 1u);
  EXPECT_EQ(b.z[0], 4);
  const auto message = [](const char* text) {
    try {
      parse_table(text, "c.csv");
    } catch (const IoError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("1,2,z\n1,2,3\n").rfind("c.csv:1: field 3 \"z\" is not a number", 0), 0u)
      << message("1,2,z\n1,2,3\n");
  EXPECT_EQ(message("1,2,3\n4,5,6,7\n").rfind("c.csv:2: expected 3 fields, as line 1 has, got 4", 0), 0u)
      << message("1,2,3\n4,5,6,7\n");
  EXPECT_EQ(message("x,y,z\n1,2,3\n\n4,5\n").rfind("c.csv:4: expected 3 fields", 0), 0u);
}

// A small terrain and its TIN, for the GDAL round trips.
struct Sample {
  Terrain terrain;
  Triangulation t;
};

Sample sample(const std::string& crs) {
  Sample s;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 50);
  for (int k = 0; k < 500; ++k) {
    s.terrain.points.push_back({500000 + u(rng), 4000000 + u(rng)});
    s.terrain.z.push_back(100 + u(rng) / 7);
  }
  s.terrain.crs = crs;
  s.t = triangulate(s.terrain.points);
  return s;
}

bool same_crs(const std::string& wkt, int epsg) {
  OGRSpatialReference a, b;
  a.importFromWkt(wkt.c_str());
  b.importFromEPSG(epsg);
  return a.IsSame(&b) != 0;
}

TEST_F(TerrainIo, TinRoundTripsThroughGeoPackageAndShapefile) {
  const Sample s = sample("EPSG:32633");
  for (const std::string name : {"tin.gpkg", "tin.shp", "tin.geojson"}) {
    write_tin(path(name), s.terrain, s.t);
    GDALDataset* ds = GDALDataset::Open(path(name).c_str(), GDAL_OF_VECTOR);
    ASSERT_NE(ds, nullptr) << name;
    OGRLayer* layer = ds->GetLayer(0);
    EXPECT_EQ(layer->GetFeatureCount(), static_cast<GIntBig>(s.t.size())) << name;
    if (name != "tin.geojson") {  // GeoJSON is WGS 84 by definition
      char* wkt = nullptr;
      ASSERT_NE(layer->GetSpatialRef(), nullptr);
      layer->GetSpatialRef()->exportToWkt(&wkt);
      EXPECT_TRUE(same_crs(wkt, 32633)) << name;
      CPLFree(wkt);
    }
    std::size_t k = 0;
    for (const auto& f : *layer) {
      const OGRLinearRing* ring = f->GetGeometryRef()->toPolygon()->getExteriorRing();
      ASSERT_EQ(ring->getNumPoints(), 4);
      // Shapefile writes rings clockwise: compare as sets of corners with heights.
      for (int i = 0; i < 3; ++i) {
        bool found = false;
        for (int c = 0; c < 3; ++c) {
          const VertexId v = s.t.triangles[3 * k + c];
          found = found ||
              (ring->getX(i) == s.terrain.points[v].x && ring->getY(i) == s.terrain.points[v].y &&
               ring->getZ(i) == s.terrain.z[v]);
        }
        EXPECT_TRUE(found) << name << " triangle " << k;
      }
      ++k;
    }
    EXPECT_EQ(k, s.t.size());
    GDALClose(ds);
  }
  for (const auto& e : fs::directory_iterator(dir_))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

TEST_F(TerrainIo, DemReadBackEqualsTheLibrarysCells) {
  const Sample s = sample("EPSG:32633");
  const RasterGrid g = RasterGrid::around(500000, 4000000, 500050, 4000050, 0.37);
  const Dem dem(s.terrain.points, s.t, s.terrain.z, g);
  const std::vector<double> want = dem.all();
  DemFile file;
  file.crs = s.terrain.crs;
  double last = 0;
  file.progress = [&](double f) { last = f; };
  write_dem(path("dem.tif"), dem, file);
  EXPECT_EQ(last, 1.0);
  GDALDataset* ds = GDALDataset::Open(path("dem.tif").c_str(), GDAL_OF_RASTER);
  ASSERT_NE(ds, nullptr);
  ASSERT_EQ(static_cast<std::size_t>(ds->GetRasterXSize()), g.nx);
  ASSERT_EQ(static_cast<std::size_t>(ds->GetRasterYSize()), g.ny);
  double gt[6];
  ds->GetGeoTransform(gt);
  EXPECT_EQ(gt[0], g.x0);
  EXPECT_EQ(gt[3], g.y1);
  EXPECT_EQ(gt[1], g.cell);
  EXPECT_EQ(gt[5], -g.cell);
  ASSERT_NE(ds->GetSpatialRef(), nullptr);
  char* wkt = nullptr;
  ds->GetSpatialRef()->exportToWkt(&wkt);
  EXPECT_TRUE(same_crs(wkt, 32633));
  CPLFree(wkt);
  std::vector<double> got(g.size());
  ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, static_cast<int>(g.nx), static_cast<int>(g.ny), got.data(),
                                           static_cast<int>(g.nx), static_cast<int>(g.ny), GDT_Float64, 0, 0, nullptr),
            CE_None);
  int has = 0;
  EXPECT_TRUE(std::isnan(ds->GetRasterBand(1)->GetNoDataValue(&has)) && has);
  GDALClose(ds);
  std::size_t nan = 0;
  for (std::size_t k = 0; k < got.size(); ++k) {
    if (std::isnan(want[k])) ++nan;
    ASSERT_TRUE(std::isnan(want[k]) ? std::isnan(got[k]) : got[k] == want[k]) << k;
  }
  EXPECT_GT(nan, 0u);  // the hull's outside
  EXPECT_LT(nan, got.size() / 5);
}

TEST_F(TerrainIo, PointLayersInWithTheirCrs) {
  const Sample s = sample("EPSG:32633");
  write_tin(path("t.ply"), s.terrain, s.t);  // PLY: no GDAL; an output for the size check
  EXPECT_GT(fs::file_size(path("t.ply")), 500u * 24);
  // A GeoPackage of PointZ written with GDAL, read back by read_terrain.
  GDALDriver* gpkg = GetGDALDriverManager()->GetDriverByName("GPKG");
  GDALDataset* ds = gpkg->Create(path("pts.gpkg").c_str(), 0, 0, 0, GDT_Unknown, nullptr);
  OGRSpatialReference srs;
  srs.importFromEPSG(32633);
  OGRLayer* layer = ds->CreateLayer("pts", &srs, wkbPoint25D, nullptr);
  for (std::size_t i = 0; i < 50; ++i) {
    OGRFeature f(layer->GetLayerDefn());
    OGRPoint p(s.terrain.points[i].x, s.terrain.points[i].y, s.terrain.z[i]);
    f.SetGeometry(&p);
    ASSERT_EQ(layer->CreateFeature(&f), OGRERR_NONE);
  }
  GDALClose(ds);
  const Terrain t = read_terrain(path("pts.gpkg"));
  ASSERT_EQ(t.points.size(), 50u);
  for (std::size_t i = 0; i < 50; ++i) {
    EXPECT_EQ(t.points[i], s.terrain.points[i]);
    EXPECT_EQ(t.z[i], s.terrain.z[i]);
  }
  EXPECT_TRUE(same_crs(t.crs, 32633));
  EXPECT_THROW(read_terrain(path("missing.gpkg")), IoError);
}

TEST_F(TerrainIo, FailedWritesLeaveNothing) {
  const Sample s = sample("");
  const std::size_t before = files();
  EXPECT_THROW(write_tin(path("tin.xyz"), s.terrain, s.t), IoError);
  EXPECT_THROW(write_tin(path("no/such/dir/tin.gpkg"), s.terrain, s.t), IoError);
  const Dem dem(s.terrain.points, s.t, s.terrain.z, RasterGrid::around(500000, 4000000, 500050, 4000050, 1));
  EXPECT_THROW(write_dem(path("dem.xyz"), dem, {}), IoError);
  Terrain bad = s.terrain;
  bad.crs = "not a CRS at all";
  EXPECT_THROW(write_tin(path("tin.gpkg"), bad, s.t), IoError);
  EXPECT_EQ(files(), before);
}

}  // namespace
}  // namespace ridt::io
