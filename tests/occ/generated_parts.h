// generated_part: machined parts built by OpenCASCADE's booleans, fillets and chamfers
// from a seed, for property tests on shapes nobody drew by hand: a block, a cylinder
// or a turned profile, then through and blind holes, bosses, a slot, a spherical
// dimple, fillets and chamfers on random edges. Each step that fails, or leaves an
// invalid shape, is skipped, so every part is valid to OpenCASCADE's checker as a
// whole (BRepCheck_Analyzer); a fillet may still leave a face that the mesher's
// per-face check calls damaged.
#pragma once

#include <TopoDS_Shape.hxx>

#include <cstdint>
#include <string>

namespace tquad {

TopoDS_Shape generated_part(std::uint32_t seed);

// generated_part(seed) built in a child process and written to `brep_path`: false when
// OpenCASCADE crashed building it (its fillets do, on some edge sets) or wrote
// nothing. The test process lives on either way.
bool write_generated_part(std::uint32_t seed, const std::string& brep_path);

// A solid cone from its tip at (x, y, z) (radius 5 at height 10 above it), with a hole of
// radius 1 drilled across it at height 6: its side face has a pole and a hole, a face
// the mesher refuses (not_supported), the tests' example of a refused face.
TopoDS_Shape drilled_cone(double x, double y, double z);

}  // namespace tquad
