// Element quality of quads: the Lee-Lo shape metric (paper, eq. 7) and the scaled
// Jacobian, with their min / average / max / standard deviation over a mesh.
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "core/mesh/quad_mesh.h"
#include "core/mesh/shape_mesh.h"

namespace tquad {

// Lee-Lo: split the quad at each corner i into the triangle (P[i-1], P[i], P[i+1])
// and take its shape measure alpha = 2 sqrt(3) area / (sum of squared edge lengths)
// (1 for an equilateral triangle, signed by the normal); sorted a1 >= a2 >= a3 >= a4,
// beta = (a3 a4) / (a1 a2). A rectangle scores 1. A quad with a corner triangle of
// zero or negative area (degenerate or inverted) scores a4 / a1 <= 0 instead.
double lee_lo_quality(const std::array<Vec3, 4>& quad, const Vec3& normal);

// Minimum over the corners of (e_next x e_prev) . n / (|e_next| |e_prev|): 1 for a
// rectangle, 0 for a 180-degree corner, negative for an inverted corner.
double scaled_jacobian(const std::array<Vec3, 4>& quad, const Vec3& normal);

// The same at corner i alone, signed by `normal` (any length): -1 when a side at the
// corner has zero length, 0 when the normal is zero.
double corner_scaled_jacobian(const std::array<Vec3, 4>& quad, int i, const Vec3& normal);

// All four corners of a quad at once (each edge measured once), each signed by its
// own node's normal: unit_normal[i] of unit length, or zero (then the quad's own
// normal, the cross product of its diagonals, stands in). The same values as
// corner_scaled_jacobian, and whether the quad is_collapsed. The smoother needs both
// signings of every corner it decides, so both come from one pass over the edges.
struct QuadCorners {
  std::array<double, 4> jacobian;
  std::array<double, 4> own_jacobian;  // each corner signed by the quad's own normal
  bool collapsed = false;
  double edge_ratio = 1.0;  // shortest edge over longest (0 when all edges are 0)
};
QuadCorners quad_corners(const std::array<Vec3, 4>& quad, const std::array<Vec3, 4>& unit_normal);

// quad_corners of a mesh's quad: its nodes' positions and unit normals looked up.
inline QuadCorners quad_corners(const Quad& quad, const std::vector<Vec3>& position,
                                const std::vector<Vec3>& unit_normal) {
  std::array<Vec3, 4> p, n;
  for (int i = 0; i < 4; ++i) {
    p[i] = position[quad[i]];
    n[i] = unit_normal[quad[i]];
  }
  return quad_corners(p, n);
}

// quad_corners of a quad in the z = 0 plane, every corner signed by +z: only the z
// components of the cross products are computed. The same values (zeros' signs aside;
// a test compares the two), for the smoother of planar regions, where quad_corners
// took a large share of the boundary route's time on large meshes.
QuadCorners planar_quad_corners(const std::array<Vec3, 4>& quad);

struct QualityStats {
  double min = 0, avg = 0, max = 0, std = 0;
};

// A straight-angle corner computes to a scaled Jacobian within rounding of 0, either
// sign: values in [-kInvertedBelow, kDegenerateUpTo] count as degenerate, below as
// inverted.
constexpr double kInvertedBelow = 1e-9;
// On a curved surface, a corner straight in the face's chart is measured against the
// surface normal at its node, which the chart and the edges' tolerance fix to about
// that much (straight corners on cylinder faces come out slightly negative, down to
// nearly -1e-3): values in [-kSurfaceInvertedBelow, 0) are straight angles, degenerate,
// not folds.
constexpr double kSurfaceInvertedBelow = 1e-3;
constexpr double kDegenerateUpTo = 1e-6;

// A quad is collapsed, a triangle in effect, when the smallest of its corner areas
// |e_i x e_(i-1)| (the Jacobian determinant of its bilinear map at the corners) is
// under this fraction of the largest: the Jacobian ratio that finite element codes
// check. Its corners' scaled Jacobians can all look fine (a side far shorter than
// the one facing it, next to a CAD edge far shorter than the size), so it is judged
// apart. A thin rectangle is not collapsed: a face narrower than the size (a strip)
// can only be meshed with such quads, and their Jacobian is even.
constexpr double kCollapsedAreaRatio = 1e-3;
bool is_collapsed(const std::array<Vec3, 4>& quad);

// The quad's scaled Jacobian against its own normal, the cross product of its
// diagonals: what any reader of the mesh measures, with no surface at hand.
double own_scaled_jacobian(const std::array<Vec3, 4>& quad);

// The one policy for quads unfit for analysis: a corner at or below kDegenerateUpTo
// against the surface normal (`surface_worst`: the quad's lowest corner so measured)
// or against its own normal (own_scaled_jacobian). A solver's Jacobian vanishes or
// changes sign in such a quad, whichever normal shows it: a quad folded across a
// curved surface can keep every corner positive against the surface's normals and not
// against its own, and a 180-degree corner at a pole shows against its own normal
// alone. A collapsed quad (is_collapsed) is bad too: a solver's Jacobian varies a
// thousandfold across it.
bool is_bad_quad(const std::array<Vec3, 4>& quad, double surface_worst);

// Histogram of the scaled Jacobian: bin 0 counts the quads below 0 (inverted, or a
// straight angle by rounding), bins 1 to 10 the tenths [0, 0.1), ..., [0.9, 1].
constexpr int kJacobianBins = 11;
int jacobian_bin(double scaled_jacobian);

struct QualitySummary {
  QualityStats lee_lo;
  QualityStats scaled_jacobian;
  std::array<long long, kJacobianBins> jacobian_histogram{};
  long long inverted = 0;    // quads with a scaled Jacobian below -kInvertedBelow
  long long degenerate = 0;  // quads with a scaled Jacobian in [-kInvertedBelow, kDegenerateUpTo]
  long long collapsed = 0;   // collapsed quads (is_collapsed)
};

// Normal used to sign the metrics: `reference` for every quad when given (a planar
// region), otherwise each quad's own normal, the cross product of its diagonals.
QualitySummary summarize_quality(const QuadMesh& mesh, const std::optional<Vec3>& reference);
QualitySummary summarize_quality(const std::vector<Vec3>& nodes, const std::vector<Quad>& quads,
                                 const std::optional<Vec3>& reference);

// Lee-Lo, the scaled Jacobian and is_collapsed of one quad, signed by `normal` (any
// length), from one pass over its edges: the same values, bit for bit, as
// lee_lo_quality, scaled_jacobian and is_collapsed, which measure each side two or
// three times (a cost that shows in the quality stage of large meshes).
struct QuadQuality {
  double lee_lo = 0, scaled_jacobian = 0;
  bool collapsed = false;
};
QuadQuality quad_quality(const std::array<Vec3, 4>& quad, const Vec3& normal);

// Each quad's Lee-Lo and scaled Jacobian, signed as summarize_quality signs them, and
// the number of collapsed quads.
struct PerQuadQuality {
  std::vector<double> lee_lo, scaled_jacobian;
  long long collapsed = 0;
};
PerQuadQuality per_quad_quality(const std::vector<Vec3>& nodes, const std::vector<Quad>& quads,
                                const std::optional<Vec3>& reference);

// The summary of values per_quad_quality gave.
QualitySummary summarize_quality(const PerQuadQuality& per_quad);

// The quality a user looks at, the same for every front end: fills mesh.lee_lo (each
// quad's own normal, or `reference` for a planar region) and, when the mesher has not
// measured it on the surface, mesh.scaled_jacobian the same way; returns their
// summary (the surface's measure decides what is inverted when it is there).
QualitySummary measure_mesh_quality(ShapeMesh& mesh, const std::optional<Vec3>& reference);

// Replaces the scaled-Jacobian statistics and the inverted and degenerate counts by
// those of per-quad values measured on a surface (each corner against the surface
// normal there); below -kSurfaceInvertedBelow is inverted.
void use_scaled_jacobians(QualitySummary& summary, const std::vector<double>& per_quad);

// Per face of the mesh (mesh.faces' quad ranges) holding collapsed quads
// (is_collapsed, by their corners), its index and how many, in face order.
std::vector<std::pair<int, long long>> collapsed_quads_per_face(const ShapeMesh& mesh);


}  // namespace tquad
