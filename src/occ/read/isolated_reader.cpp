#include "occ/read/isolated_reader.h"

#include <BRepCheck_Analyzer.hxx>
#include <BinTools.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <sstream>

#include "core/input_error.h"
#include "occ/read/descriptor_io.h"
#include "occ/read/exchange_reader.h"
#include "occ/read/shape_formats.h"
#include "occ/read/shape_reader.h"

namespace tquad {

namespace {

// Sanitizers reserve terabytes of address space: no address-space limit under them.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kLimitAddressSpace = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kLimitAddressSpace = false;
#else
constexpr bool kLimitAddressSpace = true;
#endif
#else
constexpr bool kLimitAddressSpace = true;
#endif

// The child: reads, and writes 'S' + binary BREP, or 'E' + message (the input's fault),
// 'F' + message (the program's), 'M' (memory) or 'C' (a crash caught) to fd; never returns.
[[noreturn]] void run_reader(int fd, const std::function<TopoDS_Shape(std::vector<std::string>&)>& read,
                             const ReadLimits& limits) {
  // A crash here is only this child's death, reported by the parent: the handlers
  // the caller installed (FreeCAD's turn SIGSEGV into a C++ exception; a fuzzer's
  // write a crash report) must not run on the reader's state.
  for (const int fatal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) signal(fatal, SIG_DFL);
  // Nor may its crash be dumped: the child's pipe closes only after the dump, and
  // where the system pipes dumps to a collector the parent waits for it: a slow
  // collector delays the reply by as long as it takes, and a crash can come back as
  // the caller's read timeout instead. A process that is not dumpable is never dumped
  // (and leaves no core file).
  prctl(PR_SET_DUMPABLE, 0, 0, 0, 0);
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  // OpenCASCADE's readers print their complaints; the caller's stdout (a JSON report)
  // and stderr (one line per error) are not theirs.
  const int devnull = open("/dev/null", O_WRONLY);
  if (devnull >= 0) {
    dup2(devnull, STDOUT_FILENO);
    dup2(devnull, STDERR_FILENO);
  }
  if (kLimitAddressSpace) {
    const rlimit memory{limits.memory_bytes, limits.memory_bytes};
    setrlimit(RLIMIT_AS, &memory);
  }
  std::string message;
  try {
    std::vector<std::string> warnings;
    const TopoDS_Shape shape = read(warnings);
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    std::string invalid;
    int count = 0;
    for (int i = 1; i <= faces.Extent(); ++i) {
      if (BRepCheck_Analyzer(faces(i)).IsValid()) continue;
      invalid += " " + std::to_string(i - 1);
      ++count;
    }
    std::ostringstream out;
    BinTools::Write(shape, out);
    // The warnings, a line each, between the header and the shape.
    std::string warning_lines;
    for (std::string w : warnings) {
      std::replace(w.begin(), w.end(), '\n', ' ');
      warning_lines += w + "\n";
    }
    message = "S" + std::to_string(faces.Extent()) + " " + std::to_string(count) + invalid + " " +
              std::to_string(warnings.size()) + "\n" + warning_lines + out.str();
  } catch (const InputError& e) {
    message = std::string("E") + e.what();
  } catch (const std::bad_alloc&) {
    message = "M";
  } catch (const ExchangeReadersUnavailable& e) {
    message = std::string("F") + e.what();
  } catch (...) {
    message = "C";
  }
  _exit(write_all(fd, message.data(), message.size()) ? 0 : 3);
}

// Runs `read` in a child; `what` names the input in messages. Returns the child's
// reply when it read a shape ('S' ...); throws what read_shape_isolated throws otherwise.
std::string shape_reply_from_child(const std::function<TopoDS_Shape(std::vector<std::string>&)>& read,
                                   const std::string& what,
                                   const ReadLimits& limits) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  const pid_t parent = getpid();
  const pid_t child = fork();
  if (child < 0) {
    close(fds[0]);
    close(fds[1]);
    throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  }
  if (child == 0) {
    close(fds[0]);
    // Killed when the forking thread ends, whatever ends it (a SIGKILL of the
    // caller included); a parent already gone before the request took effect is
    // seen as a new parent process.
    prctl(PR_SET_PDEATHSIG, SIGKILL, 0, 0, 0);
    if (getppid() != parent) _exit(4);
    run_reader(fds[1], read, limits);
  }
  close(fds[1]);
  std::string payload;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limits.seconds);
  bool late = false;
  char buffer[1 << 16];
  for (;;) {
    const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) { late = true; break; }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min(left * 1000.0 + 1, 1e9)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) continue;  // the deadline is checked above
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of file: the child is done (or died)
    payload.append(buffer, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  if (late) kill(child, SIGKILL);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (late) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.3g", limits.seconds);
    throw InputError(what + ": reading did not finish within " + seconds + " s (a damaged file?)");
  }
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    throw InputError(what + " is damaged: OpenCASCADE's reader crashed on it (signal " + std::to_string(sig) + ", " +
                     strsignal(sig) + ")");
  }
  if (payload.empty() || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw InputError(what + " is damaged: OpenCASCADE's reader failed on it");
  }
  switch (payload[0]) {
    case 'E': throw InputError(payload.substr(1));
    case 'M': throw InputError(what + ": reading it needs more than the memory limit (a damaged file?)");
    case 'C': throw InputError(what + " is damaged: OpenCASCADE could not read it");
    case 'F': throw std::runtime_error(payload.substr(1));  // not the file's fault
    case 'S': return payload;
    default: throw std::logic_error("unexpected reply from the reader process");
  }
}

