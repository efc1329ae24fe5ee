// read_with: one of OpenCASCADE's data exchange readers (STEPControl_Reader,
// IGESControl_Reader) on a file, its failures as InputError naming the file; for
// step_reader.cpp and iges_reader.cpp.
#pragma once

#include <IFSelect_ReturnStatus.hxx>
#include <TopoDS_Shape.hxx>

#include <string>

#include "core/input_error.h"

namespace tquad {

template <typename Reader>
TopoDS_Shape read_with(Reader& reader, const std::string& path, const char* format) {
  try {
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) {
      throw InputError("cannot read '" + path + "' as " + format);
    }
    if (reader.TransferRoots() == 0) {
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
