#include "occ/exchange_reader.h"

#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>

#include "core/input_error.h"

namespace tquad {

namespace {

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

}  // namespace

TopoDS_Shape read_exchange_file(const std::string& path, ExchangeFormat format) {
  if (format == ExchangeFormat::step) {
    STEPControl_Reader reader;
    return read_with(reader, path, "STEP");
  }
  IGESControl_Reader reader;
  return read_with(reader, path, "IGES");
}

}  // namespace tquad
