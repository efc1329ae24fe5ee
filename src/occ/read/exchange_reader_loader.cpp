// read_step_file and read_iges_file through the modules tquad_step.so and
// tquad_iges.so (exchange_reader.h): a module is looked for in the folder of the module
// or program this code is linked into, and loaded at the first file of its format (and
// kept: OpenCASCADE's libraries are not made to be unloaded).
#include <dlfcn.h>

#include <stdexcept>

#include "core/input_error.h"
#include "occ/read/exchange_module.h"
#include "occ/read/exchange_reader.h"

namespace tquad {

namespace {

// The folder holding the file this function is linked into, with its last '/'.
std::string own_folder() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&own_folder), &info) == 0 || info.dli_fname == nullptr) return "";
  const std::string file = info.dli_fname;
  const auto slash = file.find_last_of('/');
  return slash == std::string::npos ? "" : file.substr(0, slash + 1);
}

// The module's entry point; `format` ("STEP", "IGES") names it in messages.
ReadExchangeEntry load_entry(const char* file, const char* format) {
  const std::string module = own_folder() + file;
  void* handle = dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw ExchangeReadersUnavailable(std::string("cannot load the ") + format + " reader (" + module +
                                     "): " + (why ? why : "unknown") + "; the installation is incomplete");
  }
  auto entry = reinterpret_cast<ReadExchangeEntry>(dlsym(handle, kExchangeEntryPoint));
  if (entry == nullptr) throw ExchangeReadersUnavailable(module + " has no " + kExchangeEntryPoint);
  return entry;
}

TopoDS_Shape read_through(const char* file, const char* format, const std::string& path,
                          std::vector<std::string>* warnings) {
  TopoDS_Shape shape;
  std::string error;
  switch (load_entry(file, format)(path.c_str(), &shape, &error)) {
    case 0: {
      std::size_t start = 0;
      for (std::size_t end; warnings && (end = error.find('\n', start)) != std::string::npos; start = end + 1) {
        warnings->push_back(error.substr(start, end - start));
      }
      return shape;
    }
    case 2: throw InputError(error);
    default: throw std::runtime_error(error);
  }
}

}  // namespace

TopoDS_Shape read_step_file(const std::string& path, std::vector<std::string>* warnings) {
  return read_through(kStepModuleFile, "STEP", path, warnings);
}
TopoDS_Shape read_iges_file(const std::string& path, std::vector<std::string>* warnings) {
  return read_through(kIgesModuleFile, "IGES", path, warnings);
}

}  // namespace tquad
