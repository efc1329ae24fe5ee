// mesh_cad_input in the command: loads the module tquad_cad.so (cad_input.h) from
// <the program's folder>/../lib/templatequad/ and calls it. The module stays loaded
// until the process ends (OpenCASCADE's libraries are not made to be unloaded).
#include <dlfcn.h>
#include <unistd.h>

#include <climits>
#include <new>
#include <stdexcept>

#include "cli/cad_input.h"
#include "core/input_error.h"

namespace tquad {

namespace {

// Where the modules are, relative to the program's folder (the build tree and the
// installation lay them out alike: bin/tquad, lib/templatequad/).
constexpr const char* kModuleFolder = "/../lib/templatequad/";

std::string program_folder() {
  char path[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
  if (n <= 0) throw std::runtime_error("cannot find the program's own file (/proc/self/exe)");
  const std::string file(path, static_cast<std::size_t>(n));
  return file.substr(0, file.find_last_of('/'));
}

}  // namespace

void* cad_module_symbol(const char* name) {
  const std::string module = program_folder() + kModuleFolder + kCadModuleFile;
  void* handle = dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error("cannot load the CAD layer (" + module + "): " + (why ? why : "unknown") +
                             "; the installation is incomplete");
  }
  void* symbol = dlsym(handle, name);
  if (symbol == nullptr) throw std::runtime_error(module + " has no " + name);
  return symbol;
}

CadInputMesh mesh_cad_input(const MeshCommand& command, std::ostream& err) {
  const auto entry = reinterpret_cast<MeshCadInputEntry>(cad_module_symbol(kCadEntryPoint));
  CadInputMesh out;
  std::string error;
  switch (entry(command, err, out, error)) {
    case 0: return out;
    case 2: throw InputError(error);
    case 3: throw std::bad_alloc();
    default: throw std::runtime_error(error);
  }
}

}  // namespace tquad
