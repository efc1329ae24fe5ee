// libFuzzer target: STEP files through the isolated reader (isolated_reader.h, its
// processes forked by reader_server.h) and the whole shape pipeline
// (shape_fuzz_check.h). Each input is written to a fresh
// temporary .step file, read as `tquad mesh` reads it, and removed.
#include <STEPControl_Reader.hxx>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/input_error.h"
#include "occ/read/descriptor_io.h"
#include "reader_server.h"
#include "shape_fuzz_check.h"

namespace {

// The input as a temporary .step file, removed when this goes out of scope.
class TemporaryStepFile {
 public:
  TemporaryStepFile(const std::uint8_t* data, std::size_t size) {
    char name[] = "/tmp/tquad-fuzz-XXXXXX.step";
    const int fd = mkstemps(name, 5);
    if (fd < 0) std::abort();
    path_ = name;
    if (!tquad::write_all(fd, reinterpret_cast<const char*>(data), size)) std::abort();
    close(fd);
  }
  ~TemporaryStepFile() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

tquad::fuzz::ReaderServer* reader = nullptr;

}  // namespace

// STEP's reader sets up its schema tables on first use, in each reader again unless
// the server has done it once before forking them (ten times fewer runs per second);
// the server is forked while this process is small (reader_server.h).
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  STEPControl_Reader warm_up;
  reader = new tquad::fuzz::ReaderServer(tquad::fuzz::fuzz_read_limits());
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const TemporaryStepFile file(data, size);
  tquad::ReadShape read;
  try {
    read = reader->read_file(file.path());
  } catch (const tquad::InputError&) {
    return 0;
  }
  tquad::fuzz::mesh_and_check(read);
  return 0;
}
