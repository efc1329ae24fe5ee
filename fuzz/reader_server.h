// ReaderServer: the shape fuzz targets' readers, forked from a small process.
//
// read_shape_isolated forks a reader process per file. Forked from the fuzzing process
// (libFuzzer's tables, the sanitizers' shadow and quarantine: 120 to 240 MB resident),
// each fork copied its page tables and each reader's exit tore them down again:
// measured with perf on fuzz_step, the fork was 22% of the run and the readers' exit
// 32%, against 26% of reading. So the target forks this server once, at its start,
// while it is small, and the server forks the readers: the same reading code
// (read_shape_reply, read_brep_text_reply: limits, deadline, crash containment), the
// shape decoded in the fuzzing process as read_shape_isolated decodes it.
//
// Protocol over a socket pair: a request is a kind byte ('P' a path, 'T' BREP text),
// an 8-byte length and the bytes; a reply is a status byte ('S' the reader's reply,
// 'I' an InputError's message, 'R' any other exception's: a bug), a length and the
// bytes. The server leaves (_exit, so no leak check of a process that only forks)
// when the fuzzing process closes its end or dies.
#pragma once

#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>

#include "core/input_error.h"
#include "occ/read/descriptor_io.h"
#include "occ/read/isolated_reader.h"

namespace tquad::fuzz {

class ReaderServer {
 public:
  explicit ReaderServer(const ReadLimits& limits) {
    int fds[2];
    if (socketpair(AF_UNIX, SOCK_STREAM, 0, fds) != 0) std::abort();
    const pid_t pid = fork();
    if (pid < 0) std::abort();
    if (pid == 0) {
      close(fds[0]);
      serve(fds[1], limits);
    }
    close(fds[1]);
    socket_ = fds[0];
  }
  ReaderServer(const ReaderServer&) = delete;
  ReaderServer& operator=(const ReaderServer&) = delete;

  // As read_shape_isolated(path, limits) and read_brep_text_isolated(text, limits).
  ReadShape read_file(const std::string& path) { return ask('P', path); }
  ReadShape read_brep_text(const std::string& text) { return ask('T', text); }

 private:
  ReadShape ask(char kind, const std::string& bytes) {
    if (!send_message(socket_, kind, bytes)) std::abort();
    char status = 0;
    std::string reply;
    if (!receive_message(socket_, status, reply)) std::abort();  // the server died: a bug
    switch (status) {
      case 'S': return decode_shape_reply(reply);
      case 'I': throw InputError(reply);
      default: throw std::runtime_error(reply);
    }
  }

  [[noreturn]] static void serve(int socket, const ReadLimits& limits) {
    char kind = 0;
    std::string request;
    while (receive_message(socket, kind, request)) {
      char status = 'S';
      std::string reply;
      try {
        reply = kind == 'P' ? read_shape_reply(request, limits) : read_brep_text_reply(request, limits);
      } catch (const InputError& e) {
        status = 'I';
        reply = e.what();
      } catch (const std::exception& e) {
        status = 'R';
        reply = e.what();
      }
      if (!send_message(socket, status, reply)) break;
    }
    _exit(0);
  }

  static bool send_message(int fd, char kind, const std::string& bytes) {
    const std::uint64_t size = bytes.size();
    return write_all(fd, &kind, 1) && write_all(fd, reinterpret_cast<const char*>(&size), sizeof size) &&
           write_all(fd, bytes.data(), bytes.size());
  }

  static bool receive_message(int fd, char& kind, std::string& bytes) {
    std::uint64_t size = 0;
    if (!read_exactly(fd, &kind, 1) || !read_exactly(fd, reinterpret_cast<char*>(&size), sizeof size)) return false;
    bytes.resize(size);
    return read_exactly(fd, bytes.data(), size);
  }

  int socket_ = -1;
};

}  // namespace tquad::fuzz
