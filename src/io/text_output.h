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
// The integer's decimal digits (std::to_chars: no allocation).
void append_integer(std::string& text, long long value);

// The same, in at most `width` characters: the shortest round-trip text when it fits,
// else the most significant digits that fit (CalculiX reads a field of at most 20
// characters, and "-4.269692791533339e-15" has 22).
void append_double_within(std::string& text, double value, int width);

// CalculiX's widest field.
inline constexpr int kInpFieldWidth = 20;

// Writes `text` to `out` and clears it once it holds more than about 1 MiB.
void flush_if_large(std::ostream& out, std::string& text);

// Writes all of `text` to `out` and clears it.
void flush_text(std::ostream& out, std::string& text);

}  // namespace tquad
