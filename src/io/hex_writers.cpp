#include "io/hex_writers.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

#include "core/input_error.h"
#include "io/atomic_file_writer.h"
#include "io/text_output.h"

namespace tquad {

namespace {

// The C3D8 faces, as CalculiX numbers them (S1..S6), by the element's local nodes.
constexpr int kHexFaces[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};

std::string extension_of(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void append_ids(std::string& text, const std::vector<NodeId>& ids, int per_line) {
  for (std::size_t i = 0; i < ids.size(); ++i) {
    append_integer(text, static_cast<long long>(ids[i]) + 1);
    text += (i + 1 == ids.size() || (i + 1) % per_line == 0) ? "\n" : ", ";
  }
}

// Each face's nodes once, ascending, by face (a face two solids share is one set).
std::map<int, std::vector<NodeId>> merged_face_nodes(const HexMesh& mesh) {
  std::map<int, std::vector<NodeId>> sets;
  for (const auto& [face, nodes] : mesh.face_nodes) {
    std::vector<NodeId>& set = sets[face];
    set.insert(set.end(), nodes.begin(), nodes.end());
  }
  for (auto& [face, nodes] : sets) {
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  }
  return sets;
}

}  // namespace

void check_hex_mesh(const HexMesh& mesh) {
  for (const Vec3& p : mesh.nodes) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      throw std::invalid_argument("a node of the hexahedral mesh has a coordinate that is not finite");
    }
  }
  const auto count = static_cast<long long>(mesh.nodes.size());
  for (const Hex& h : mesh.hexes) {
    for (NodeId n : h) {
      if (n < 0 || n >= count) throw std::invalid_argument("a hexahedron names node " + std::to_string(n) + " of " + std::to_string(count));
    }
  }
  if (mesh.scaled_jacobian.size() != mesh.hexes.size()) {
    throw std::invalid_argument("the hexahedral mesh's quality list does not match its hexahedra");
  }
  if (mesh.second_order() && (mesh.mid_nodes.size() != mesh.hexes.size() || mesh.jacobian_ratio.size() != mesh.hexes.size())) {
    throw std::invalid_argument("the hexahedral mesh's edge middles do not match its hexahedra");
  }
  for (const auto& m : mesh.mid_nodes) {
    for (NodeId n : m) {
      if (n < 0 || n >= count) throw std::invalid_argument("an edge middle names node " + std::to_string(n) + " of " + std::to_string(count));
    }
  }
}

