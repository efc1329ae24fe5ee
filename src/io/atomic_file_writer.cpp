#include "io/atomic_file_writer.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include <sys/stat.h>
#include <unistd.h>
#include <cstdlib>

#include "core/input_error.h"

namespace tquad {

namespace {

void remove_quietly(const std::string& path) {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

// A new file next to `path` with a name no other writer has (mkstemp: O_EXCL), with
// the permissions a plain new file would get; returns its name.
std::string unique_temporary(const std::string& path) {
  std::string name = path + ".tmp.XXXXXX";
  const int fd = mkstemp(name.data());
  if (fd < 0) throw InputError("cannot create a file next to " + path + ": " + std::strerror(errno));
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  close(fd);
  return name;
}

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const std::string temporary = unique_temporary(path);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw InputError("cannot create " + temporary + ": " + std::strerror(errno));
    }
    try {
      write(out);
    } catch (...) {
      out.close();
      remove_quietly(temporary);
      throw;
    }
    out.flush();
    out.close();
    if (!out) {
      const int error = errno;
      remove_quietly(temporary);
      throw InputError("cannot write " + temporary + ": " +
                       (error != 0 ? std::strerror(error) : "write failed"));
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    remove_quietly(temporary);
    throw InputError("cannot rename " + temporary + " to " + path + ": " + ec.message());
  }
}

}  // namespace tquad
