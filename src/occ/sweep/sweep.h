// sweep_shape: hexahedra by sweeping a source face's quad mesh through a solid.
//
// Each solid goes by the first route that fits it:
// - an extrusion or a partial revolution: two planar faces of it (the caps, source
//   and target) are the same face moved by a vector d not in their plane, or turned by
//   an angle under a full turn about an axis (the axis of a side face's circular
//   edge); every other face runs from source to target in one piece, each of its
//   edges on a cap or the path of a point (a straight segment equal to d, or an arc of
//   that angle about the axis). The layers are the source's nodes moved by k / N of
//   the motion (the exact transform);
// - a full revolution: every face turns about one axis; the solid's section by a
//   half-plane through it is the source, and the last layer is the first;
// - a one-to-one sweep (projected_sweep.h): two caps of any shape joined by side
//   faces that are each four-sided along the sweep (lofts, twisted or scaled; pipes
//   along curves); the layers are placed by least-squares projection.
// The source is meshed by the face mesher (mesh_shape, its options); the target gets
// the same quads moved, not a mesh of its own. Every hexahedron is checked (corners,
// and at second order its 27 integration points): a solid with one inverted is refused.
//
// Refused, with the reason and the faces: a revolution's profile touching its axis
// (wedges); side faces stacked along the sweep; sides that are not four-sided.
// Solids are swept one by one, in order; a cap an earlier solid swept is the source of
// a later one that has it (as that solid left it), and the nodes of a face two solids
// list at one point are joined (merge_shared_face_nodes): shared caps conform; shared
// side faces conform only where both sweeps put the same nodes (mesh.unshared_faces).
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
  // Wall seconds, summed over the solids: meshing their sources; placing the layers
  // and building and measuring the hexahedra; finding each CAD face's nodes.
  double source_seconds = 0.0, layer_seconds = 0.0, node_set_seconds = 0.0;
};

// Throws InputError when the shape has no solid, when a given source and target are
// not the caps of an extrusion, or (without keep_going) when a solid is refused; with
// keep_going a refused solid is listed in mesh.refused and the others are swept.
SweepResult sweep_shape(const TopoDS_Shape& shape, const SweepOptions& options);

}  // namespace tquad
