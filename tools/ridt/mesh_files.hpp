// ridt mesh's files (mesh_files.cpp): Triangle's run (ridt::triangle::Output) written as Triangle
// writes it.
#pragma once

#include <string>

#include "io.hpp"
#include "ridt/triangle.hpp"

namespace ridt::tool {

/// OUT.ele, OUT.node, OUT.edge (every edge where the run listed them, else the segments'
/// pieces) and, as `files` asks, OUT.neigh, OUT.off, OUT.v.node and OUT.v.edge of `m`: all or,
/// on an error, none; numbered from `first_index`. Or a drawing, OUT.svg, its segments apart.
void write_mesh(const std::string& path, const triangle::Output& m, const io::MeshFileSet& files, int first_index,
                unsigned threads);

}  // namespace ridt::tool
