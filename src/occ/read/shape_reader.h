// read_shape: a CAD shape from a STEP, IGES or BREP file, or from BREP text (what
// FreeCAD's Shape.exportBrepToString() gives).
#pragma once

#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

#include "occ/read/shape_formats.h"  // is_shape_path

namespace tquad {

// The file's format follows its extension: .step/.stp, .iges/.igs, .brep/.brp.
// Throws InputError naming the file when it cannot be read or holds no face; what
// the reader read past without loss goes to `warnings` (exchange_reader.h).
TopoDS_Shape read_shape(const std::string& path, std::vector<std::string>* warnings = nullptr);

// Throws InputError when the text is not a BREP shape with at least one face.
TopoDS_Shape read_brep_text(const std::string& brep);

}  // namespace tquad
