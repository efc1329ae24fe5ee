// The `.json` mesh file of DESIGN.md (public contracts):
//   {"nodes": [[x, y, z], ...], "quads": [[i, j, k, l], ...],
//    "faces": [{"face": 0, "template_tree": "...", "quads": [first, count]}]}
// Coordinates are written in the shortest text that reads back to the same double,
// so boundary nodes stay bit-exact through a write and a read.
#pragma once

#include <ostream>
#include <string>

#include "core/quad_mesh.h"

namespace tquad {

// One boundary region is one face (face 0, all quads). Throws std::logic_error for a
// non-finite coordinate (JSON cannot express it; the mesher never makes one).
void write_mesh_json(std::ostream& out, const QuadMesh& mesh);

// Writes PATH atomically (see atomic_file_writer.h).
void write_mesh_json_file(const std::string& path, const QuadMesh& mesh);

}  // namespace tquad
