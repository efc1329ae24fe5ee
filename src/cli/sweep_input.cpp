// The module tquad_cad.so: the CAD path of `tquad sweep` (sweep_command.h).
#include <Message.hxx>
#include <Message_Messenger.hxx>

#include <chrono>
#include <new>
#include <string>
#include <type_traits>

#include "cli/exit_status.h"
#include "cli/sweep_command.h"
#include "core/elapsed.h"
#include "core/input_error.h"
#include "occ/read/isolated_reader.h"

namespace tquad {
namespace {

SweepOutput sweep_cad_input(const SweepCommand& command) {
  const auto start = std::chrono::steady_clock::now();
  const ReadShape read = read_shape_isolated(command.input, command.read);
  const double read_seconds = seconds_since(start);
  SweepOptions options = command.sweep;
  for (int f : read.invalid_faces) options.face.damaged_faces[f] = kInvalidFaceReason;
  SweepOutput out;
  out.read_warnings = read.warnings;
  out.read_seconds = read_seconds;
  try {
    SweepResult result = sweep_shape(read.shape, options);
    out.mesh = std::move(result.mesh);
    out.size = result.size;
    out.source_seconds = result.source_seconds;
    out.layer_seconds = result.layer_seconds;
    out.node_set_seconds = result.node_set_seconds;
  } catch (const InputError& e) {
    // A solid's refusal ("solid 2 ...") stops the job only without --keep-going.
    const bool solid_refused = std::string(e.what()).rfind("solid ", 0) == 0;
    throw InputError(command.input + ": " + e.what() +
                     (solid_refused && !options.keep_going ? " (--keep-going sweeps the other solids)" : ""));
  }
  return out;
}

}  // namespace
}  // namespace tquad

extern "C" __attribute__((visibility("default"))) int tquad_sweep_cad_input(const tquad::SweepCommand& command,
                                                                           tquad::SweepOutput& out,
                                                                           std::string& error) {
  return tquad::module_status_of(
      [&] {
        Message::DefaultMessenger()->ChangePrinters().Clear();
        out = tquad::sweep_cad_input(command);
      },
      error);
}

static_assert(std::is_same_v<decltype(&tquad_sweep_cad_input), tquad::SweepCadInputEntry>);
