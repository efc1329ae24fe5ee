// Text output helpers shared by the text mesh writers (.json, .inp, .msh): the
// shortest text of a double that reads back to the same value, and writing a large
// file in chunks (neither one huge string nor many tiny writes).
#pragma once

#include <ostream>
#include <string>

namespace tquad {

// Appends the shortest round-trip text of `value` (std::to_chars without a precision,
// e.g. "0.1", "1e-07", "-0", "3"). The writers call it on a ShapeMesh that passed
// check_shape_mesh, which refuses NaN and infinite coordinates (no mesh file format
// here can express them).
void append_double(std::string& text, double value);

// Writes `text` to `out` and clears it once it holds more than about 1 MiB.
void flush_if_large(std::ostream& out, std::string& text);

// Writes all of `text` to `out` and clears it.
void flush_text(std::ostream& out, std::string& text);

}  // namespace tquad
