// Writers of swept hexahedral meshes (core/mesh/hex_mesh.h), each atomic
// (atomic_file_writer.h):
//
// - .inp (Abaqus / CalculiX): *NODE (NSET=NALL), one *ELEMENT block of C3D8 (C3D20 at
//   second order, on two lines) per swept solid (ELSET=SOLID<k>), ELSET EALL; per CAD face of a swept solid a node set
//   FACE<f> and an element surface SFACE<f> (TYPE=ELEMENT, the C3D8 faces S1..S6 on
//   it) for supports and pressures. Ids are 1-based: node k + 1 is mesh node k,
//   element k + 1 hexahedron k. Refused solids are listed as comments.
// - .vtu (VTK XML, ASCII): VTK_HEXAHEDRON (type 12) or VTK_QUADRATIC_HEXAHEDRON (25)
//   cells, cell data scaled_jacobian and solid.
// - .msh (Gmsh 4.1 ASCII): a volume entity per swept solid (tag solid + 1), its
//   nodes and its hexahedra (type 5, or 17 with Gmsh's edge order at second order).
// - .json: {"nodes": [[x, y, z], ...], "hexes": [[8 or 20 node ids], ...] (0-based),
//   "solids": [...], "refused_solids": [...], "face_nodes": {"<face>": [ids]}}.
//
// Coordinates are the shortest text that reads back to the same double (in .inp, within
// CalculiX's 20-character field).
#pragma once

#include <ostream>
#include <string>

#include "core/mesh/hex_mesh.h"

namespace tquad {

// std::invalid_argument when a hexahedron names a node the mesh lacks, or a
// coordinate is not finite: nothing is written then.
void check_hex_mesh(const HexMesh& mesh);

void write_hex_inp(std::ostream& out, const HexMesh& mesh);
void write_hex_vtu(std::ostream& out, const HexMesh& mesh);
void write_hex_json(std::ostream& out, const HexMesh& mesh);
void write_hex_msh(std::ostream& out, const HexMesh& mesh);

// By PATH's extension (.inp, .vtu, .msh, .json); InputError for another extension.
void write_hex_file(const std::string& path, const HexMesh& mesh);

// Whether PATH's extension is one write_hex_file writes.
bool is_hex_output(const std::string& path);

}  // namespace tquad
