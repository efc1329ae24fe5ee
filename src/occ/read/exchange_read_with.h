// read_with: one of OpenCASCADE's data exchange readers (STEPControl_Reader,
// IGESControl_Reader) on a file, its failures as InputError naming the file; for
// step_reader.cpp and iges_reader.cpp.
#pragma once

#include <IFSelect_ReturnStatus.hxx>
#include <TopoDS_Shape.hxx>

#include <string>

#include "core/input_error.h"

namespace tquad {

// `explain_empty(reader)`, when given, runs before a file that transfers nothing is
// refused as such, to throw a more precise InputError (an entity that did not read).
template <typename Reader>
TopoDS_Shape read_with(Reader& reader, const std::string& path, const char* format,
                       void (*explain_empty)(Reader&, const std::string&) = nullptr) {
  try {
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) {
      throw InputError("cannot read '" + path + "' as " + format);
    }
    if (reader.TransferRoots() == 0) {
      if (explain_empty) explain_empty(reader, path);
      throw InputError("'" + path + "' holds no shape OpenCASCADE can transfer");
    }
    return reader.OneShape();
  } catch (const InputError&) {
    throw;
  } catch (...) {
    throw InputError("'" + path + "' is damaged: OpenCASCADE could not read it as " + format);
  }
}

}  // namespace tquad
