// mesh_disk_o_grid: a disk (one smooth loop, no hole) meshed as a square in the middle
// and four mapped patches around it, the classic O-grid of a circle.
//
// Two curves with corners on a smooth circle (T5) put a quad with a corner near
// 180 - 360/n degrees at each corner, so its scaled Jacobian halves each time the mesh
// is refined. Here every boundary node has two quads, and the worst corners sit at the
// square's corners (near 135 degrees on a circle), whatever the size.
//
// The loop's points are split into four arcs of a, b, a, b segments (a + b = n / 2,
// from point 0); the square's corners lie on the segments from the centroid to the
// arcs' ends, kSquareScale of the way out; the connectors get the count that best
// fits their length at the loop's mean spacing. Every patch has equal opposite counts
// (T0). On a convex loop the square's sides bow towards the loop (kSideBow).
#pragma once

#include <optional>

#include "core/templates/mesher.h"
#include "core/decomposition/planar_domain.h"

namespace tquad {

// Where the square's corners lie, as a fraction of the way from the centroid to the
// loop (0.5 to 0.6 is usual for an O-grid of a circle).
constexpr double kSquareScale = 0.55;

// How far the square's sides bow from straight towards the loop's arcs scaled by
// kSquareScale. Straight sides leave the square's corners at 90 degrees inside and
// 135 outside (scaled Jacobian 0.707 in the patches around); a third of the way
// turns each side's ends by about 15 degrees on a circle, so both corners near 120
// (0.87), and the smoother has little left to do.
constexpr double kSideBow = 1.0 / 3;

// The mesh (the loop's points first, bit-exact), or nothing when the domain is not
// such a disk: a hole, fewer than 8 points, a sharp CAD vertex, or the square or a
// connector not inside the loop.
std::optional<QuadMesh> mesh_disk_o_grid(const PlanarDomain& domain, const MeshOptions& options = {});

}  // namespace tquad