void write_hex_inp(std::ostream& out, const HexMesh& mesh) {
  check_hex_mesh(mesh);
  const std::string type = mesh.second_order() ? "C3D20" : "C3D8";
  std::string text = "** TemplateQuad sweep: " + std::to_string(mesh.nodes.size()) + " nodes, " +
                     std::to_string(mesh.hexes.size()) + " " + type + " elements, " + std::to_string(mesh.solids.size()) +
                     " solids\n";
  for (const RefusedSolid& r : mesh.refused) text += "** not swept: " + r.reason.substr(0, 110) + "\n";
  text += "*NODE, NSET=NALL\n";
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    append_integer(text, static_cast<long long>(i) + 1);
    for (double v : {mesh.nodes[i].x, mesh.nodes[i].y, mesh.nodes[i].z}) {
      text += ", ";
      append_double_within(text, v, kInpFieldWidth);
    }
    text += "\n";
    flush_if_large(out, text);
  }
  for (const SweptSolid& s : mesh.solids) {
    text += "*ELEMENT, TYPE=" + type + ", ELSET=SOLID" + std::to_string(s.solid) + "\n";
    for (std::int64_t k = s.first_hex; k < s.first_hex + s.hex_count; ++k) {
      append_integer(text, k + 1);
      // At most 16 entries a line (the element number and 15 nodes), then a
      // continuation line: C3D20's 21 entries take two.
      int entries = 1;
      for (NodeId n : mesh.element_nodes(static_cast<std::size_t>(k))) {
        text += entries == 16 ? ",\n" : ", ";
        if (entries == 16) entries = 0;
        append_integer(text, static_cast<long long>(n) + 1);
        ++entries;
      }
      text += "\n";
      flush_if_large(out, text);
    }
  }
  if (!mesh.hexes.empty()) text += "*ELSET, ELSET=EALL, GENERATE\n1, " + std::to_string(mesh.hexes.size()) + ", 1\n";
  // Node sets, and the element faces whose four nodes are all on the face.
  const std::map<int, std::vector<NodeId>> sets = merged_face_nodes(mesh);
  std::vector<std::vector<int>> faces_of_node(mesh.nodes.size());
  for (const auto& [face, nodes] : sets) {
    for (NodeId n : nodes) faces_of_node[n].push_back(face);
  }
  std::map<int, std::vector<std::pair<std::size_t, int>>> surfaces;
  for (std::size_t k = 0; k < mesh.hexes.size(); ++k) {
    for (int side = 0; side < 6; ++side) {
      std::vector<int> common = faces_of_node[mesh.hexes[k][kHexFaces[side][0]]];
      for (int i = 1; i < 4 && !common.empty(); ++i) {
        const std::vector<int>& other = faces_of_node[mesh.hexes[k][kHexFaces[side][i]]];
        common.erase(std::remove_if(common.begin(), common.end(),
                                    [&](int f) { return std::find(other.begin(), other.end(), f) == other.end(); }),
                     common.end());
      }
      for (int f : common) surfaces[f].emplace_back(k, side);
    }
  }
  for (const auto& [face, nodes] : sets) {
    text += "*NSET, NSET=FACE" + std::to_string(face) + "\n";
    append_ids(text, nodes, 8);
    flush_if_large(out, text);
  }
  for (const auto& [face, elements] : surfaces) {
    text += "*SURFACE, NAME=SFACE" + std::to_string(face) + ", TYPE=ELEMENT\n";
    for (const auto& [k, side] : elements) text += std::to_string(k + 1) + ", S" + std::to_string(side + 1) + "\n";
    flush_if_large(out, text);
  }
  flush_text(out, text);
}

void write_hex_vtu(std::ostream& out, const HexMesh& mesh) {
  check_hex_mesh(mesh);
  std::string text =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(mesh.nodes.size()) + "\" NumberOfCells=\"" +
      std::to_string(mesh.hexes.size()) + "\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Vec3& p : mesh.nodes) {
    append_double(text, p.x);
    text += " ";
    append_double(text, p.y);
    text += " ";
    append_double(text, p.z);
    text += "\n";
    flush_if_large(out, text);
  }
  text += "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  const int per = mesh.nodes_per_element();
  for (std::size_t k = 0; k < mesh.hexes.size(); ++k) {
    const HexMesh::ElementNodes ids = mesh.element_nodes(k);
    for (int i = 0; i < per; ++i) {
      append_integer(text, ids[i]);
      text += i + 1 == per ? '\n' : ' ';
    }
    flush_if_large(out, text);
  }
  text += "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < mesh.hexes.size(); ++k) {
    append_integer(text, static_cast<long long>(per) * static_cast<long long>(k + 1));
    text += '\n';
    flush_if_large(out, text);
  }
  text += "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  const std::string cell_type = mesh.second_order() ? "25\n" : "12\n";  // VTK's (quadratic) hexahedron
  for (std::size_t k = 0; k < mesh.hexes.size(); ++k) {
    text += cell_type;
    flush_if_large(out, text);
  }
  text += "</DataArray>\n</Cells>\n<CellData Scalars=\"scaled_jacobian\">\n"
          "<DataArray type=\"Float64\" Name=\"scaled_jacobian\" format=\"ascii\">\n";
  for (double sj : mesh.scaled_jacobian) {
    append_double(text, sj);
    text += "\n";
    flush_if_large(out, text);
  }
  text += "</DataArray>\n<DataArray type=\"Int32\" Name=\"solid\" format=\"ascii\">\n";
  for (const SweptSolid& s : mesh.solids) {
    for (std::int64_t k = 0; k < s.hex_count; ++k) {
      append_integer(text, s.solid);
      text += '\n';
      flush_if_large(out, text);
    }
  }
  text += "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  flush_text(out, text);
}

