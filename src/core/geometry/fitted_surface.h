// FittedSurface: the surface a curved 3D loop's mesh spans, for smoothing a region
// that comes with no surface of its own (points given to the CLI or the Python
// module).
//
// The templates put the interior nodes on transfinite maps of the loop (paper, eqs.
// 3 and 4): that surface is the one the user gets unsmoothed, so smoothing keeps the
// nodes on it rather than on another surface through the loop. (A mean value
// interpolation of the loop's heights, tried first, pulled the middle of a sphere
// octant's mesh from radius 0.90 to 0.76.) Over the loop's mean plane (its Newell
// normal), each interior node moves on the quadric of heights fitted by least squares
// to the nodes of the quads around it, through its own starting point: second-order
// exact on a smooth surface, so a node moved by a fraction of an edge stays on the
// templates' surface to far less than an edge's length. Where the nodes around it
// cannot determine a quadric (fewer than five, or on one line), a plane. Each node
// moves on its own fit, made once: the surface does not drift as nodes move.
#pragma once

#include <vector>

#include "core/geometry/mean_plane.h"
#include "core/mesh/quad_mesh.h"

namespace tquad {

class FittedSurface {
 public:
  // Heights over `plane` (MeanPlane::of_loop) of a mesh whose first `loop_points`
  // nodes are its loop.
  FittedSurface(const MeanPlane& plane, int loop_points) : plane_(plane), first_interior_(loop_points) {}

  // Fits the nodes [loop points, nodes) of a mesh whose first nodes are the loop's
  // points, each to the nodes of its quads.
  void fit_nodes(const std::vector<Vec3>& nodes, const std::vector<Quad>& quads);

  const MeanPlane& plane() const { return plane_; }

  // Node `node` (an interior one) at plane coordinates `param` on its fit, and the
  // fit's normal there (oriented as the loop, any length).
  bool place(int node, const Vec3& param, Vec3& position, Vec3& normal) const;

 private:
  // height = at.z + a dx + b dy + c dx^2 + d dx dy + e dy^2, (dx, dy) from (at.x, at.y).
  struct Quadric {
    Vec3 at;
    double a = 0, b = 0, c = 0, d = 0, e = 0;
  };
  static Quadric fit(const Vec3& at, const std::vector<Vec3>& around);

  MeanPlane plane_;
  int first_interior_ = 0;
  std::vector<Quadric> fits_;  // node first_interior_ + i at fits_[i]
};

}  // namespace tquad
