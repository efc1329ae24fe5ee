// Edge discretization: every edge of the shape is cut once, by arc length on its 3D
// curve, so the faces it bounds share its nodes (a closed solid meshes watertight).
// Vertex nodes come first in the node array, then each edge's inner nodes.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/geometry/box3.h"
#include "core/mesh/quad_mesh.h"
#include "occ/face/cusp_ends.h"
#include "occ/intervals/local_sizes.h"
#include "occ/model/shape_index.h"

namespace tquad {

// The edge in its FORWARD orientation: the one its EdgeNodes run along.
TopoDS_Edge forward(const TopoDS_Edge& e);

struct EdgeNodes {
  bool degenerate = false;     // a collapsed edge (cone apex, sphere pole): one point
  double length = 0.0;
  std::vector<double> params;  // curve parameters of the nodes, first to last
  std::vector<NodeId> nodes;   // node ids along the edge's FORWARD orientation
};

// Edges whose 3D curve OpenCASCADE cannot evaluate (none, a failure, a non-finite
// point, tangent or length), that end at a vertex whose tolerance is a sizeable part
// of `box` (a gap the edges do not close), or whose curve strays far out of `box`,
// the shape's bounding box (BRepBndLib: a B-spline face's box comes from its surface,
// not its edges, so a damaged edge curve with a faraway pole can lie far out of it),
// each with the reason; a damaged file's edges. Degenerate edges are not listed.
std::map<int, std::string> unusable_edges(const ShapeIndex& index, const Box3& box);

// The fewest segments per full turn of a curve: one per 45 degrees, so that no quad
// cuts across the surface it stands for (a full circle gets at least 8 segments, a
// semicircle 4; Gmsh's default is at least 7 points per circle).
constexpr int kDefaultSegmentsPerTurn = 8;

// The fewest segments that stand for a curve turning by `turn` radians: `per_turn`
// per full turn (never under kDefaultSegmentsPerTurn), at least 1. Edges and the cuts
// of a decomposed face (face_decomposed.h) both take it.
int segments_for_turn(double turn, int per_turn = kDefaultSegmentsPerTurn);

// Per edge, `per_turn` segments per full turn of its curve's turning, at least 1 (0
// for a degenerate edge): the fewest segments that stand for its shape.
// `usable`: per edge, or empty for all; the others get 0.
std::vector<int> edge_turn_minimums(const ShapeIndex& index, const std::vector<char>& usable = {},
                                    int per_turn = kDefaultSegmentsPerTurn);

// Whether shape edge `e` is a line on face `f`'s plane: its segments are the edge
// itself, in space and in the face's (u, v) alike, whatever their count.
bool is_line_on_plane(const ShapeIndex& index, int f, int e);

// Segments of each edge from the target size: round(length / size), at least 1 and
// at least one per 45 degrees of the curve's turning; degenerate edges get 0.
std::vector<int> edge_segment_counts(const ShapeIndex& index, double size,
                                     std::vector<double>& lengths);
// The same with the turning minimums already computed (edge_turn_minimums).
std::vector<int> edge_segment_counts(const ShapeIndex& index, double size, const std::vector<int>& turn_minimums,
                                     std::vector<double>& lengths, const std::vector<char>& usable = {});

// An edge's nodes at one count: curve parameters (its ends included) and the inner
// points.
struct EdgeSpacing {
  int segments = 0;  // 0: none yet
  std::vector<double> params;
  std::vector<Vec3> inner_points;
};
// How each edge is spaced, and the spacing last computed, kept for the next
// discretization: the interval assignment's provisional one (band_balance.h) and each
// refinement round ask again for mostly the same counts, and the arc-length spacing
// is the costly part.
struct EdgeSpacings {
  // Per edge, its cusp ends' segment lengths (cusp_ends.h), or empty: all even.
  std::vector<CuspEnds> cusp_ends;
  // Per edge, its graded sizes (local_sizes.h), or empty: the uniform size. A graded
  // edge's nodes follow its size field, and its cusp ends are not lengthened.
  std::vector<EdgeSizing> grading;
  std::vector<EdgeSpacing> last;
};

// Places the nodes: vertices (nodes 0 .. vertex_count-1), then the inner nodes of each
// edge with segments[e] > 0 (edges of unmeshed faces can be given 0 and are skipped).
// Segments are even by arc length, but for a cusp end's segment (kept->cusp_ends) where
// it is longer than the even ones, and but for a graded edge's (kept->grading). With `kept`, an edge whose count is the one kept
// takes its spacing from there (the same numbers), and the others' are kept for next
// time.
std::vector<EdgeNodes> discretize_edges(const ShapeIndex& index, const std::vector<int>& segments,
                                        std::vector<Vec3>& nodes, EdgeSpacings* kept = nullptr);

}  // namespace tquad
