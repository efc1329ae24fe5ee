#include <IGESControl_Reader.hxx>

#include "occ/exchange_read_with.h"
#include "occ/exchange_reader.h"

namespace tquad {

TopoDS_Shape read_iges_file(const std::string& path) {
  IGESControl_Reader reader;
  return read_with(reader, path, "IGES");
}

}  // namespace tquad
