// T3 and T4: templates of three-curve regions (paper, Figure 3(c) and 3(d)).
#include <algorithm>

#include "core/templates/patch_maps.h"
#include "core/templates/template_realization.h"

namespace tquad {

namespace {

struct ThreeCurves {
  CurveGeometry s0, s1, s2;
  TriPatchMap map;
  ThreeCurves(const Region& r, const std::vector<Vec3>& nodes)
      : s0(r.curves[0], nodes), s1(r.curves[1], nodes), s2(r.curves[2], nodes),
        map(s0, s1, s2) {}
};

// Barycentric coordinates of the point at parameter t of curve i.
Barycentric on_curve(int i, double t) {
  switch (i) {
    case 0: return {1 - t, t, 0};
    case 1: return {0, 1 - t, t};
    default: return {t, 0, 1 - t};
  }
}

struct MapLine {
  const TriPatchMap& map;
  Barycentric a, b;
  Vec3 operator()(double s) const {
    return map({a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])});
  }
};

Barycentric normalized(double l0, double l1, double l2) {
  const double sum = l0 + l1 + l2;
  return {l0 / sum, l1 / sum, l2 / sum};
}

// The trimapping centre. Each split node M_i, at parameter t_i of curve s_i, defines a
// cevian from the opposite corner; the centre is the mean of the three pairwise
// cevian intersections (they coincide when the splits satisfy Ceva's condition, e.g.
// at the midpoints of an equilateral triangle). Placing it from the split parameters,
// which come from 3D lengths, draws it towards a curve whose interior line has few
// edges, as eq. 6's counts ask; being a convex combination it stays inside. On the
// property cases it beat, in the mean worst scaled Jacobian of convex three-curve
// meshes before repair, the mean of the three split nodes and, by far, barycentric
// weights from the line counts.
//
// A split node's parameter is strictly inside (0, 1), but rounds to 0 or 1 where the
// segments on one side of it are below the rounding of the curve's length (a fuzzed
// curve ending in a segment 1e-16 long): each is kept kSplitParameterMargin inside,
// so that no ratio below is infinite and the centre NaN.
constexpr double kSplitParameterMargin = 1e-12;
Barycentric trimap_centre(double t0, double t1, double t2) {
  for (double* t : {&t0, &t1, &t2}) *t = std::clamp(*t, kSplitParameterMargin, 1 - kSplitParameterMargin);
  const double r0 = (1 - t0) / t0;  // l0 / l1 on the cevian from V2 through M0
  const double r1 = (1 - t1) / t1;  // l1 / l2 on the cevian from V0 through M1
  const double r2 = (1 - t2) / t2;  // l2 / l0 on the cevian from V1 through M2
  const Barycentric a = normalized(r0, 1, 1 / r1);
  const Barycentric b = normalized(1 / r2, r1, 1);
  const Barycentric c = normalized(1, 1 / r0, r2);
  return {(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3};
}

}  // namespace

// T3 (trimapping with the offset correction of Figure 4): the centre O joins the split
// node M_i of each curve by a cut of lines[i] edges, leaving three corner regions.
std::vector<Region> split_t3(const Region& r, MeshBuilder& builder) {
  const auto counts = r.counts();
  const T3Split split = tquad::split_t3(counts);
  const auto& p = split.first_part;
  const ThreeCurves g(r, builder.nodes());
  const CurveGeometry* curve[3] = {&g.s0, &g.s1, &g.s2};

  std::array<Barycentric, 3> split_at;
  for (int i = 0; i < 3; ++i) split_at[i] = on_curve(i, curve[i]->param(p[i]));
  const Barycentric centre = trimap_centre(curve[0]->param(p[0]), curve[1]->param(p[1]),
                                           curve[2]->param(p[2]));
  const NodeId o = builder.add_node(g.map(centre));
  std::array<std::vector<NodeId>, 3> cut;
  for (int i = 0; i < 3; ++i) {
    cut[i] = builder.add_cut(o, r.curves[i][p[i]], split.lines[i],
                             MapLine{g.map, centre, split_at[i]});
  }
  const auto& s = r.curves;
  return {
      Region{{piece(s[2], p[2], counts[2]), piece(s[0], 0, p[0]), reversed(cut[0]), cut[2]}},
      Region{{piece(s[0], p[0], counts[0]), piece(s[1], 0, p[1]), reversed(cut[1]), cut[0]}},
      Region{{piece(s[1], p[1], counts[1]), piece(s[2], 0, p[2]), reversed(cut[2]), cut[1]}},
  };
}

// T4: a cut of c edges from Q0 on A (a edges before the corner V1) to Q1 on B (b edges
// after V1) separates the triangle a x b x c at V1 from the strip along C. The cut is
// the straight parameter line between the two split nodes, whose parameters come from
// 3D lengths along A and B.
std::vector<Region> split_t4(const Region& r, MeshBuilder& builder) {
  const auto counts = r.counts();
  const int A = counts[0], B = counts[1];
  const T4Split split = tquad::split_t4(counts);
  const ThreeCurves g(r, builder.nodes());
  const Barycentric q0 = on_curve(0, g.s0.param(A - split.a));
  const Barycentric q1 = on_curve(1, g.s1.param(split.b));
  const auto cut = builder.add_cut(r.curves[0][A - split.a], r.curves[1][split.b], split.c,
                                   MapLine{g.map, q0, q1});
  const auto& s = r.curves;
  return {
      Region{{piece(s[0], A - split.a, A), piece(s[1], 0, split.b), reversed(cut)}},
      Region{{piece(s[0], 0, A - split.a), cut, piece(s[1], split.b, B), s[2]}},
  };
}

}  // namespace tquad