void write_hex_json(std::ostream& out, const HexMesh& mesh) {
  check_hex_mesh(mesh);
  std::string text = "{\n\"nodes\": [";
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    text += i ? ",\n[" : "\n[";
    append_double(text, mesh.nodes[i].x);
    text += ", ";
    append_double(text, mesh.nodes[i].y);
    text += ", ";
    append_double(text, mesh.nodes[i].z);
    text += "]";
    flush_if_large(out, text);
  }
  text += "],\n\"hexes\": [";
  for (std::size_t k = 0; k < mesh.hexes.size(); ++k) {
    text += k ? ",\n[" : "\n[";
    const HexMesh::ElementNodes ids = mesh.element_nodes(k);
    for (std::size_t i = 0; i < ids.size(); ++i) {
      append_integer(text, ids[i]);
      text += i + 1 == ids.size() ? "]" : ", ";
    }
    flush_if_large(out, text);
  }
  text += "],\n\"solids\": [";
  for (std::size_t i = 0; i < mesh.solids.size(); ++i) {
    const SweptSolid& s = mesh.solids[i];
    text += std::string(i ? ",\n" : "\n") + "{\"solid\": " + std::to_string(s.solid) + ", \"source\": " +
            std::to_string(s.source) + ", \"target\": " + std::to_string(s.target) + ", \"layers\": " +
            std::to_string(s.layers) + ", \"height\": ";
    append_double(text, s.height);
    const auto vec = [&](const Vec3& v) {
      text += "[";
      append_double(text, v.x);
      text += ", ";
      append_double(text, v.y);
      text += ", ";
      append_double(text, v.z);
      text += "]";
    };
    if (s.projected) {
      text += ", \"projection\": \"least squares\"";
    } else if (s.rotation) {
      text += ", \"rotation\": {\"point\": ";
      vec(s.point);
      text += ", \"direction\": ";
      vec(s.vector);
      text += ", \"angle\": ";
      append_double(text, s.angle);
      text += "}";
    } else {
      text += ", \"translation\": ";
      vec(s.vector);
    }
    text += ", \"first_hex\": " + std::to_string(s.first_hex) + ", \"hex_count\": " + std::to_string(s.hex_count) + "}";
  }
  text += "],\n\"refused_solids\": [";
  for (std::size_t i = 0; i < mesh.refused.size(); ++i) {
    std::string reason;
    for (char c : mesh.refused[i].reason) {
      if (c == '"' || c == '\\') reason += '\\';
      if (static_cast<unsigned char>(c) >= 0x20) reason += c;
    }
    text += std::string(i ? ",\n" : "\n") + "{\"solid\": " + std::to_string(mesh.refused[i].solid) +
            ", \"reason\": \"" + reason + "\"}";
  }
  text += "],\n\"face_nodes\": {";
  bool first = true;
  for (const auto& [face, nodes] : merged_face_nodes(mesh)) {
    text += std::string(first ? "\n" : ",\n") + "\"" + std::to_string(face) + "\": [";
    first = false;
    for (std::size_t j = 0; j < nodes.size(); ++j) {
      if (j) text += ", ";
      append_integer(text, nodes[j]);
    }
    text += "]";
    flush_if_large(out, text);
  }
  text += "}\n}\n";
  flush_text(out, text);
}

