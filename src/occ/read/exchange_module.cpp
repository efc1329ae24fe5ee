// The modules tquad_step.so (TQUAD_EXCHANGE_STEP defined) and tquad_iges.so: one of
// OpenCASCADE's readers behind a C entry point (exchange_module.h).
#include "occ/read/exchange_module.h"

#include <exception>
#include <type_traits>
#include <vector>

#include "core/input_error.h"
#include "occ/read/exchange_reader.h"

extern "C" __attribute__((visibility("default"))) int tquad_read_exchange_file(const char* path,
                                                                              TopoDS_Shape* shape,
                                                                              std::string* error) {
  try {
    std::vector<std::string> warnings;
#ifdef TQUAD_EXCHANGE_STEP
    *shape = tquad::read_step_file(path, &warnings);
#else
    *shape = tquad::read_iges_file(path, &warnings);
#endif
    error->clear();
    for (const std::string& w : warnings) *error += w + "\n";
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
