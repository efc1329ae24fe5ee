// The `.json` mesh file of docs/design.md, "Public contracts":
//   {"nodes": [[x, y, z], ...], "quads": [[i, j, k, l], ...],
//    "faces": [{"face": k, "template_tree": "...", "quads": [first, count]}, ...]}
// with one "faces" entry per face record of the ShapeMesh, in record order.
// Coordinates are written in the shortest text that reads back to the same double,
// so boundary nodes stay bit-exact through a write and a read.
#pragma once

#include <ostream>
#include <string>

#include "core/mesh/shape_mesh.h"

namespace tquad {

// Throws std::invalid_argument for an inconsistent ShapeMesh (see shape_mesh_check.h)
// and std::logic_error for a non-finite coordinate (JSON cannot express it; the mesher
// never makes one). Refused faces are not part of the mesh file (the report has them).
void write_mesh_json(std::ostream& out, const ShapeMesh& mesh);

// Writes PATH atomically (see atomic_file_writer.h).
void write_mesh_json_file(const std::string& path, const ShapeMesh& mesh);

}  // namespace tquad
