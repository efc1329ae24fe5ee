// The entry point of the modules tquad_step.so and tquad_iges.so (exchange_module.cpp,
// built once for each format), which exchange_reader_loader.cpp loads: the format's
// reader without exceptions crossing the module's edge.
#pragma once

#include <TopoDS_Shape.hxx>

#include <string>

// The modules' file names, and the name of their entry point.
inline constexpr const char* kStepModuleFile = "tquad_step.so";
inline constexpr const char* kIgesModuleFile = "tquad_iges.so";
inline constexpr const char* kExchangeEntryPoint = "tquad_read_exchange_file";

// Returns 0 with *shape set and *error the reader's warnings, one per line (empty when
// none); 2 with *error the InputError's message; 1 with *error the message of any
// other failure.
using ReadExchangeEntry = int (*)(const char* path, TopoDS_Shape* shape, std::string* error);
