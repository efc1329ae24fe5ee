// The sweep's general route: a solid between two caps that are not one face moved
// exactly (a loft between similar faces, twisted or scaled; a sweep along a curve;
// curved caps), joined by side faces that are each four-sided along the sweep.
//
// Topology (find_projected_caps): every face but the caps has one wire of four
// non-degenerate edges: one on the source, the opposite one on the target, and two
// links running from a source vertex to a target vertex; one side per source edge.
//
// Placement (ProjectedPaths), at the fraction t of the sweep (arc length along the
// links; docs/design.md, "Sweeping"):
// - a point of the source's boundary, on source edge e at arc fraction s, goes on the
//   side face of e, at the transfinite interpolation in that face's (u, v) of its four
//   edges (source and target edge at the same arc fraction s, the links at t): at t = 1
//   on the target edge, between on the side surface;
// - an interior point goes where Roca and Sarrate's least-squares projection puts it:
//   (1 - t) A(x_source) + t B(x_target), A and B the least-squares affine maps of the
//   source's and the target's boundary points onto the layer's (AffineMap::fit); the
//   target's own interior points are the source's mapped the same way onto the
//   target's boundary, then put on the target's surface. Where the boundary moves
//   in no affine way (a hole that keeps its size in a tapered loft), each map's misfit
//   at the rim is carried inside by inverse-distance weights (Shepard), so nodes
//   near a loop follow it.
#pragma once

#include <TopoDS_Edge.hxx>

#include <string>
#include <vector>

#include "core/geometry/vec3.h"

namespace tquad {

class ShapeIndex;

// A side face's four edges as they occur in its wire (with the orientation that
// gives their pcurves on it), each with whether it runs, in the sweep's own
// direction (source edge and target edge from the first link to the second; links
// from source to target), as its curve's parameter grows.
struct ProjectedSide {
  int face = -1;
  int source_edge = -1;  // shape edge index
  TopoDS_Edge source, target, first_link, second_link;
  bool source_forward = true, target_forward = true, first_forward = true, second_forward = true;
};

struct ProjectedCaps {
  int source = -1, target = -1;       // shape face indices; -1: none found
  std::vector<ProjectedSide> sides;   // one per source edge
  std::string why_not;                // when none: the reason, naming a face
};

// The caps of the solid with faces `solid_faces` (shape face indices): the pair given
// (given_source >= 0), or the valid pair whose source has the most edges, planar
// caps first. Does not check that the links' shape makes hexahedra valid: the
// placement's hexahedra are checked.
ProjectedCaps find_projected_caps(const ShapeIndex& index, const std::vector<int>& solid_faces, int given_source,
                                  int given_target);

class ProjectedPaths {
 public:
  // `points`: the source mesh's points (corners and, at second order, middles);
  // `rim[i]`: whether point i lies on the source's boundary. Throws InputError when a
  // rim point lies on no source edge (farther than `tol`... from all of them).
  ProjectedPaths(const ShapeIndex& index, const ProjectedCaps& caps, const std::vector<Vec3>& points,
                 const std::vector<bool>& rim, double tol);

  double height() const { return height_; }  // the longest link
  // Every point at the fraction t of the sweep (0: the source's, 1: the target's).
  std::vector<Vec3> at(double t) const;

 private:
  struct RimPoint {
    int index = 0;     // into the points
    int side = 0;      // into sides_
    double s = 0.0;    // arc fraction along the side's source edge, in the sweep's direction
    double su = 0, sv = 0, tu = 0, tv = 0;  // (u, v) on the side of the source and target ends
  };
  struct SideFrame {
    ProjectedSide side;
    double su0 = 0, sv0 = 0, su1 = 0, sv1 = 0, tu0 = 0, tv0 = 0, tu1 = 0, tv1 = 0;  // corners (s = 0, 1)
  };
  std::vector<Vec3> rim_at(double t) const;

  const ShapeIndex& index_;
  std::vector<SideFrame> sides_;
  std::vector<RimPoint> rim_;
  std::vector<int> interior_;          // indices of the interior points
  std::vector<Vec3> source_, target_;  // every point at t = 0 and t = 1
  std::vector<Vec3> source_rim_, target_rim_;
  std::vector<int> samples_;           // rim points (into rim_) that carry the misfit inside
  double height_ = 0.0;
};

}  // namespace tquad
