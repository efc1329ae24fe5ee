// read_exchange_file calling the readers directly (exchange_reader.h).
#include "occ/exchange_reader.h"

namespace tquad {

TopoDS_Shape read_exchange_file(const std::string& path, ExchangeFormat format) {
  return format == ExchangeFormat::step ? read_step_file(path) : read_iges_file(path);
}

}  // namespace tquad
