#include "occ/shape_reader.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "core/input_error.h"

namespace tquad {

namespace {

std::string extension_of(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void require_faces(const TopoDS_Shape& shape, const std::string& what) {
  if (shape.IsNull() || !TopExp_Explorer(shape, TopAbs_FACE).More()) {
    throw InputError(what + " holds no face to mesh");
  }
}

template <typename Reader>
TopoDS_Shape read_with(Reader& reader, const std::string& path, const char* format) {
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) {
    throw InputError("cannot read '" + path + "' as " + format);
  }
  if (reader.TransferRoots() == 0) {
    throw InputError("'" + path + "' holds no shape OpenCASCADE can transfer");
  }
  return reader.OneShape();
}

// BRepTools::Read prints to stdout when the text is not a BREP shape; a BREP starts
// with "DBRep_DrawableShape" or "CASCADE Topology V..." within its first lines.
bool looks_like_brep(std::istream& in) {
  std::string line;
  for (int i = 0; i < 5 && std::getline(in, line); ++i) {
    if (line.rfind("DBRep_DrawableShape", 0) == 0 || line.rfind("CASCADE Topology V", 0) == 0) return true;
  }
  return false;
}

}  // namespace

bool is_shape_path(const std::string& path) {
  const std::string ext = extension_of(path);
  return ext == "step" || ext == "stp" || ext == "iges" || ext == "igs" || ext == "brep" || ext == "brp";
}

TopoDS_Shape read_shape(const std::string& path) {
  if (!std::ifstream(path).good()) throw InputError("cannot open '" + path + "'");
  const std::string ext = extension_of(path);
  TopoDS_Shape shape;
  if (ext == "step" || ext == "stp") {
    STEPControl_Reader reader;
    shape = read_with(reader, path, "STEP");
  } else if (ext == "iges" || ext == "igs") {
    IGESControl_Reader reader;
    shape = read_with(reader, path, "IGES");
  } else if (ext == "brep" || ext == "brp") {
    std::ifstream header(path);
    if (!looks_like_brep(header)) throw InputError("'" + path + "' is not a BREP file (no topology header)");
    BRep_Builder builder;
    if (!BRepTools::Read(shape, path.c_str(), builder)) {
      throw InputError("cannot read '" + path + "' as BREP");
    }
  } else {
    throw InputError("'" + path + "': unknown shape format (use .step, .stp, .iges, .igs, .brep)");
  }
  require_faces(shape, "'" + path + "'");
  return shape;
}

TopoDS_Shape read_brep_text(const std::string& brep) {
  std::istringstream header(brep);
  if (!looks_like_brep(header)) throw InputError("the text is not a BREP shape (no topology header)");
  std::istringstream in(brep);
  TopoDS_Shape shape;
  BRep_Builder builder;
  BRepTools::Read(shape, in, builder);
  require_faces(shape, "the BREP text");
  return shape;
}

}  // namespace tquad
