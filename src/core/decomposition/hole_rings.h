// ring_holes: mapped rings of quads around the holes of a planar domain.
//
// A hole's rim is where a part's stress peaks (a bolt hole, a cutout), and where the
// decomposition's cuts end: the templates' transitions (a fan of quads at a patch
// corner) would sit on the rim, at the peak. In a plate with a hole in tension
// (tests/freecad/test_fem_plate.py), a fan at the rim put CalculiX's stress
// concentration factor well above Heywood's. So each hole first gets
// `layers` rings of quads, one per rim segment, each ring as thick as the rim's local
// spacing (square quads), as FEM practice meshes a washer zone; the rest of the domain
// (the outer loop and the rings' outer loops as holes) is then decomposed as usual,
// with its transitions off the rim.
//
// A rim over kGradedRingContrast times finer than the outer loop gets graded
// rings, each kRingGrowth times as thick as the one inside it, until they reach the
// outer loop's spacing: a local size on the hole then grows outward at that rate.
//
// A hole gets fewer rings, or none, when they would not fit: a ring quad with a poor
// corner (a notch in the rim), or the rings coming within one more ring's thickness of
// another loop's points (both sides' rings included). If the domain left over is
// still not valid (a long boundary segment passing the rings), no hole gets rings.
#pragma once

#include <vector>

#include "core/decomposition/planar_domain.h"
#include "core/mesh/quad_mesh.h"

namespace tquad {

// Rings per hole, where they fit.
constexpr int kHoleRingLayers = 2;
// A hole whose rim is much finer than the outer loop (a local size on it) gets graded
// rings instead, each this many times as thick as the one inside it (the growth rate's
// default, local_sizes.h), as many as reach the outer loop's spacing, at most
// kMaxHoleRingLayers.
constexpr double kRingGrowth = 1.3;
constexpr int kMaxHoleRingLayers = 12;
// How much finer than the outer loop a rim must be for graded rings: that of a local
// size, while a hole merely refined for its curvature (a small circle's eight
// segments) keeps its two square rings.
constexpr double kGradedRingContrast = 4.0;

struct RingedDomain {
  // The domain left inside: the outer loop, and per hole its outermost ring (or the
  // hole itself when it has none), clockwise.
  PlanarDomain inner;
  // The whole mesh's numbering: the domain's points [0, P), then ring_nodes.
  std::vector<Vec3> ring_nodes;
  std::vector<Quad> ring_quads;  // counter-clockwise
  // Inner point i is whole-mesh node inner_node[i].
  std::vector<NodeId> inner_node;
  int rings = 0;  // over all holes
};

RingedDomain ring_holes(const PlanarDomain& domain, int layers = kHoleRingLayers);

// The whole domain's mesh from the rings and a mesh of `ringed.inner` (its points
// first, as every domain mesh): the domain's points first (bit-exact), then the ring
// nodes, then the inner mesh's other nodes. Quads: the rings', then the inner mesh's.
QuadMesh join_rings(const PlanarDomain& domain, const RingedDomain& ringed, const QuadMesh& inner);

}  // namespace tquad
