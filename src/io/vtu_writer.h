// write_vtu: VTK XML UnstructuredGrid (.vtu) of a quad mesh, readable by ParaView,
// VisIt and meshio. Cells are VTK_QUAD (type 9); cell data "face" (Int32) is the face
// each quad belongs to (0 for a single boundary region).
#pragma once

#include <ostream>
#include <string>

#include "core/quad_mesh.h"

namespace tquad {

enum class VtuEncoding {
  appended_raw,  // binary after the XML (compact and fast; the default)
  ascii,         // plain text, for reading by eye
};

void write_vtu(std::ostream& out, const QuadMesh& mesh, VtuEncoding encoding = VtuEncoding::appended_raw);

// Writes PATH atomically (see atomic_file_writer.h).
void write_vtu_file(const std::string& path, const QuadMesh& mesh,
                    VtuEncoding encoding = VtuEncoding::appended_raw);

}  // namespace tquad
