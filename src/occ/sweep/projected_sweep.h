// The sweep's general route: a solid between two caps that are not one face moved
// exactly (a loft between similar faces, twisted or scaled; a sweep along a curve;
// curved caps), joined by side faces that are each four-sided along the sweep.
//
// Topology (find_projected_caps): every face but the caps has one wire of four
// non-degenerate edges, and the sides stack in columns: from each source edge, a side
// face's opposite edge is the next side's bottom, up to an edge of the target. The
// other two edges of each side are links. Columns joined by links (around one loop of
// the caps) stack alike; each side gets a share of the layers after its links'
// length, so every edge between stacked sides is a layer of nodes.
//
// Placement (ProjectedPaths), at the fraction t of the sweep (arc length along the
// links; docs/design.md, "Sweeping"):
// - a point of the source's boundary, on source edge e at arc fraction s, goes up the
//   column of e: on the side face whose share of the layers holds t, at the
//   transfinite interpolation in that face's (u, v) of its four edges (bottom and top
//   at the same arc fraction s, the links at the fraction of that face's share): on
//   the edges between stacked sides and on the target's edge at their layers;
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

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/vec3.h"

namespace tquad {

class ShapeIndex;

// One side face of a column: its four edges as they occur in its wire (with the
// orientation that gives their pcurves on it), each with whether it runs, in the
// sweep's own direction (bottom and top from the first link to the second; links
// from the source's side to the target's), as its curve's parameter grows.
struct ProjectedBand {
  int face = -1;
  TopoDS_Edge bottom, top, first_link, second_link;
  bool bottom_forward = true, top_forward = true, first_forward = true, second_forward = true;
  double length = 0.0;  // its longer link
};

// The side faces stacked from one source edge to the target, bottom first.
struct ProjectedColumn {
  int source_edge = -1;              // shape edge index
  std::vector<ProjectedBand> bands;
  int group = 0;                     // columns joined by their links (a loop of the caps)
};

struct ProjectedCaps {
  int source = -1, target = -1;       // shape face indices; -1: none found
  std::vector<ProjectedColumn> columns;  // one per source edge
  int groups = 0;
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
  // rim point lies on none of the source's edges.
  ProjectedPaths(const ShapeIndex& index, const ProjectedCaps& caps, const std::vector<Vec3>& points,
                 const std::vector<bool>& rim, double tol);

  // The layers for edge length `size`: per group, each side's links' length over the
  // size (at least 1); the most any group needs.
  int layers_for(double size) const;
  // Shares `layers` among each group's stacked sides, after their lengths (each at
  // least 1). Throws InputError when a group has more sides stacked than layers.
  void set_layers(int layers);
  double height() const { return height_; }  // the longest stack of links

  // Every point at layer position k (0 to the layers; k + 0.5 between two layers):
  // 0 the source's points, the last layer the target's.
  std::vector<Vec3> at(double k) const;
  // The side faces (shape indices) that point i lies on at layer position k: none for
  // an interior point, two for one at a vertex of the source's edges.
  std::vector<int> faces_at(int point, double k) const;

 private:
  struct OnColumn {
    int column = 0;
    double s = 0.0;  // arc fraction along its bottom edges, in the sweep's direction
    // Per band, the (u, v) on it of the point's bottom and top.
    std::vector<std::array<double, 4>> ends;
  };
  struct RimPoint {
    int index = 0;                  // into the points
    std::vector<OnColumn> columns;  // the first places it; a vertex lies on two
  };
  struct BandFrame {
    double u[4] = {0, 0, 0, 0}, v[4] = {0, 0, 0, 0};  // bottom at s = 0, 1; top at s = 0, 1
  };
  // Which band of `column` holds layer position k, and the fraction through it.
  std::pair<int, double> band_at(int column, double k) const;
  std::vector<Vec3> rim_at(double k) const;

  const ShapeIndex& index_;
  ProjectedCaps caps_;
  std::vector<std::vector<BandFrame>> frames_;  // per column, per band
  std::vector<std::vector<int>> starts_;        // per group, the layer each band starts at (and the end)
  int layers_ = 0;
  std::vector<RimPoint> rim_;
  std::vector<int> rim_of_;            // per point, its place in rim_, or -1
  std::vector<int> interior_;          // indices of the interior points
  std::vector<Vec3> source_, target_;  // every point at the first and the last layer
  std::vector<Vec3> source_rim_, target_rim_;
  std::vector<int> samples_;           // rim points (into rim_) that carry the misfit inside
  double height_ = 0.0;
};

}  // namespace tquad
