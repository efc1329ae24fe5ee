#include "io/mesh_json_writer.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "io/atomic_file_writer.h"
#include "io/shape_mesh_check.h"
#include "io/text_output.h"

namespace tquad {

namespace {

// "1" or "-0" would read back as JSON integers, losing the sign of -0.0 and turning
// into ints in Python: keep every coordinate a float literal.
void append_json_double(std::string& text, double value) {
  const std::size_t start = text.size();
  append_double(text, value);
  if (std::find_if(text.begin() + static_cast<std::ptrdiff_t>(start), text.end(),
                   [](char c) { return c == '.' || c == 'e'; }) == text.end()) {
    text += ".0";
  }
}

// Rows of four node indices as JSON arrays, one a line.
void append_index_rows(std::ostream& out, std::string& text, const std::vector<Quad>& rows) {
  for (std::size_t k = 0; k < rows.size(); ++k) {
    text += k == 0 ? "\n[" : ",\n[";
    for (int i = 0; i < 4; ++i) {
      if (i > 0) text += ", ";
      text += std::to_string(rows[k][i]);
    }
    text += ']';
    flush_if_large(out, text);
  }
}

}  // namespace

void write_mesh_json(std::ostream& out, const ShapeMesh& mesh) {
  check_shape_mesh(mesh);
  std::string text = "{\n\"nodes\": [";
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const Vec3& p = mesh.nodes[i];
    text += i == 0 ? "\n[" : ",\n[";
    append_json_double(text, p.x);
    text += ", ";
    append_json_double(text, p.y);
    text += ", ";
    append_json_double(text, p.z);
    text += ']';
    flush_if_large(out, text);
  }
  text += "\n],\n\"quads\": [";
  append_index_rows(out, text, mesh.quads);
  if (mesh.second_order()) {  // per quad, the nodes in the middle of edges 0-1, 1-2, 2-3, 3-0
    text += "\n],\n\"mid_nodes\": [";
    append_index_rows(out, text, mesh.mid_nodes);
  }
  text += "\n],\n\"faces\": [";
  for (std::size_t r = 0; r < mesh.faces.size(); ++r) {
    const FaceMesh& f = mesh.faces[r];
    text += r == 0 ? "" : ",\n";
    text += "{\"face\": " + std::to_string(f.face) + ", \"template_tree\": ";
    text += nlohmann::json(f.template_tree).dump();  // escaped JSON string
    text += ", \"quads\": [" + std::to_string(f.first_quad) + ", " + std::to_string(f.quad_count) + "]}";
  }
  text += "]\n}\n";
  flush_text(out, text);
}

void write_mesh_json_file(const std::string& path, const ShapeMesh& mesh) {
  write_file_atomically(path, [&](std::ostream& out) { write_mesh_json(out, mesh); });
}

}  // namespace tquad
