#include "io/mesh_json_writer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/atomic_file_writer.h"

namespace tquad {

namespace {

// Shortest round-trip text of a finite double (std::to_chars without a precision).
void append_double(std::string& text, double value) {
  if (!std::isfinite(value)) throw std::logic_error("mesh has a non-finite node coordinate");
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  text.append(buffer, result.ptr);
  // "1" or "-0" would read back as JSON integers, losing the sign of -0.0 and turning
  // into ints in Python: keep every coordinate a float literal.
  if (std::find_if(buffer, result.ptr, [](char c) { return c == '.' || c == 'e'; }) == result.ptr) {
    text += ".0";
  }
}

// Text is built in chunks so a large mesh is neither one huge string nor many tiny writes.
void flush_if_large(std::ostream& out, std::string& text) {
  if (text.size() > (1u << 20)) {
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    text.clear();
  }
}

}  // namespace

void write_mesh_json(std::ostream& out, const QuadMesh& mesh) {
  std::string text = "{\n\"nodes\": [";
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const Vec3& p = mesh.nodes[i];
    text += i == 0 ? "\n[" : ",\n[";
    append_double(text, p.x);
    text += ", ";
    append_double(text, p.y);
    text += ", ";
    append_double(text, p.z);
    text += ']';
    flush_if_large(out, text);
  }
  text += "\n],\n\"quads\": [";
  for (std::size_t k = 0; k < mesh.quads.size(); ++k) {
    const Quad& q = mesh.quads[k];
    text += k == 0 ? "\n[" : ",\n[";
    for (int i = 0; i < 4; ++i) {
      if (i > 0) text += ", ";
      text += std::to_string(q[i]);
    }
    text += ']';
    flush_if_large(out, text);
  }
  text += "\n],\n\"faces\": [{\"face\": 0, \"template_tree\": ";
  text += nlohmann::json(mesh.template_tree).dump();  // escaped JSON string
  text += ", \"quads\": [0, " + std::to_string(mesh.quads.size()) + "]}]\n}\n";
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

void write_mesh_json_file(const std::string& path, const QuadMesh& mesh) {
  write_file_atomically(path, [&](std::ostream& out) { write_mesh_json(out, mesh); });
}

}  // namespace tquad
