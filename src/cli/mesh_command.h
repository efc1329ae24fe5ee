// run_mesh_command: the job of `tquad mesh INPUT -o OUTPUT`. Reads the boundary,
// meshes it completely, checks the mesh, and only then writes OUTPUT (through
// OUTPUT.tmp and a rename), so OUTPUT is never partial or bad.
#pragma once

#include <ostream>
#include <string>

#include "core/templates/mesher.h"
#include "occ/read/isolated_reader.h"
#include "occ/shape_mesher.h"

namespace tquad {

struct MeshCommand {
  std::string input;   // .json boundary, or a CAD shape (.step .stp .iges .igs .brep)
  std::string output;  // .json, .vtu, .inp, .msh, or (boundary input only) .svg
  bool report_json = false;  // print the JSON report instead of the human summary
  MeshOptions options;
  // CAD input only (options.templates is ignored: `options` above is used).
  ShapeMeshOptions shape;
  std::string faces;                 // --faces "0,2,5-7"
  std::vector<std::string> corners;  // --corners "FACE:V1,V2,..."
  std::vector<std::string> sizes_at;  // --size-at "face3:0.5" (local_sizes.h)
  bool progress = false;             // --progress: stages and faces on stderr
  bool verbose = false;              // --verbose: the summary lists each face's template tree
  ReadLimits read;                   // --read-timeout: the CAD reader's child process
};

// Exit status: 0 done; 2 the input (or the command line) is wrong; 1 an internal
// failure. Messages go to `err` as one line starting "tquad: error: "; the summary or
// the report goes to `out`. Never throws.
int run_mesh_command(const MeshCommand& command, std::ostream& out, std::ostream& err);

}  // namespace tquad
