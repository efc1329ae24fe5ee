// run_sweep_command: the job of `tquad sweep INPUT -o OUTPUT`: every solid of a CAD
// shape that is an extrusion becomes hexahedra (occ/sweep/sweep.h), written as .inp
// (C3D8), .vtu or .json only when the whole job succeeded. The CAD work runs in the
// module tquad_cad.so, as `tquad mesh`'s does (cad_input.h).
#pragma once

#include <ostream>
#include <string>

#include "core/mesh/hex_mesh.h"
#include "occ/read/isolated_reader.h"
#include "occ/sweep/sweep.h"

namespace tquad {

struct SweepCommand {
  std::string input;   // a CAD shape (.step .stp .iges .igs .brep)
  std::string output;  // .inp, .vtu or .json
  bool report_json = false;
  SweepOptions sweep;  // sweep.face: the source faces' meshing options
  ReadLimits read;
};

struct SweepOutput {
  HexMesh mesh;
  double size = 0.0;
  std::vector<std::string> read_warnings;
  // Wall seconds: reading (in its child process), then sweep_shape's stages.
  double read_seconds = 0.0, source_seconds = 0.0, layer_seconds = 0.0, node_set_seconds = 0.0;
};

// Exit status as run_mesh_command's: 0 done, 2 the input or the command line is
// wrong, 1 an internal failure; one "tquad: error: " line on `err`. Never throws.
int run_sweep_command(const SweepCommand& command, std::ostream& out, std::ostream& err);

// The module's entry point (sweep_input.cpp): 0 with `out` set; 2 with `error` an
// InputError's message; 3 out of memory; 1 any other failure.
inline constexpr const char* kSweepEntryPoint = "tquad_sweep_cad_input";
using SweepCadInputEntry = int (*)(const SweepCommand& command, SweepOutput& out, std::string& error);

}  // namespace tquad
