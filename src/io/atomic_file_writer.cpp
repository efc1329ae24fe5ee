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
    const bool written = static_cast<bool>(out);
    const int write_error = errno;
    out.close();
    if (!written || !out) {
      const int error = written ? errno : write_error;
      remove_quietly(temporary);
      // A full disk (ENOSPC) or a file-size limit (EFBIG; main ignores SIGXFSZ so the
      // write fails instead of killing the process) ends here.
      throw InputError("cannot write " + path + ": " + (error != 0 ? std::strerror(error) : "write failed") +
                       "; nothing was written");
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    remove_quietly(temporary);
    throw InputError("cannot rename " + temporary + " to " + path + ": " + ec.message());
  }
}

void check_output_location(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    throw InputError(path + " exists and is not a regular file; give a file name to write");
  }
  const fs::path folder = fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
  if (!fs::is_directory(folder, ec)) throw InputError("cannot write " + path + ": no folder " + folder.string());
  // The one sure test of a location (permissions do not stop root; /proc and
  // read-only file systems do): create the temporary file the writer would, and
  // remove it.
  remove_quietly(unique_temporary(path));
}

}  // namespace tquad
