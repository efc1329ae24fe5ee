// read_boundary_json: the `.json` boundary input of the CLI (docs/design.md,
// "Public contracts"): {"points": [[x, y, z], ...], "corners": [i, ...]}. A point
// may also be [x, y] (z = 0). Other keys are ignored.
#pragma once

#include <string>

#include "core/geometry/boundary_loop.h"

namespace tquad {

// Reads and checks the file's structure (not the geometry: that is
// validate_boundary's job). Throws InputError with a message that starts with the
// file path and says what is wrong where, e.g. "b.json: points[12] has 4 coordinates".
BoundaryLoop read_boundary_json(const std::string& path);

// The same for JSON text already in memory; `source_name` starts the messages.
BoundaryLoop parse_boundary_json(const std::string& text, const std::string& source_name);

}  // namespace tquad
