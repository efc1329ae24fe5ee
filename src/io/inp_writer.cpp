#include "io/inp_writer.h"

#include <algorithm>

#include "io/atomic_file_writer.h"
#include "io/shape_mesh_check.h"
#include "io/text_output.h"

namespace tquad {

namespace {

constexpr std::size_t max_line = 132;  // CalculiX reads at most 132 characters a line

// A "** ..." comment line: one line, cut to the line limit.
std::string comment(std::string text) {
  std::replace_if(text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  text = "** " + text;
  if (text.size() > max_line - 1) text = text.substr(0, max_line - 4) + "...";
  return text + "\n";
}

}  // namespace

void write_inp(std::ostream& out, const ShapeMesh& mesh) {
  check_shape_mesh(mesh);
  // Second order: S8R, the eight-node shell with reduced integration (CalculiX expands
  // it to C3D20R, its usual choice for shells); its node order is ShapeMesh's.
  const std::string type = mesh.second_order() ? "S8R" : "S4";
  std::string text;
  text += comment("TemplateQuad mesh: " + std::to_string(mesh.nodes.size()) + " nodes, " +
                  std::to_string(mesh.quads.size()) + " " + type + " elements, " +
                  std::to_string(mesh.faces.size()) + " faces");
  text += comment("element set FACE<k>: the elements of face k; EALL: all elements; NALL: all nodes");
  for (const FaceMesh& f : mesh.faces) {
    if (f.quad_count == 0) continue;
    text += comment("FACE" + std::to_string(f.face) + ": elements " + std::to_string(f.first_quad + 1) + " to " +
                    std::to_string(f.first_quad + f.quad_count));
  }
  for (const RefusedFace& f : mesh.refused_faces) {
    text += comment("face " + std::to_string(f.face) + " refused (not meshed): " + f.reason);
  }

  text += "*NODE, NSET=NALL\n";
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const Vec3& p = mesh.nodes[i];
    text += std::to_string(i + 1);
    for (double c : {p.x, p.y, p.z}) {
      text += ", ";
      append_double_within(text, c, kInpFieldWidth);
    }
    text += '\n';
    flush_if_large(out, text);
  }

  for (const FaceMesh& f : mesh.faces) {
    if (f.quad_count == 0) continue;
    text += "*ELEMENT, TYPE=" + type + ", ELSET=FACE" + std::to_string(f.face) + "\n";
    for (std::int64_t k = f.first_quad; k < f.first_quad + f.quad_count; ++k) {
      text += std::to_string(k + 1);
      for (NodeId id : mesh.element_nodes(static_cast<std::size_t>(k))) {
        text += ", ";
        text += std::to_string(static_cast<std::int64_t>(id) + 1);
      }
      text += '\n';
      flush_if_large(out, text);
    }
  }
  if (!mesh.quads.empty()) {
    text += "*ELSET, ELSET=EALL, GENERATE\n1, " + std::to_string(mesh.quads.size()) + ", 1\n";
  }
  flush_text(out, text);
}

void write_inp_file(const std::string& path, const ShapeMesh& mesh) {
  write_file_atomically(path, [&](std::ostream& out) { write_inp(out, mesh); });
}

}  // namespace tquad
