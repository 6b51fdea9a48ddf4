// The file formats, a row each (formats.hpp): every role a format plays, with its reader or
// writer and what the file holds in it. The writers of triangulations take a uniform call here;
// each format's own code is in its io_*.cpp.
#include "formats.hpp"

// A row names only the roles its format has; the others stay empty.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace ridt::io::detail {
namespace {

// Writes through a Writer that commits only when the whole file is written.
template <class Body>
void whole(const std::string& path, Body body) {
  Writer out(path);
  body(out);
  out.commit();
}

void ele_out(const std::string& path, const TriangulationOut& o) {
  whole(path, [&](Writer& out) { write_ele(out, o.triangles(), o.first_index, {}, o.threads); });
}

void neigh_out(const std::string& path, const TriangulationOut& o) {
  const std::size_t nt = o.t.size();
  if (o.t.neighbors.size() < 3 * nt)
    fail_file(path,
              "the triangulation has " + std::to_string(o.t.neighbors.size()) + " neighbour entries for " +
                  std::to_string(nt) + " triangles");
  whole(path, [&](Writer& out) { write_neigh(out, std::span(o.t.neighbors).first(3 * nt), o.first_index, o.threads); });
}

void off_out(const std::string& path, const TriangulationOut& o) {
  check_indices(path, o.triangles(), o.points.size(), "a triangle");
  whole(path, [&](Writer& out) { write_off(out, o.points, o.triangles()); });
}

void obj_out(const std::string& path, const TriangulationOut& o) {
  check_indices(path, o.triangles(), o.points.size(), "a triangle");
  whole(path, [&](Writer& out) { write_obj(out, o.points, o.triangles()); });
}

void svg_out(const std::string& path, const TriangulationOut& o) { write_svg(path, o.points, o.t); }

std::vector<VertexId> bin_triangles_in(const std::string& path, std::string_view data, int /*first_index*/,
                                       unsigned /*threads*/) {
  return read_bin_triangles(path, data);
}

void bin_out(const std::string& path, const TriangulationOut& o) {
  whole(path, [&](Writer& out) { write_bin_triangles(out, o.triangles()); });
}

Terrain ogr_in(const std::string& path, const PointFilter& /*filter*/, const Columns& columns) {
  return read_ogr(path, columns);
}

// What the text formats hold.
constexpr std::string_view kTextPoints = "one point a line, `x y` or `x,y`; `#` starts a comment";
constexpr std::string_view kTextTriangles = "three indices a line, from 0";
constexpr std::string_view kOgrTerrain = "a point layer; z from the geometry or a field (`--columns x,y,FIELD`)";
constexpr std::string_view kOgrTin = "triangles as PolygonZ, with the CRS";
constexpr std::string_view kRasterSizes = "the first band's cells' centres, bilinear between them";
constexpr std::string_view kTable =
    "a table with or without a header, fields apart by commas, semicolons, tabs or spaces";

// GDAL's vector formats: terrain in, TINs out, through GDAL's module.
constexpr Format ogr(std::string_view extension, std::string_view name, std::string_view driver) {
  return {.extension = extension,
          .name = name,
          .terrain_in = {ogr_in, kOgrTerrain, true},
          .tin_out = {write_tin_ogr, kOgrTin, true},
          .gdal_driver = driver};
}

// GDAL's raster formats: size fields in, DEMs out, through GDAL's module.
constexpr std::string_view kGeoTiffDem = "GeoTIFF, tiled, DEFLATE, Float64 or Float32, with the CRS";
constexpr Format raster(std::string_view extension, std::string_view name, std::string_view driver,
                        std::string_view dem) {
  return {.extension = extension,
          .name = name,
          .size_in = {read_size_gdal, kRasterSizes, true},
          .dem_out = {write_dem_gdal, dem, true},
          .gdal_driver = driver};
}

constexpr Format text(std::string_view extension) {
  return {.extension = extension,
          .name = "text",
          .points_in = {read_text_points, kTextPoints},
          .points_out = {write_text_points, kTextPoints},
          .triangles_in = {read_text_triangles, kTextTriangles},
          .terrain_in = {read_table, kTable}};
}

constexpr Format kFormats[] = {
    {.extension = ".node",
     .name = "Triangle's nodes",
     .points_in = {read_node, "header `n 2 attributes markers`, then `i x y ...`; its first index (0 or 1) is kept"},
     .points_out = {write_node, "Triangle's, numbered from 0, no attributes or markers"},
     .graph_in = {read_node_graph, "points alone (no segments)"},
     .size_in = {read_size_node, "sizes at points, their first attribute, linear over their Delaunay triangulation"},
     .mesh_files = {true, "`OUT.node`: the mesh's vertices, attributes, markers; `OUT.v.node`: its dual's vertices"}},
    {.extension = ".poly",
     .name = "Triangle's planar straight-line graph",
     .points_in = {read_poly_points, "its vertices (or the `.node` beside it)"},
     .graph_in = {read_poly, "vertices (or none, and the `.node` beside it), segments, holes, regions"}},
    {.extension = ".ele",
     .name = "Triangle's elements",
     .triangles_in = {read_ele, "`T 3 0`, then `k a b c`, numbered like the `.node` (else from 0)"},
     .triangulation_out = {ele_out, "`T 3 0`, then `k a b c`, numbered like the input `.node` (else from 0)"},
     .size_in = {read_size_mesh, "a background mesh, the sizes its `.node`'s first attribute, linear in each triangle"},
     .mesh_files = {true, "three nodes or six (`o2`), an attribute each (`A`); read with `r` and by `check`"}},
    {.extension = ".area",
     .name = "Triangle's area bounds",
     .mesh_files = {true, "with `r` and `a`: `n`, then `i max_area`, an area bound a triangle"}},
    {.extension = ".edge",
     .name = "Triangle's edges",
     .mesh_files = {true,
                    "`m 1`, then `i a b marker` a segment's edge (every edge with `e`); `OUT.v.edge`: the dual, "
                    "a ray as `i u -1 dx dy`"}},
    {.extension = ".neigh",
     .name = "Triangle's neighbours",
     .triangulation_out = {neigh_out, "three neighbours a triangle, -1 on the hull"},
     .mesh_files = {true, "with `n`"},
     .writes_neighbors = true},
    {.extension = ".parts",
     .name = "an index of parts",
     .triangles_in = {read_parts_index, "`ridt parts N`, then N part files (`.ele` from 0, or `.bin`)"}},
    {.extension = ".bin",
     .name = "little-endian binary",
     .points_in = {read_bin_points, "float64 `x, y` pairs"},
     .points_out = {write_bin_points, "float64 `x, y` pairs"},
     .triangles_in = {bin_triangles_in, "uint32 triples"},
     .triangulation_out = {bin_out, "uint32 triples"},
     .values_out = {write_values_bin, "float64 values"},
     .put_sorted = put_bin_sorted},
    {.extension = ".ply",
     .name = "Stanford PLY, binary little-endian",
     .points_out = {write_ply_points, "binary PLY: the vertices alone, float64 x, y, z (z = 0)"},
     .triangulation_out = {write_ply, "binary PLY: float64 x, y, z (z = 0), faces of uint32 indices"},
     .tin_out = {write_tin_ply, "vertices with their heights, faces"}},
    {.extension = ".obj",
     .name = "Wavefront OBJ",
     .triangulation_out = {obj_out, "vertices (z = 0), faces"},
     .tin_out = {write_tin_obj, "vertices with their heights, faces"}},
    {.extension = ".off",
     .name = "Object File Format",
     .triangulation_out = {off_out, "vertices (z = 0), faces"},
     .voronoi_out = {write_voronoi_off, "each cell clipped to the box a face"},
     .mesh_files = {true, "with `g`: the triangles for a viewer"}},
    {.extension = ".svg",
     .name = "a drawing",
     .triangulation_out = {svg_out, "the triangles (at most 200,000), segments apart"},
     .voronoi_out = {write_voronoi_svg, "the cells clipped to the box, and the sites"},
     .writes_neighbors = true},
    {.extension = ".png",
     .name = "a picture",
     .values_out = {write_values_png, "a grid's values as a colour map"},
     .dem_out = {write_dem_png, "a hillshade (sun in the north-west, 45 degrees high), transparent where no height"}},
    {.extension = ".json",
     .name = "JSON, or GeoJSON through GDAL",
     .voronoi_out = {write_voronoi_json, "vertices, cells, ridges"},
     .terrain_in = {ogr_in, kOgrTerrain, true},
     .tin_out = {write_tin_ogr, kOgrTin, true},
     .gdal_driver = "GeoJSON"},
    {.extension = ".las",
     .name = "ASPRS LAS 1.0-1.4",
     .terrain_in = {read_las_terrain, "ASPRS LAS 1.0-1.4, point formats 0-10, the CRS from its WKT or GeoTIFF keys"}},
    {.extension = ".laz",
     .name = "compressed LAS",
     .terrain_in = {read_laz, "compressed LAS: refused, with how to decompress it"}},
    ogr(".gpkg", "GeoPackage", "GPKG"),
    ogr(".shp", "ESRI Shapefile", "ESRI Shapefile"),
    ogr(".geojson", "GeoJSON", "GeoJSON"),
    ogr(".fgb", "FlatGeobuf", "FlatGeobuf"),
    ogr(".gml", "GML", "GML"),
    ogr(".kml", "KML", "KML"),
    ogr(".sqlite", "SpatiaLite", "SQLite"),
    raster(".tif", "GeoTIFF", "GTiff", kGeoTiffDem),
    raster(".tiff", "GeoTIFF", "GTiff", kGeoTiffDem),
    raster(".img", "Erdas Imagine", "HFA", "Erdas Imagine, Float64 or Float32, with the CRS"),
    {.extension = ".asc",
     .name = "ESRI ASCII grid",
     .size_in = {read_size_ascii_grid, "sizes at the cells' centres, bilinear between them"}},
    {.extension = ".csv",
     .name = "comma-separated values",
     .points_in = {read_text_points, "`x,y` a line"},
     .points_out = {write_csv_points, "`x,y` a line"},
     .values_out = {write_values_csv, "`x,y,values` a line"},
     .terrain_in = {read_table, kTable}},
    text(".txt"),
    text(".xy"),
    text(".pts"),
    text(".dat"),
    {.extension = "",
     .name = "text",
     .points_in = {read_text_points, kTextPoints},
     .points_out = {write_text_points, kTextPoints},
     .triangles_in = {read_text_triangles, kTextTriangles},
     .terrain_in = {read_table, kTable}},
};

}  // namespace

std::span<const Format> formats() { return kFormats; }

}  // namespace ridt::io::detail
