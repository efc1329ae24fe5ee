#include "io/msh_writer.h"

#include <stdexcept>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "io/atomic_file_writer.h"
#include "io/shape_mesh_check.h"
#include "io/text_output.h"

namespace tquad {

namespace {

constexpr int gmsh_quad = 3;            // 4-node quadrangle
constexpr int gmsh_quadratic_quad = 16;  // 8-node second-order quadrangle (corners, then edge middles)

std::string entity_tag(const FaceMesh& f) { return std::to_string(static_cast<std::int64_t>(f.face) + 1); }

// The nodes each face record lists: node i belongs to the first record whose quads
// use it (as a corner or, at second order, an edge middle). Returned as a counting sort: nodes of record r are
// order[start[r] .. start[r + 1]), ascending.
struct NodeBlocks {
  std::vector<std::size_t> start;
  std::vector<NodeId> order;
};

NodeBlocks node_blocks(const ShapeMesh& mesh) {
  const std::size_t records = mesh.faces.size();
  std::vector<std::int32_t> owner(mesh.nodes.size(), -1);
  for (std::size_t r = 0; r < records; ++r) {
    const FaceMesh& f = mesh.faces[r];
    for (std::int64_t k = f.first_quad; k < f.first_quad + f.quad_count; ++k) {
      for (NodeId id : mesh.element_nodes(static_cast<std::size_t>(k))) {
        if (owner[static_cast<std::size_t>(id)] < 0) owner[static_cast<std::size_t>(id)] = static_cast<std::int32_t>(r);
      }
    }
  }
  NodeBlocks blocks;
  blocks.start.assign(records + 1, 0);
  for (std::int32_t r : owner) {
    if (r >= 0) ++blocks.start[static_cast<std::size_t>(r) + 1];
  }
  for (std::size_t r = 0; r < records; ++r) blocks.start[r + 1] += blocks.start[r];
  blocks.order.resize(blocks.start[records]);
  std::vector<std::size_t> next(blocks.start.begin(), blocks.start.end() - 1);
  for (std::size_t i = 0; i < owner.size(); ++i) {
    if (owner[i] >= 0) blocks.order[next[static_cast<std::size_t>(owner[i])]++] = static_cast<NodeId>(i);
  }
  return blocks;
}

void append_bounding_box(std::string& text, const ShapeMesh& mesh, const FaceMesh& f) {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  if (f.quad_count > 0) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::numeric_limits<double>::infinity();
      hi[a] = -std::numeric_limits<double>::infinity();
    }
    for (std::int64_t k = f.first_quad; k < f.first_quad + f.quad_count; ++k) {
      for (NodeId id : mesh.quads[static_cast<std::size_t>(k)]) {
        const Vec3& p = mesh.nodes[static_cast<std::size_t>(id)];
        const double c[3] = {p.x, p.y, p.z};
        for (int a = 0; a < 3; ++a) {
          lo[a] = std::min(lo[a], c[a]);
          hi[a] = std::max(hi[a], c[a]);
        }
      }
    }
  }
  for (double v : {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]}) {
    text += ' ';
    append_double(text, v);
  }
}

}  // namespace

void write_msh(std::ostream& out, const ShapeMesh& mesh) {
  check_shape_mesh(mesh);
  const int element_type = mesh.second_order() ? gmsh_quadratic_quad : gmsh_quad;
  std::string text = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";

  const std::size_t records = mesh.faces.size();
  if (records > 0) {
    text += "$PhysicalNames\n" + std::to_string(records) + "\n";
    for (const FaceMesh& f : mesh.faces) text += "2 " + entity_tag(f) + " \"FACE" + std::to_string(f.face) + "\"\n";
    text += "$EndPhysicalNames\n";
  }

  // Surfaces: tag, bounding box, one physical tag (the same number), no bounding curves.
  text += "$Entities\n0 0 " + std::to_string(records) + " 0\n";
  for (const FaceMesh& f : mesh.faces) {
    text += entity_tag(f);
    append_bounding_box(text, mesh, f);
    text += " 1 " + entity_tag(f) + " 0\n";
  }
  text += "$EndEntities\n";

  const NodeBlocks blocks = node_blocks(mesh);
  std::size_t node_block_count = 0;
  for (std::size_t r = 0; r < records; ++r) node_block_count += blocks.start[r + 1] > blocks.start[r] ? 1 : 0;
  const std::size_t listed = blocks.order.size();
  const auto [min_node, max_node] =
      listed == 0 ? std::pair<NodeId, NodeId>{-1, -1}
                  : std::pair<NodeId, NodeId>{*std::min_element(blocks.order.begin(), blocks.order.end()),
                                              *std::max_element(blocks.order.begin(), blocks.order.end())};
  text += "$Nodes\n" + std::to_string(node_block_count) + " " + std::to_string(listed) + " " +
          std::to_string(static_cast<std::int64_t>(min_node) + 1) + " " +
          std::to_string(static_cast<std::int64_t>(max_node) + 1) + "\n";
  for (std::size_t r = 0; r < records; ++r) {
    const std::size_t begin = blocks.start[r], end = blocks.start[r + 1];
    if (begin == end) continue;
    text += "2 " + entity_tag(mesh.faces[r]) + " 0 " + std::to_string(end - begin) + "\n";
    for (std::size_t i = begin; i < end; ++i) {
      text += std::to_string(static_cast<std::int64_t>(blocks.order[i]) + 1);
      text += '\n';
      flush_if_large(out, text);
    }
    for (std::size_t i = begin; i < end; ++i) {
      const Vec3& p = mesh.nodes[static_cast<std::size_t>(blocks.order[i])];
      append_double(text, p.x);
      text += ' ';
      append_double(text, p.y);
      text += ' ';
      append_double(text, p.z);
      text += '\n';
      flush_if_large(out, text);
    }
  }
  text += "$EndNodes\n";

  std::size_t element_block_count = 0;
  for (const FaceMesh& f : mesh.faces) element_block_count += f.quad_count > 0 ? 1 : 0;
  const std::size_t elements = mesh.quads.size();
  text += "$Elements\n" + std::to_string(element_block_count) + " " + std::to_string(elements) + " " +
          (elements == 0 ? std::string("0 0") : "1 " + std::to_string(elements)) + "\n";
  for (const FaceMesh& f : mesh.faces) {
    if (f.quad_count == 0) continue;
    text += "2 " + entity_tag(f) + " " + std::to_string(element_type) + " " + std::to_string(f.quad_count) + "\n";
    for (std::int64_t k = f.first_quad; k < f.first_quad + f.quad_count; ++k) {
      text += std::to_string(k + 1);
      for (NodeId id : mesh.element_nodes(static_cast<std::size_t>(k))) {
        text += ' ';
        text += std::to_string(static_cast<std::int64_t>(id) + 1);
      }
      text += '\n';
      flush_if_large(out, text);
    }
  }
  text += "$EndElements\n";
  flush_text(out, text);
}

void write_msh_file(const std::string& path, const ShapeMesh& mesh) {
  write_file_atomically(path, [&](std::ostream& out) { write_msh(out, mesh); });
}

}  // namespace tquad
