// T5: the template of two-curve regions (paper, Figure 3(e)).
#include "core/templates/patch_maps.h"
#include "core/templates/template_realization.h"

namespace tquad {

// Each curve is split in two (M0 after a edges of s0, M1 after b edges of s1), which
// makes the region a four-curve patch V0 M0 V1 M1 (the paper's "bilinear mapping in
// parametric space"); the cut of c edges is that patch's diagonal from M0 to M1.
std::vector<Region> split_t5(const Region& r, MeshBuilder& builder, const TemplateOptions& options) {
  const auto counts = r.counts();
  const int A = counts[0], B = counts[1];
  const T5Split split = tquad::split_t5(counts, options.t5_cut_hint);
  const auto& s = r.curves;
  const auto s0a = piece(s[0], 0, split.a), s0b = piece(s[0], split.a, A);
  const auto s1a = piece(s[1], 0, split.b), s1b = piece(s[1], split.b, B);
  const auto& nodes = builder.nodes();
  const CurveGeometry g0(s0a, nodes), g1(s0b, nodes), g2(s1a, nodes), g3(s1b, nodes);
  const QuadPatchMap map(g0, g1, g2, g3);
  const auto cut = builder.add_cut(s[0][split.a], s[1][split.b], split.c,
                                   [&map](double t) { return map(1 - t, t); });
  return {
      Region{{s0a, cut, s1b}},
      Region{{s0b, s1a, reversed(cut)}},
  };
}

// Geometric hint for T5's cut: the distance between the split nodes over the mean
// boundary edge length (paper, section 3, "take the distance d1 ... and divide it by
// the average size of all boundary edges").
double t5_cut_hint(const Region& r, const std::vector<Vec3>& nodes) {
  const auto counts = r.counts();
  double perimeter = 0.0;
  for (const auto& curve : r.curves) {
    for (std::size_t i = 1; i < curve.size(); ++i) perimeter += distance(nodes[curve[i - 1]], nodes[curve[i]]);
  }
  const double mean_edge = perimeter / (counts[0] + counts[1]);
  const double d1 = distance(nodes[r.curves[0][counts[0] / 2]], nodes[r.curves[1][counts[1] / 2]]);
  return d1 / mean_edge;
}

}  // namespace tquad
