// write_vtu: VTK XML UnstructuredGrid (.vtu) of a shape's quad mesh, readable by
// ParaView, VisIt and meshio. Cells are VTK_QUAD (type 9) in quad order; cell data
// "face" (Int32) is the face index of the record that owns each quad (0 for a single
// boundary region).
#pragma once

#include <ostream>
#include <string>

#include "core/mesh/shape_mesh.h"

namespace tquad {

enum class VtuEncoding {
  appended_raw,  // binary after the XML (compact and fast; the default)
  ascii,         // plain text, for reading by eye
};

// Throws std::invalid_argument for an inconsistent ShapeMesh (see shape_mesh_check.h).
void write_vtu(std::ostream& out, const ShapeMesh& mesh, VtuEncoding encoding = VtuEncoding::appended_raw);

// Writes PATH atomically (see atomic_file_writer.h).
void write_vtu_file(const std::string& path, const ShapeMesh& mesh,
                    VtuEncoding encoding = VtuEncoding::appended_raw);

}  // namespace tquad
