// write_msh: a Gmsh MSH 4.1 ASCII file (.msh) of a shape's quad mesh, read by Gmsh,
// meshio and the solvers that take Gmsh meshes:
//   - $MeshFormat 4.1 0 8;
//   - $PhysicalNames and $Entities: one surface (dimension 2) per face record, entity
//     tag = face index + 1, in the physical surface of the same tag named "FACE<k>"
//     (the name of the face's element set in the .inp file), bounding box = its quads'
//     nodes; no points, curves or volumes;
//   - $Nodes: node tag = ShapeMesh node index + 1. Each node is listed once, in the
//     block of the first face record whose quads use it (faces share their common
//     boundary nodes, so the mesh stays conforming); nodes no quad uses are left out
//     (node tags may then have gaps, which MSH 4.1 allows);
//   - $Elements: one block of 4-node quadrangles (type 3) per face record, element tag
//     = ShapeMesh quad index + 1 (continuous from 1), nodes in the quad's order.
// Coordinates are the shortest text that reads back to the same double. A face record
// with no quads is an entity without node or element block.
#pragma once

#include <ostream>
#include <string>

#include "core/mesh/shape_mesh.h"

namespace tquad {

// Throws std::invalid_argument for an inconsistent ShapeMesh (see shape_mesh_check.h)
// and std::logic_error for a non-finite coordinate.
void write_msh(std::ostream& out, const ShapeMesh& mesh);

// Writes PATH atomically (see atomic_file_writer.h).
void write_msh_file(const std::string& path, const ShapeMesh& mesh);

}  // namespace tquad
