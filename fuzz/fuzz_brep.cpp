// libFuzzer target: BREP text through the isolated reader (isolated_reader.h, its
// processes forked by reader_server.h) and the whole shape pipeline
// (shape_fuzz_check.h). The seeds are the shipped BREP shapes; the reader runs in a
// child process, so what a damaged file does to OpenCASCADE's
// reader must come back as an InputError, and whatever the reader accepts must mesh
// or be refused cleanly in this process.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/input_error.h"
#include "reader_server.h"
#include "shape_fuzz_check.h"

namespace {
tquad::fuzz::ReaderServer* reader = nullptr;
}  // namespace

// The readers' server, forked while this process is small (reader_server.h).
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  reader = new tquad::fuzz::ReaderServer(tquad::fuzz::fuzz_read_limits());
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  tquad::ReadShape read;
  try {
    read = reader->read_brep_text(text);
  } catch (const tquad::InputError&) {
    return 0;
  }
  tquad::fuzz::mesh_and_check(read);
  return 0;
}
