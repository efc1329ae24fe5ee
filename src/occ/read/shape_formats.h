// shape_format_of: which CAD reader a file goes to, by its extension. Free of
// OpenCASCADE so that the command can tell a CAD input from a boundary file before it
// loads the CAD layer (cli/cad_input.h).
#pragma once

#include <algorithm>
#include <cctype>
#include <string>

namespace tquad {

enum class ShapeFormat { none, step, iges, brep };

// .step/.stp, .iges/.igs, .brep/.brp in any case; none for anything else.
inline ShapeFormat shape_format_of(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos) return ShapeFormat::none;
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == "step" || ext == "stp") return ShapeFormat::step;
  if (ext == "iges" || ext == "igs") return ShapeFormat::iges;
  if (ext == "brep" || ext == "brp") return ShapeFormat::brep;
  return ShapeFormat::none;
}

// True for the extensions read_shape reads.
inline bool is_shape_path(const std::string& path) { return shape_format_of(path) != ShapeFormat::none; }

}  // namespace tquad
