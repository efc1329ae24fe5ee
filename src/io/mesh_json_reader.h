// read_mesh_json: reads back the `.json` mesh file that mesh_json_writer writes (for
// tests, tools and round trips). A file of several faces gives one mesh of all of
// them; template_tree is then the trees joined by "; ".
#pragma once

#include <string>

#include "core/mesh/quad_mesh.h"

namespace tquad {

// Throws InputError naming the file and the entry at fault (syntax error, missing
// key, wrong type, node index out of range).
QuadMesh read_mesh_json(const std::string& path);
QuadMesh parse_mesh_json(const std::string& text, const std::string& source_name);

}  // namespace tquad
