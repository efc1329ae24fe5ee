// The module tquad_exchange.so: OpenCASCADE's STEP and IGES readers behind one C entry
// point (exchange_module.h).
#include "occ/exchange_module.h"

#include <exception>

#include "core/input_error.h"
#include "occ/exchange_reader.h"

extern "C" __attribute__((visibility("default"))) int tquad_read_exchange_file(const char* path, int format,
                                                                              TopoDS_Shape* shape,
                                                                              std::string* error) {
  try {
    *shape = tquad::read_exchange_file(path, format == 0 ? tquad::ExchangeFormat::step : tquad::ExchangeFormat::iges);
    return 0;
  } catch (const tquad::InputError& e) {
    *error = e.what();
    return 2;
  } catch (const std::exception& e) {
    *error = e.what();
    return 1;
  } catch (...) {
    *error = "unknown exception";
    return 1;
  }
}

// The entry point's type is checked against the loader's.
static_assert(std::is_same_v<decltype(&tquad_read_exchange_file), ReadExchangeEntry>);
