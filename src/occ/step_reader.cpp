#include <Interface_InterfaceModel.hxx>
#include <STEPControl_Reader.hxx>
#include <StepShape_ConnectedFaceSet.hxx>
#include <StepShape_Face.hxx>
#include <StepShape_HArray1OfFace.hxx>
#include <TCollection_HAsciiString.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include "core/input_error.h"
#include "occ/exchange_read_with.h"
#include "occ/exchange_reader.h"

namespace tquad {

namespace {

// A shell that came through the transfer but lost a face: an entity of the file that
// does not read (a damaged type name, a reference to the wrong entity, a broken line)
// drops that face, and OpenCASCADE transfers the rest without it. Random one-byte
// edits of the parts in ../shared/data/cad dropped a face in 16 of 360 edited STEP
// files, which were then meshed with a hole and exit 0; no shell of the unedited
// files lost one. Faces are checked in the shells that were transferred only, so
// representations the transfer does not reach stay out of it.
void refuse_lost_faces(STEPControl_Reader& reader, const std::string& path) {
  const Handle(Interface_InterfaceModel) model = reader.Model();
  const Handle(Transfer_TransientProcess) process = reader.WS()->TransferReader()->TransientProcess();
  if (model.IsNull() || process.IsNull()) return;
  const auto label = [&](const Handle(Standard_Transient)& entity) {
    const Handle(TCollection_HAsciiString) text = model->StringLabel(entity);
    return text.IsNull() ? std::string("#?") : std::string(text->ToCString());
  };
  for (int i = 1; i <= model->NbEntities(); ++i) {
    const auto shell = Handle(StepShape_ConnectedFaceSet)::DownCast(model->Value(i));
    if (shell.IsNull() || !process->IsBound(shell)) continue;
    const Handle(StepShape_HArray1OfFace) faces = shell->CfsFaces();
    if (faces.IsNull()) continue;
    for (int j = faces->Lower(); j <= faces->Upper(); ++j) {
      const Handle(StepShape_Face)& face = faces->Value(j);
      if (!face.IsNull() && process->IsBound(face)) continue;
      const std::string which = face.IsNull() ? "its face " + std::to_string(j - faces->Lower() + 1) + " of " +
                                                    std::to_string(faces->Length()) + " (not a face entity)"
                                              : "its face " + label(face);
      throw InputError("'" + path + "' is damaged: shell " + label(shell) + " lost " + which +
                       ", which did not read or transfer; the shape would be meshed without it");
    }
  }
}

}  // namespace

TopoDS_Shape read_step_file(const std::string& path) {
  STEPControl_Reader reader;
  const TopoDS_Shape shape = read_with(reader, path, "STEP");
  refuse_lost_faces(reader, path);
  return shape;
}

}  // namespace tquad
