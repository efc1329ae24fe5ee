// Why a face was not meshed, as a code a front end can act on without reading the
// message: the FreeCAD workbench words its own advice per code, the CLI and the
// Python module report it beside the message.
#pragma once

#include <string>

#include "core/input_error.h"

namespace tquad {

enum class RefusalCode {
  cannot_mesh,     // no route gave a valid mesh (the message says what failed)
  inverted_quads,  // every mesh found keeps inverted quads on the surface
  too_coarse,      // too few boundary segments: a smaller element size helps
  not_supported,   // a kind of face the mesher does not handle yet
  damaged,         // the face's geometry is invalid (OpenCASCADE's checker or evaluators)
  internal,        // the mesher failed (a broken invariant, out of memory): a bug
};

// The code's name as the JSON report and the Python module spell it ("too_coarse").
inline const char* refusal_code_name(RefusalCode code) {
  switch (code) {
    case RefusalCode::cannot_mesh: return "cannot_mesh";
    case RefusalCode::inverted_quads: return "inverted_quads";
    case RefusalCode::too_coarse: return "too_coarse";
    case RefusalCode::not_supported: return "not_supported";
    case RefusalCode::damaged: return "damaged";
    case RefusalCode::internal: return "internal";
  }
  return "cannot_mesh";
}

// A face refused for a reason known more precisely than "cannot_mesh".
class FaceRefusalError : public InputError {
 public:
  FaceRefusalError(RefusalCode code, const std::string& message) : InputError(message), code_(code) {}
  RefusalCode code() const { return code_; }

 private:
  RefusalCode code_;
};

}  // namespace tquad
