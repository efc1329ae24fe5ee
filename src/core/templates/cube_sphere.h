// cube_sphere: the equiangular cube sphere, a closed all-quad mesh of the unit sphere.
//
// A closed surface around two poles (a full sphere, an ellipsoid of revolution: a
// face whose only edges are its seam and two poles) has no boundary for the templates
// to cut. Its mesh is the cube's six faces, each an m x m grid, projected onto the
// sphere with equal angles between grid lines: the cube's eight corners are the only
// irregular nodes (three quads each, corners of 120 degrees on a sphere), and no node
// sits where the quads around it would reach 180 degrees. With the poles at the
// centres of two opposite cube faces and m even, the half great circle from pole to
// pole through the centre of a side face runs along grid lines, in 2m equal angles:
// the seam of the face, whose nodes the edge discretization puts there.
#pragma once

#include <vector>

#include "core/mesh/quad_mesh.h"
#include "core/geometry/vec3.h"

namespace tquad {

struct CubeSphere {
  std::vector<Vec3> nodes;  // unit vectors
  std::vector<Quad> quads;  // counter-clockwise seen from outside the sphere
  // The 2m + 1 nodes of the half great circle y = 0, x >= 0, from the south pole
  // (0, 0, -1) to the north pole (0, 0, 1).
  std::vector<NodeId> seam;
};

// m: segments along each cube edge, even and at least 2 (std::invalid_argument
// otherwise). 6 m^2 quads, 6 m^2 + 2 nodes.
CubeSphere cube_sphere(int m);

}  // namespace tquad
