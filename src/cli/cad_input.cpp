// The module tquad_cad.so: the CAD path of `tquad mesh` (cad_input.h).
#include "cli/cad_input.h"

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <chrono>
#include <exception>
#include <functional>
#include <new>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "cli/exit_status.h"
#include "cli/shape_arguments.h"
#include "core/elapsed.h"
#include "core/input_error.h"
#include "occ/read/isolated_reader.h"

namespace tquad {

namespace {

// --progress: one line per stage on `err`, and the faces meshed in tenths.
std::function<void(const MeshProgress&)> progress_printer(std::ostream& err) {
  return [&err, last_tenth = -1](const MeshProgress& p) mutable {
    if (p.stage != "mesh faces" || p.total <= 1) {
      if (p.done == 0) err << "tquad: " << p.stage << "\n";
      last_tenth = -1;
      return;
    }
    const int tenth = 10 * p.done / p.total;
    if (tenth == last_tenth) return;
    last_tenth = tenth;
    err << "tquad: mesh faces " << p.done << " of " << p.total << "\n";
  };
}

}  // namespace

CadInputMesh mesh_cad_input(const MeshCommand& command, std::ostream& err) {
  ShapeMeshOptions options = command.shape;
  options.templates = command.options;
  if (command.progress) options.progress = progress_printer(err);
  std::vector<std::string> corner_specs;
  for (const std::string& spec : command.corners) {
    if (spec == "best") {
      options.best_corners = true;
    } else {
      corner_specs.push_back(spec);
    }
  }
  options.corners = parse_corner_specs(corner_specs);
  for (const std::string& entry : command.sizes_at) options.local_sizes.push_back(parse_local_size(entry));
  check_growth_rate(options.growth_rate);
  const auto reading = std::chrono::steady_clock::now();
  const ReadShape read = read_shape_isolated(command.input, command.read);
  const double read_seconds = seconds_since(reading);
  const TopoDS_Shape& shape = read.shape;
  if (!command.faces.empty()) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    try {
      options.faces = parse_face_list(command.faces, faces.Extent());
    } catch (const InputError& e) {
      throw InputError(command.input + ": " + e.what());
    }
  }
  for (int f : read.invalid_faces) options.damaged_faces[f] = kInvalidFaceReason;
  CadInputMesh out;
  out.read_warnings = read.warnings;
  try {
    out.result = mesh_shape(shape, options);
  } catch (const FacesRefusedError& e) {
    throw InputError(command.input + ": " + e.what() + " (--keep-going meshes the other faces)");
  } catch (const InputError& e) {
    throw InputError(command.input + ": " + e.what());
  }
  // The reader's child process (file, shape check, transfer back) as a stage of its own.
  out.result.stage_seconds["read"] = read_seconds;
  // Lee-Lo is signed by each quad's own normal; the scaled Jacobian is the occ
  // layer's, each corner against the face's outer normal at that corner.
  const auto measuring = std::chrono::steady_clock::now();
  out.quality = measure_mesh_quality(out.result.mesh, std::nullopt);
  out.result.stage_seconds["quality"] = seconds_since(measuring);
  return out;
}

}  // namespace tquad

extern "C" __attribute__((visibility("default"))) int tquad_mesh_cad_input(const tquad::MeshCommand& command,
                                                                          std::ostream& err,
                                                                          tquad::CadInputMesh& out,
                                                                          std::string& error) {
  // tquad reports problems itself, one line each; OpenCASCADE's readers would print
  // their own diagnostics on stdout, which --report json keeps for the report.
  return tquad::module_status_of(
      [&] {
        Message::DefaultMessenger()->ChangePrinters().Clear();
        out = tquad::mesh_cad_input(command, err);
      },
      error);
}

// The entry point's type is checked against the loader's.
static_assert(std::is_same_v<decltype(&tquad_mesh_cad_input), tquad::MeshCadInputEntry>);
