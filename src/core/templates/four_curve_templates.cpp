// T1 and T2: templates of four-curve regions (paper, Figure 3(a) and 3(b)).
#include "core/templates/patch_maps.h"
#include "core/templates/template_realization.h"

namespace tquad {

namespace {

struct UV {
  double u, v;
};

// Positions along the straight parameter line from a to b, through the map.
struct MapLine {
  const QuadPatchMap& map;
  UV a, b;
  Vec3 operator()(double s) const {
    return map(a.u + s * (b.u - a.u), a.v + s * (b.v - a.v));
  }
};

struct FourCurves {
  CurveGeometry s0, s1, s2, s3;
  QuadPatchMap map;
  FourCurves(const Region& r, const std::vector<Vec3>& nodes)
      : s0(r.curves[0], nodes), s1(r.curves[1], nodes), s2(r.curves[2], nodes),
        s3(r.curves[3], nodes), map(s0, s1, s2, s3) {}
};

}  // namespace

// T1: the long side s0 (B edges) is cut b | A | b at nodes Q1, Q2; interior points P1
// above Q1 and P2 above Q2 bound the middle A x C block, and the A x b block between
// P1 P2 and the short side s2. Across the region, the side s3 has C edges where the
// middle column has C + b (C below P1, b in the A x b block), so P1 sits at
// v1 = C / (C + b): eq. 3's v1 = d1 / (d1 + d4) with both lengths measured in edges
// of the side's own size. Measuring d1 along the long side instead (the b edges of
// s0) put P1 too high: on the convex four-curve property cases it left many meshes
// with an inverted quad before repair, against none with v1 = C / (C + b), which
// also raised the mean worst scaled Jacobian.
std::vector<Region> split_t1(const Region& r, MeshBuilder& builder) {
  const auto counts = r.counts();
  const int B = counts[0], A = counts[2], b = tquad::split_t1(counts).b;
  const FourCurves g(r, builder.nodes());
  const int C = counts[1];
  const double u1 = g.s0.param(b), u2 = g.s0.param(b + A);
  const double v1 = static_cast<double>(C) / (C + b), v2 = v1;

  const NodeId q1 = r.curves[0][b], q2 = r.curves[0][b + A];
  const NodeId top_left = r.curves[3][0], top_right = r.curves[2][0];
  const NodeId p1 = builder.add_node(g.map(u1, v1));
  const NodeId p2 = builder.add_node(g.map(u2, v2));
  const auto c1 = builder.add_cut(q1, p1, C, MapLine{g.map, {u1, 0}, {u1, v1}});
  const auto c2 = builder.add_cut(p1, top_left, b, MapLine{g.map, {u1, v1}, {0, 1}});
  const auto c3 = builder.add_cut(p1, p2, A, MapLine{g.map, {u1, v1}, {u2, v2}});
  const auto c4 = builder.add_cut(q2, p2, C, MapLine{g.map, {u2, 0}, {u2, v2}});
  const auto c5 = builder.add_cut(p2, top_right, b, MapLine{g.map, {u2, v2}, {1, 1}});

  return {
      Region{{c3, c5, r.curves[2], reversed(c2)}},                         // A x b
      Region{{piece(r.curves[0], 0, b), c1, c2, r.curves[3]}},            // b x C
      Region{{piece(r.curves[0], b, b + A), c4, reversed(c3), reversed(c1)}},  // A x C
      Region{{piece(r.curves[0], b + A, B), r.curves[1], reversed(c5), reversed(c4)}},
  };
}

// T2: strips of width b along the short sides s2 (A x b) and s3 (b x C) meet at the
// interior point P, placed at the parameters of the split nodes B1 on s0 and R1 on
// s1 (eq. 4: u1 = d1 / d3, v1 = d2 / d4 from lengths); the rest is T0 or T1.
std::vector<Region> split_t2(const Region& r, MeshBuilder& builder) {
  const auto counts = r.counts();
  const int B = counts[0], D = counts[1], A = counts[2], C = counts[3];
  const int b = tquad::split_t2(counts).b;
  const FourCurves g(r, builder.nodes());
  const double u = g.s0.param(b), v = g.s1.param(D - b);

  const NodeId b1 = r.curves[0][b], r1 = r.curves[1][D - b], top_left = r.curves[3][0];
  const NodeId p = builder.add_node(g.map(u, v));
  const auto c1 = builder.add_cut(b1, p, C, MapLine{g.map, {u, 0}, {u, v}});
  const auto c2 = builder.add_cut(p, top_left, b, MapLine{g.map, {u, v}, {0, 1}});
  const auto c3 = builder.add_cut(p, r1, A, MapLine{g.map, {u, v}, {1, v}});

  return {
      Region{{c3, piece(r.curves[1], D - b, D), r.curves[2], reversed(c2)}},  // A x b
      Region{{piece(r.curves[0], 0, b), c1, c2, r.curves[3]}},               // b x C
      Region{{piece(r.curves[0], b, B), piece(r.curves[1], 0, D - b), reversed(c3), reversed(c1)}},
  };
}

}  // namespace tquad