void write_hex_msh(std::ostream& out, const HexMesh& mesh) {
  check_hex_mesh(mesh);
  // Gmsh's element types and its 20-node hexahedron's edge order (edges 0-1, 0-3, 0-4,
  // 1-2, 1-5, 2-3, 2-6, 3-7, 4-5, 4-7, 5-6, 6-7), as positions in ours.
  const int type = mesh.second_order() ? 17 : 5;
  constexpr int kGmshEdges[12] = {0, 3, 8, 1, 9, 2, 10, 11, 4, 7, 5, 6};
  // Each node in the block of the first solid whose hexahedra use it.
  std::vector<int> owner(mesh.nodes.size(), -1);
  for (std::size_t r = 0; r < mesh.solids.size(); ++r) {
    const SweptSolid& s = mesh.solids[r];
    for (std::int64_t k = s.first_hex; k < s.first_hex + s.hex_count; ++k) {
      for (NodeId n : mesh.element_nodes(static_cast<std::size_t>(k))) {
        if (owner[n] < 0) owner[n] = static_cast<int>(r);
      }
    }
  }
  std::vector<std::vector<NodeId>> blocks(mesh.solids.size());
  for (std::size_t i = 0; i < owner.size(); ++i) {
    if (owner[i] >= 0) blocks[owner[i]].push_back(static_cast<NodeId>(i));
  }
  std::string text = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 0 " + std::to_string(mesh.solids.size()) + "\n";
  for (std::size_t r = 0; r < mesh.solids.size(); ++r) {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (NodeId n : blocks[r]) {
      const double c[3] = {mesh.nodes[n].x, mesh.nodes[n].y, mesh.nodes[n].z};
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], c[a]);
        hi[a] = std::max(hi[a], c[a]);
      }
    }
    text += std::to_string(mesh.solids[r].solid + 1);
    for (int a = 0; a < 3; ++a) {
      text += " ";
      append_double(text, blocks[r].empty() ? 0.0 : lo[a]);
    }
    for (int a = 0; a < 3; ++a) {
      text += " ";
      append_double(text, blocks[r].empty() ? 0.0 : hi[a]);
    }
    text += " 0 0\n";
  }
  std::size_t used = 0;
  for (const auto& b : blocks) used += b.size();
  text += "$EndEntities\n$Nodes\n" + std::to_string(mesh.solids.size()) + " " + std::to_string(used) + " 1 " +
          std::to_string(mesh.nodes.size()) + "\n";
  for (std::size_t r = 0; r < mesh.solids.size(); ++r) {
    text += "3 " + std::to_string(mesh.solids[r].solid + 1) + " 0 " + std::to_string(blocks[r].size()) + "\n";
    for (NodeId n : blocks[r]) {
      append_integer(text, static_cast<long long>(n) + 1);
      text += '\n';
    }
    for (NodeId n : blocks[r]) {
      append_double(text, mesh.nodes[n].x);
      text += " ";
      append_double(text, mesh.nodes[n].y);
      text += " ";
      append_double(text, mesh.nodes[n].z);
      text += "\n";
      flush_if_large(out, text);
    }
  }
  text += "$EndNodes\n$Elements\n" + std::to_string(mesh.solids.size()) + " " + std::to_string(mesh.hexes.size()) +
          " 1 " + std::to_string(mesh.hexes.size()) + "\n";
  for (const SweptSolid& s : mesh.solids) {
    text += "3 " + std::to_string(s.solid + 1) + " " + std::to_string(type) + " " + std::to_string(s.hex_count) + "\n";
    for (std::int64_t k = s.first_hex; k < s.first_hex + s.hex_count; ++k) {
      append_integer(text, k + 1);
      for (NodeId n : mesh.hexes[k]) {
        text += ' ';
        append_integer(text, static_cast<long long>(n) + 1);
      }
      if (mesh.second_order()) {
        for (int e : kGmshEdges) {
          text += ' ';
          append_integer(text, static_cast<long long>(mesh.mid_nodes[k][e]) + 1);
        }
      }
      text += "\n";
      flush_if_large(out, text);
    }
  }
  text += "$EndElements\n";
  flush_text(out, text);
}

bool is_hex_output(const std::string& path) {
  const std::string ext = extension_of(path);
  return ext == ".inp" || ext == ".vtu" || ext == ".json" || ext == ".msh";
}

void write_hex_file(const std::string& path, const HexMesh& mesh) {
  const std::string ext = extension_of(path);
  if (!is_hex_output(path)) {
    throw InputError("'" + path + "': a swept mesh is written as .inp, .vtu, .msh or .json, not '" + ext + "'");
  }
  check_hex_mesh(mesh);
  write_file_atomically(path, [&](std::ostream& out) {
    if (ext == ".inp") write_hex_inp(out, mesh);
    if (ext == ".vtu") write_hex_vtu(out, mesh);
    if (ext == ".json") write_hex_json(out, mesh);
    if (ext == ".msh") write_hex_msh(out, mesh);
  });
}

}  // namespace tquad
