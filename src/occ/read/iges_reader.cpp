#include <IGESControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESEntity.hxx>
#include <IGESData_IGESModel.hxx>
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

#include <TCollection_HAsciiString.hxx>

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "occ/read/exchange_read_with.h"
#include "occ/read/exchange_reader.h"

namespace tquad {

namespace {

// A shell (entity 514) that lost a face: as in a STEP file (step_reader.cpp), an
// entity that does not read drops the face and the rest is transferred without it.
// Random one-byte edits of solids written as IGES by OpenCASCADE did so (a directory
// entry's sequence number, which left half a shell's faces out of it; a changed
// entity type): meshed with exit 0 and faces missing. A face reference that does not
// resolve is damage in any shell; a face without a shape counts in the shells that
// were transferred.
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
// can of it. Random one-byte edits of a solid written as IGES: a face whose
// parameters did not read gave one face too many, and a vertex list that did not
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

// The unit names IGES gives each unit flag of the global section, and the spelled-out
// names some writers use (flag 3: the name says the unit, so it is not checked here).
std::vector<std::string> unit_names(int flag) {
  switch (flag) {
    case 1: return {"IN", "INCH", "INCHES"};
    case 2: return {"MM", "MILLIMETER", "MILLIMETERS", "MILLIMETRE", "MILLIMETRES"};
    case 4: return {"FT", "FOOT", "FEET"};
    case 5: return {"MI", "MILE", "MILES"};
    case 6: return {"M", "METER", "METERS", "METRE", "METRES"};
    case 7: return {"KM", "KILOMETER", "KILOMETERS", "KILOMETRE", "KILOMETRES"};
    case 8: return {"MIL", "MILS"};
    case 9: return {"UM", "MICRON", "MICRONS", "MICROMETER", "MICROMETERS", "MICROMETRE", "MICROMETRES"};
    case 10: return {"CM", "CENTIMETER", "CENTIMETERS", "CENTIMETRE", "CENTIMETRES"};
    case 11: return {"UIN", "MICROINCH", "MICROINCHES"};
    default: return {};
  }
}

// A global section whose unit flag and unit name disagree: OpenCASCADE scales by the
// flag alone, so one damaged digit scales the shape silently. A part written by
// OpenCASCADE (flag 2, "MM") with its flag made 1 came out 25.4 times too large, and
// made 9, 1000 times too small, both meshed with exit 0 (random edits of IGES files
// find such digits). A flag outside IGES's 1 to 11 transferred nothing.
void refuse_unit_disagreement(IGESControl_Reader& reader, const std::string& path) {
  const auto model = Handle(IGESData_IGESModel)::DownCast(reader.Model());
  if (model.IsNull()) return;
  const IGESData_GlobalSection& global = model->GlobalSection();
  const int flag = global.UnitFlag();
  if (flag < 0 || flag > 11) {
    throw InputError("'" + path + "' is damaged: its global section's unit flag is " + std::to_string(flag) +
                     ", not one of IGES's units 1 to 11");
  }
  const std::vector<std::string> names = unit_names(flag);
  const Handle(TCollection_HAsciiString) given = global.UnitName();
  if (names.empty() || given.IsNull()) return;
  std::string name = given->ToCString();
  name.erase(std::remove_if(name.begin(), name.end(), [](unsigned char c) { return std::isspace(c); }), name.end());
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::toupper(c); });
  if (name.empty() || std::find(names.begin(), names.end(), name) != names.end()) return;
  throw InputError("'" + path + "' is damaged: its global section's unit flag " + std::to_string(flag) + " means " +
                   names.front() + " but its unit name is '" + given->ToCString() +
                   "'; OpenCASCADE would scale the shape by the flag");
}

// Everything that shows a file read in part or wrongly; for a file that transfers
// nothing too.
void refuse_partial_reading(IGESControl_Reader& reader, const std::string& path) {
  refuse_unit_disagreement(reader, path);
  refuse_unread_face_entities(reader, path);
}

}  // namespace

TopoDS_Shape read_iges_file(const std::string& path, std::vector<std::string>* /*warnings: none so far*/) {
  IGESControl_Reader reader;
  const TopoDS_Shape shape = read_with(reader, path, "IGES", &refuse_partial_reading);
  refuse_lost_faces(reader, path);
  refuse_partial_reading(reader, path);
  return shape;
}

}  // namespace tquad
