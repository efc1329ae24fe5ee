// sweep_shape: hexahedra by sweeping a source face's quad mesh through a solid.
//
// A solid is swept when it is an extrusion: two planar faces of it (the caps, source
// and target) are translates of each other by a vector d not in their plane, and
// every other face is a side face running from source to target in one piece: each
// of its edges lies on a cap or is a straight segment equal to d (so there are as
// many side faces as source edges). The source face is meshed by the face mesher
// (mesh_shape, its options); the target gets the same quads moved by d, not a mesh
// of its own; the layers are the source's nodes moved by k / N of d (the exact
// transform of an extrusion), so every hexahedron is the source quad's prism and its
// scaled Jacobian is the quad's times the sine of d's angle to the cap.
//
// Not swept yet (refused, with the reason and the faces): revolutions, sweeps along
// curves and lofts; side faces split along the sweep; caps that are not planar. Solids
// are swept one by one: solids sharing a face do not share its nodes.
#pragma once

#include "core/mesh/hex_mesh.h"
#include "occ/shape_mesher.h"

class TopoDS_Shape;

namespace tquad {

struct SweepOptions {
  // The source faces' meshing: size (0: the shape's diagonal / 25), min_size, smooth,
  // threads, corners, t4_ratio... (faces and keep_going are the sweep's own).
  ShapeMeshOptions face;
  int layers = 0;                 // hexahedra through each solid; 0: round(height / size), at least 1
  int source = -1, target = -1;   // the caps (shape face indices) when given, both or neither
  bool keep_going = false;        // sweep the other solids when one is refused
};

struct SweepResult {
  HexMesh mesh;
  double size = 0.0;  // the target edge length used
};

// Throws InputError when the shape has no solid, when a given source and target are
// not the caps of an extrusion, or (without keep_going) when a solid is refused; with
// keep_going a refused solid is listed in mesh.refused and the others are swept.
SweepResult sweep_shape(const TopoDS_Shape& shape, const SweepOptions& options);

}  // namespace tquad
