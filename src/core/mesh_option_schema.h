// The options of meshing a shape, declared once for every front end.
//
// Each row names one option as the command line (`tquad mesh`), Python
// (`tquad.mesh_shape`) and the FreeCAD mesh object know it, with its Python type and
// default and the text that explains it. The command's help and Python's docstring
// take their text from here, Python's stub (`__init__.pyi`) is generated from it
// (scripts/generate_stubs.py), and tests fail when a front end lacks an option of
// the schema or has one the schema does not list (tests/cli/test_option_schema.cpp,
// tests/python/test_option_schema.py, tests/freecad/test_workbench.py).
#pragma once

#include <string>
#include <vector>

namespace tquad {

struct MeshOptionField {
  std::string name;     // Python keyword of mesh_shape, snake_case
  std::string flag;     // tquad mesh's option ("--size"); "" when the command has none
  std::string freecad;  // the FreeCAD mesh object's property; "" when FreeCAD sets it
  std::string type;     // Python annotation of the keyword
  std::string python_default;  // the keyword's default, as Python writes it
  std::string help;     // what it does, the same words in every front end
};

// In the order of mesh_shape's keywords.
const std::vector<MeshOptionField>& mesh_option_schema();

// The row of `name`; std::out_of_range when the schema has none (a front end naming
// an option the schema lacks is a programming error).
const MeshOptionField& mesh_option(const std::string& name);

// `text` wrapped at `width` columns (words kept whole), lines joined by '\n'.
std::string wrap_text(const std::string& text, std::size_t width);

}  // namespace tquad
