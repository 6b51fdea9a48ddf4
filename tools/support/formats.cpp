// The file formats, one line each (formats.hpp). The writers of triangulations take a uniform
// call here; each format's own code is in its io_*.cpp.
#include "formats.hpp"

namespace ridt::io::detail {

void write_ply(const std::string& path, const TriangulationOut& o);  // io_ply.cpp
void write_ply_points(Writer& out, std::span<const Point> points, int first_index, unsigned threads);
Pslg read_poly(const std::string& path, std::string_view text, unsigned threads);  // io_poly.cpp
PointFile read_poly_points(const std::string& path, std::string_view text, unsigned threads);
Pslg read_node_graph(const std::string& path, std::string_view text, unsigned threads);  // io_poly.cpp

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

// clang-format off
// extension, description, points in, triangles in, points out, triangulation out, Voronoi out, values out, graph in
// (and, where the triangulation's writer reads the neighbours, true; where the triangles can be
// written as they are sorted, how)
constexpr Format kFormats[] = {
    {".poly", "Triangle's planar straight-line graph", read_poly_points, nullptr, nullptr, nullptr, nullptr, nullptr, read_poly},
    {".node", "Triangle's nodes",           read_node,        nullptr,             write_node,        nullptr,   nullptr,            nullptr, read_node_graph},
    {".ele", "Triangle's elements",         nullptr,          read_ele,            nullptr,           ele_out,   nullptr,            nullptr, nullptr},
    {".neigh", "Triangle's neighbours",     nullptr,          nullptr,             nullptr,           neigh_out, nullptr,            nullptr, nullptr, true},
    {".off", "OFF mesh",                    nullptr,          nullptr,             nullptr,           off_out,   write_voronoi_off,  nullptr, nullptr},
    {".ply", "Stanford PLY, binary",        nullptr,          nullptr,             write_ply_points,  write_ply, nullptr,            nullptr, nullptr},
    {".obj", "Wavefront OBJ",               nullptr,          nullptr,             nullptr,           obj_out,   nullptr,            nullptr, nullptr},
    {".svg", "a drawing",                   nullptr,          nullptr,             nullptr,           svg_out,   write_voronoi_svg,  nullptr, nullptr, true},
    {".json", "JSON",                       nullptr,          nullptr,             nullptr,           nullptr,   write_voronoi_json, nullptr, nullptr},
    {".csv", "x,y rows (and values)",       read_text_points, nullptr,             write_csv_points,  nullptr,   nullptr,            write_values_csv, nullptr},
    {".txt", "text, a point a line",        read_text_points, read_text_triangles, write_text_points, nullptr,   nullptr,            nullptr, nullptr},
    {".xy", "text, a point a line",         read_text_points, read_text_triangles, write_text_points, nullptr,   nullptr,            nullptr, nullptr},
    {".pts", "text, a point a line",        read_text_points, read_text_triangles, write_text_points, nullptr,   nullptr,            nullptr, nullptr},
    {".dat", "text, a point a line",        read_text_points, read_text_triangles, write_text_points, nullptr,   nullptr,            nullptr, nullptr},
    {".png", "a colour map of a grid",      nullptr,          nullptr,             nullptr,           nullptr,   nullptr,            write_values_png, nullptr},
    {".bin", "little-endian binary",        read_bin_points,  bin_triangles_in,    write_bin_points,  bin_out,   nullptr,            write_values_bin, nullptr, false, put_bin_sorted},
    {"", "text, a point or triangle a line", read_text_points, read_text_triangles, write_text_points, nullptr,  nullptr,            nullptr, nullptr},
};
// clang-format on

}  // namespace

std::span<const Format> formats() { return kFormats; }

}  // namespace ridt::io::detail

namespace ridt::io {

std::string point_formats() { return detail::extensions_with(&detail::Format::read_points); }
std::string point_output_formats() { return detail::extensions_with(&detail::Format::write_points, false); }
std::string triangle_formats() { return detail::extensions_with(&detail::Format::read_triangles); }
std::string triangulation_formats() { return detail::extensions_with(&detail::Format::write_triangulation); }
std::string voronoi_formats() {
  return ".svg (the cells clipped to the box, and the sites), .off (each clipped cell a face) or .json (vertices, "
         "cells, ridges)";
}
std::string values_formats() { return ".csv (x,y,values), .bin (float64 values) or, for a grid, .png (a colour map)"; }

}  // namespace ridt::io
