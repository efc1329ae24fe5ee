// read_step_file, read_iges_file: a STEP or IGES file through OpenCASCADE's data
// exchange readers.
//
// Two definitions of each, chosen when a program is linked:
//   step_reader.cpp, iges_reader.cpp  call the reader (the library, the Python module,
//                                     tests, and the reader modules themselves);
//   exchange_reader_loader.cpp        loads the reader first, from the module
//                                     tquad_step.so or tquad_iges.so beside the calling
//                                     module (the command's CAD layer).
// Debian links OpenCASCADE's libraries to bind every symbol when they are loaded; the
// STEP and IGES toolkits are a large part of what the command's CAD layer loads, of its
// start time and of its memory (the IGES toolkits, with what they pull in, a good part
// of that), so the command loads them only for a STEP or IGES file, each format's
// alone, in the reader's child process (isolated_reader.h).
#pragma once

#include <TopoDS_Shape.hxx>

#include <stdexcept>
#include <string>
#include <vector>

namespace tquad {

// The readers could not be loaded (an incomplete installation): a failure of the
// program, not of the file.
class ExchangeReadersUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The file's shape (all its roots as one). Throws InputError naming the file when the
// reader cannot read it or it holds no shape the reader can transfer; the loading
// definitions throw ExchangeReadersUnavailable when the module is missing. Problems
// that take nothing out of the shape (an entity's name written as $) are appended to
// `warnings`, one line each, when it is given.
TopoDS_Shape read_step_file(const std::string& path, std::vector<std::string>* warnings = nullptr);
TopoDS_Shape read_iges_file(const std::string& path, std::vector<std::string>* warnings = nullptr);

}  // namespace tquad
