// The command's one policy for failures: exit status 2 and one "tquad: error: " line
// for wrong input (InputError), 1 and "internal failure" for anything else; and for
// the CAD module's entry points, the same outcome as a code (no exception crosses a
// module's edge).
#pragma once

#include <algorithm>
#include <exception>
#include <new>
#include <ostream>
#include <string>

#include "core/input_error.h"

namespace tquad {

// `text` on one line (messages are one line on stderr).
inline std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

// Runs `job` (which returns the exit status) and turns what it throws into the exit
// status and the message on `err`; `memory_advice` follows "out of memory".
template <typename Job>
int exit_status_of(const Job& job, std::ostream& err, const char* memory_advice) {
  try {
    return job();
  } catch (const InputError& e) {
    err << "tquad: error: " << one_line(e.what()) << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    err << "tquad: error: internal failure: out of memory (" << memory_advice << ")\n";
    return 1;
  } catch (const std::exception& e) {
    err << "tquad: error: internal failure: " << one_line(e.what()) << "\n";
    return 1;
  } catch (...) {
    err << "tquad: error: internal failure: unknown exception\n";
    return 1;
  }
}

// A module entry point's code for `job`: 0 done; 2 with `error` an InputError's
// message; 3 out of memory; 1 with `error` any other failure's.
template <typename Job>
int module_status_of(const Job& job, std::string& error) {
  try {
    job();
    return 0;
  } catch (const InputError& e) {
    error = e.what();
    return 2;
  } catch (const std::bad_alloc&) {
    return 3;
  } catch (const std::exception& e) {
    error = e.what();
    return 1;
  } catch (...) {
    error = "unknown exception";
    return 1;
  }
}

}  // namespace tquad
