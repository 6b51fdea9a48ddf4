// ridt mesh's files (mesh_files.cpp): a constrained triangulation or mesh written as Triangle
// writes it, with Triangle's markers, attributes and switches for the output.
#pragma once

#include <string>

#include "io.hpp"
#include "ridt/constrained.hpp"

namespace ridt::tool {

/// What ridt mesh writes, and how.
struct MeshOutput {
  std::string path;  ///< OUT.ele (OUT.node, OUT.edge and OUT.neigh beside it), or OUT.svg
  unsigned threads = 0;
  bool attributes = false;  ///< each triangle's attribute in OUT.ele (-A)
  io::MeshFileSet files;  ///< which files beside OUT.ele: -N, -E, -n, -g, -v
  bool zero_based = false;  ///< numbered from 0 (-z), else as the input
  bool second_order = false;  ///< six-node triangles (-o2)
  bool markers = true;  ///< boundary markers in OUT.node and OUT.edge (-B: none)
  bool all_edges = false;  ///< OUT.edge lists every edge, not the segments' alone (-e)
  bool jettison = false;  ///< OUT.node leaves out the vertices of no triangle (-j)
};

/// OUT.ele, OUT.node, OUT.edge (and OUT.neigh, OUT.off, OUT.v.node and OUT.v.edge) of `t`, the
/// mesh of `g`: all or, on an error, none; or a drawing, OUT.svg, its segments apart.
void write_mesh(const MeshOutput& o, const io::Pslg& g, const ConstrainedTriangulation& t);

}  // namespace ridt::tool
