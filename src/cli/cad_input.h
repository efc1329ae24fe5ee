// mesh_cad_input: the CAD path of `tquad mesh` (read the shape, mesh its faces,
// measure the quality), in a module of its own.
//
// The command links no OpenCASCADE library: the CAD layer is the module tquad_cad.so
// (cad_input.cpp), loaded from <the program's folder>/../lib/templatequad/ only for a
// CAD input (cad_input_loader.cpp). Debian links OpenCASCADE's libraries to bind
// every symbol when they are loaded: a boundary file is meshed without that start
// (binding them all costs a program noticeable time and memory before it does
// anything), and a BREP file without the STEP and IGES readers' (occ/read/exchange_reader.h).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "cli/mesh_command.h"
#include "core/mesh/quality.h"
#include "core/mesh/shape_mesh.h"
#include "occ/shape_mesher.h"

namespace tquad {

struct CadInputMesh {
  ShapeMeshResult result;  // the mesh and the pipeline's report
  QualitySummary quality;
  std::vector<std::string> read_warnings;  // ReadShape::warnings
};

// Reads command.input in a child process (occ/read/isolated_reader.h), meshes the faces
// command.shape selects, measures the quality. Throws InputError naming the file;
// progress lines (--progress) go to `err`.
CadInputMesh mesh_cad_input(const MeshCommand& command, std::ostream& err);

// The module's file name and entry point. The entry point returns 0 with `out` set;
// 2 with `error` the InputError's message; 3 when memory ran out; 1 with `error` the
// message of any other failure. No exception crosses the module's edge.
inline constexpr const char* kCadModuleFile = "tquad_cad.so";
// A symbol of the module, which is loaded at the first call and kept; runtime_error
// when the module or the symbol is missing (an incomplete installation).
void* cad_module_symbol(const char* name);
inline constexpr const char* kCadEntryPoint = "tquad_mesh_cad_input";
using MeshCadInputEntry = int (*)(const MeshCommand& command, std::ostream& err, CadInputMesh& out,
                                  std::string& error);

}  // namespace tquad
