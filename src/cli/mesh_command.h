// run_mesh_command: the job of `tquad mesh INPUT -o OUTPUT`. Reads the boundary,
// meshes it completely, checks the mesh, and only then writes OUTPUT (through
// OUTPUT.tmp and a rename), so OUTPUT is never partial or bad.
#pragma once

#include <ostream>
#include <string>

#include "core/mesher.h"

namespace tquad {

struct MeshCommand {
  std::string input;   // .json boundary (CAD extensions are refused for now)
  std::string output;  // .json, .vtu or .svg
  bool report_json = false;  // print the JSON report instead of the human summary
  MeshOptions options;
};

// Exit status: 0 done; 2 the input (or the command line) is wrong; 1 an internal
// failure. Messages go to `err` as one line starting "tquad: error: "; the summary or
// the report goes to `out`. Never throws.
int run_mesh_command(const MeshCommand& command, std::ostream& out, std::ostream& err);

}  // namespace tquad
