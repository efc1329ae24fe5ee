#include <STEPControl_Reader.hxx>

#include "occ/exchange_read_with.h"
#include "occ/exchange_reader.h"

namespace tquad {

TopoDS_Shape read_step_file(const std::string& path) {
  STEPControl_Reader reader;
  return read_with(reader, path, "STEP");
}

}  // namespace tquad