// The checks before a file is given to a reader process: InputError naming the file.
// Returns its size in bytes.
unsigned long long check_file_to_read(const std::string& path, const ReadLimits& limits) {
  struct stat info {};
  if (stat(path.c_str(), &info) != 0) throw InputError("cannot open '" + path + "'");
  if (!S_ISREG(info.st_mode)) throw InputError("'" + path + "' is not a regular file");
  if (static_cast<unsigned long long>(info.st_size) > limits.file_bytes) {
    throw InputError("'" + path + "' is " + std::to_string(info.st_size) + " bytes, over the limit of " +
                     std::to_string(limits.file_bytes));
  }
  if (info.st_size == 0 && is_shape_path(path)) throw InputError("'" + path + "' is empty");
  return static_cast<unsigned long long>(info.st_size);
}

}  // namespace

ReadShape decode_shape_reply(const std::string& payload) {
  // "S<faces> <invalid count> <indices...> <warning count>\n<warning lines>\n<binary BREP>"
  std::size_t line_end = payload.find('\n');
  if (payload.empty() || payload[0] != 'S' || line_end == std::string::npos) {
    throw std::logic_error("the reader process's reply has no header");
  }
  std::istringstream header(payload.substr(1, line_end - 1));
  int face_count = 0, invalid = 0;
  header >> face_count >> invalid;
  ReadShape result;
  for (int i = 0, f = 0; i < invalid && header >> f; ++i) result.invalid_faces.push_back(f);
  std::size_t warnings = 0;
  if (!(header >> warnings)) throw std::logic_error("the reader process's reply has no warning count");
  for (std::size_t i = 0; i < warnings; ++i) {
    const std::size_t start = line_end + 1;
    line_end = payload.find('\n', start);
    if (line_end == std::string::npos) throw std::logic_error("the reader process's reply lacks a warning");
    result.warnings.push_back(payload.substr(start, line_end - start));
  }
  std::istringstream in(payload.substr(line_end + 1));
  BinTools::Read(result.shape, in);
  if (result.shape.IsNull()) throw std::logic_error("the reader process's shape did not come back");
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(result.shape, TopAbs_FACE, faces);
  if (faces.Extent() != face_count) throw std::logic_error("the shape came back with another face count");
  return result;
}

std::string read_shape_reply(const std::string& path, const ReadLimits& limits) {
  const unsigned long long bytes = check_file_to_read(path, limits);
  if (!is_shape_path(path)) read_shape(path);  // throws, naming the unknown format
  ReadLimits used = limits;
  if (used.seconds <= 0) used.seconds = default_read_seconds(bytes);
  return shape_reply_from_child([&](std::vector<std::string>& warnings) { return read_shape(path, &warnings); },
                                "'" + path + "'", used);
}

std::string read_brep_text_reply(const std::string& brep, const ReadLimits& limits) {
  ReadLimits used = limits;
  if (used.seconds <= 0) used.seconds = default_read_seconds(brep.size());
  return shape_reply_from_child([&](std::vector<std::string>&) { return read_brep_text(brep); }, "the BREP text",
                                used);
}

ReadShape read_shape_isolated(const std::string& path, const ReadLimits& limits) {
  return decode_shape_reply(read_shape_reply(path, limits));
}

ReadShape read_brep_text_isolated(const std::string& brep, const ReadLimits& limits) {
  return decode_shape_reply(read_brep_text_reply(brep, limits));
}

}  // namespace tquad
