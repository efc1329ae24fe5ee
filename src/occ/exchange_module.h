// The entry point of the module tquad_exchange.so (exchange_module.cpp), which
// exchange_reader_loader.cpp loads: read_exchange_file without exceptions crossing
// the module's edge.
#pragma once

#include <TopoDS_Shape.hxx>

#include <string>

// The module's file name, and the name of its entry point.
inline constexpr const char* kExchangeModuleFile = "tquad_exchange.so";
inline constexpr const char* kExchangeEntryPoint = "tquad_read_exchange_file";

// format: 0 STEP, 1 IGES. Returns 0 with *shape set; 2 with *error the InputError's
// message; 1 with *error the message of any other failure.
using ReadExchangeEntry = int (*)(const char* path, int format, TopoDS_Shape* shape, std::string* error);
