// write_all, read_exactly: whole buffers through a file descriptor (a pipe, a socket,
// a file), retried when a signal interrupts the call. False when the other end closed
// or the call failed.
#pragma once

#include <unistd.h>

#include <cerrno>
#include <cstddef>

namespace tquad {

inline bool write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

inline bool read_exactly(int fd, char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::read(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace tquad
