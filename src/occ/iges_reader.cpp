#include <IGESControl_Reader.hxx>
#include <IGESData_IGESEntity.hxx>
#include <IGESGeom_Boundary.hxx>
#include <IGESGeom_BoundedSurface.hxx>
#include <IGESGeom_CurveOnSurface.hxx>
#include <IGESGeom_TrimmedSurface.hxx>
#include <IGESSolid_Face.hxx>
#include <IGESSolid_Shell.hxx>
#include <Interface_Check.hxx>
#include <Interface_InterfaceModel.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include "core/input_error.h"
#include "occ/exchange_read_with.h"
#include "occ/exchange_reader.h"

namespace tquad {

namespace {

// A shell (entity 514) that lost a face: as in a STEP file (step_reader.cpp), an
// entity that does not read drops the face and the rest is transferred without it.
// Random one-byte edits of tank.brep and the shipped bracket written as IGES by
// OpenCASCADE did so in 2 of 80 files (a directory entry's sequence number, which
// left 25 of tank's 52 faces out of its shell; an entity type 123 made 193): meshed
// with exit 0 and faces missing. A face reference that does not resolve is damage in
// any shell; a face without a shape counts in the shells that were transferred.
void refuse_lost_faces(IGESControl_Reader& reader, const std::string& path) {
  const Handle(Interface_InterfaceModel) model = reader.Model();
  const Handle(Transfer_TransientProcess) process = reader.WS()->TransferReader()->TransientProcess();
  if (model.IsNull() || process.IsNull()) return;
  for (int i = 1; i <= model->NbEntities(); ++i) {
    const auto shell = Handle(IGESSolid_Shell)::DownCast(model->Value(i));
    if (shell.IsNull()) continue;
    const bool transferred = process->IsBound(shell);
    for (int j = 1; j <= shell->NbFaces(); ++j) {
      const Handle(IGESSolid_Face) face = shell->Face(j);
      const bool lost = face.IsNull() || (transferred && TransferBRep::ShapeResult(process, face).IsNull());
      if (!lost) continue;
      throw InputError("'" + path + "' is damaged: the shell at directory entry " + std::to_string(2 * i - 1) +
                       " lost its face " + std::to_string(j) + " of " + std::to_string(shell->NbFaces()) +
                       ", which did not read or transfer; the shape would be meshed without it");
    }
  }
}

// The entities that make faces: the B-rep solids' topology (types 186 to 514) and
// the trimmed and bounded surfaces (141 to 144) that other systems write faces as.
// Curves and points are left out: their entities' display fields (a point's
// display symbol) fail to read without changing the shape.
bool makes_faces(const Handle(Standard_Transient)& entity) {
  return std::string(entity->DynamicType()->Name()).rfind("IGESSolid_", 0) == 0 ||
         entity->IsKind(STANDARD_TYPE(IGESGeom_TrimmedSurface)) ||
         entity->IsKind(STANDARD_TYPE(IGESGeom_BoundedSurface)) ||
         entity->IsKind(STANDARD_TYPE(IGESGeom_Boundary)) || entity->IsKind(STANDARD_TYPE(IGESGeom_CurveOnSurface));
}

// An entity that makes faces and did not read whole: OpenCASCADE transfers what it
// can of it. Random one-byte edits of tank.brep written as IGES (40, seed 11): a face
// whose parameters did not read gave 53 faces of 52, and a vertex list that did not
// read meshed with exit 0.
void refuse_unread_face_entities(IGESControl_Reader& reader, const std::string& path) {
  const Handle(Interface_InterfaceModel) model = reader.Model();
  if (model.IsNull()) return;
  for (int i = 1; i <= model->NbEntities(); ++i) {
    const Handle(Interface_Check)& check = model->Check(i, /*syntactic=*/true);
    if (check.IsNull() || !check->HasFailed()) continue;
    const auto entity = Handle(IGESData_IGESEntity)::DownCast(model->Value(i));
    if (entity.IsNull() || !makes_faces(entity)) continue;
    // OpenCASCADE's messages for some failures are keys it has no text for.
    const std::string why = check->CFail(1);
    throw InputError("'" + path + "' is damaged: the entity at directory entry " + std::to_string(2 * i - 1) +
                     " (type " + std::to_string(entity->TypeNumber()) + ") did not read" +
                     (why.rfind("Unknown message", 0) == 0 ? std::string() : " (" + why + ")") +
                     ": OpenCASCADE would transfer the shape without it or with a default in its place");
  }
}

}  // namespace

TopoDS_Shape read_iges_file(const std::string& path) {
  IGESControl_Reader reader;
  const TopoDS_Shape shape = read_with(reader, path, "IGES", &refuse_unread_face_entities);
  refuse_lost_faces(reader, path);
  refuse_unread_face_entities(reader, path);
  return shape;
}

}  // namespace tquad
