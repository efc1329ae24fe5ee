// The template catalogue (paper, section 3 and Figure 1), at the level of edge counts.
//
// A region is a closed loop of boundary edges grouped into 2, 3 or 4 curves; its
// "counts" are the numbers of edges of its curves in loop order. A template either
// meshes the region directly (T0) or cuts it into subregions whose counts follow
// from the parent's counts alone. Because every rule below depends on counts only,
// two regions with equal counts get identical connectivity (the paper's topological
// equivalence, section 1); geometry only decides where the nodes go.
//
//   four curves  (s0, s1, s2, s3; s0 opposite s2, s1 opposite s3)
//     T0  s0 == s2 and s1 == s3: mapped grid (eq. 1).
//     T1  one opposite pair equal (C == D), the other not (B > A):
//         b = (B - A) / 2; the long side B is cut b | A | b and the region splits
//         into A x b (next to A), b x C, A x C, b x C, all T0.
//     T2  both pairs unequal (B > A, D > C, B and D adjacent):
//         b = min(B - A, D - C); A x b and b x C strips along the short sides (T0)
//         and the rest (B - b) x (D - b) x A x C, which is T0 or T1.
//         (docs/design.md, "Template catalogue": b is not halved here, or Table 1's
//         rows fail.)
//   three curves (s0, s1, s2)
//     T3  trimapping: a centre joined to one split node per curve. Interior lines get
//         l0 = (n1 + n2 - n0) / 2 edges (to the split of s0), and so on (eq. 6);
//         when one is <= 0 the offset correction of Figure 4 raises it to 1 and the
//         long curve keeps an even excess, which one corner region takes as a T1.
//     T4  one curve much shorter (k C <= A and k C <= B, k = 2 by default): a cut of
//         C edges separates a strip along C (C, A - a, C, B - b: T0 or T1) from the
//         triangle a x b x c at the corner of A and B (T3); a = b = c = C, plus one
//         on the longer of A and B when a + b + c is odd.
//   two curves (A, B)
//     T5  each curve split in two (a = A/2, b = B/2) and the split nodes joined by a
//         cut of c edges: two three-curve regions a x c x (B - b) and (A - a) x b x c.
//
// Regions below the templates' minimums (a three-curve region with a one-edge curve,
// a two-curve region with a curve under 4 edges) are regrouped into another number of
// curves before a template is chosen (region_regrouping.h).
//
// Each template is one row of template_table(): the curves it meshes, their fewest
// edges, when it applies (and the rotation to its canonical form), its count rule
// and its realization (template_realization.h). select_template takes the first row
// in table order that applies; the planner (template_plan.h) and the mesher
// (mesher.h) follow the rows' count rules and realizations.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace tquad {

enum class TemplateKind { T0, T1, T2, T3, T4, T5 };

std::string template_name(TemplateKind kind);

// Counts of one region, in loop order.
using CurveCounts = std::vector<int>;

// Options that change which template is chosen or how counts are split.
struct TemplateOptions {
  // k of the T4 test k C <= A and k C <= B (paper, section 3: k >= 2).
  int t4_ratio = 2;
  // Edges on T5's interior cut, as a real number before rounding and the parity
  // fix. Geometry supplies it (distance between the split nodes over the mean edge
  // length); <= 0 uses 2 min(A, B) / pi, the value for a disk.
  double t5_cut_hint = 0.0;
};

// The template chosen for a region and the rotation that brings the region to the
// template's canonical form: canonical curve i is the region's curve (i + rotation)
// mod n. Canonical forms: T1 s0 is the long side B, s2 the short side A; T2 s0 and s1
// are the long sides; T3 s0 carries the offset excess (rotation 0 without offset);
// T4 s2 is the short curve C; T0 and T5 are not rotated.
struct TemplateChoice {
  TemplateKind kind = TemplateKind::T0;
  int rotation = 0;
};

// Selects the template for a region that is already within the templates' minimums
// (four curves >= 1 edge, three >= 2, two >= 4). Throws std::logic_error otherwise.
TemplateChoice select_template(const CurveCounts& counts, const TemplateOptions& options);

// Count-level split rules, on canonical counts. Subregions are listed in a fixed
// order, each with counts in its own loop order (the order realization builds them).
struct T1Split {
  int b;  // edges on each end piece of the long side
};
T1Split split_t1(const CurveCounts& canonical);

struct T2Split {
  int b;  // width of the two strips along the short sides
};
T2Split split_t2(const CurveCounts& canonical);

struct T3Split {
  std::array<int, 3> lines;       // edges of the cut from the centre to curve i's split
  std::array<int, 3> first_part;  // edges of curve i from its start to its split node
};
T3Split split_t3(const CurveCounts& canonical);

struct T4Split {
  int a, b, c;  // triangle at the corner of A and B: a on A, b on B, c on the cut
};
T4Split split_t4(const CurveCounts& canonical);

struct T5Split {
  int a, b, c;  // a edges of A before its split, b of B, c on the cut
};
T5Split split_t5(const CurveCounts& canonical, double cut_hint);

// Children counts of a template applied to canonical counts, in realization order.
std::vector<CurveCounts> subregion_counts(TemplateKind kind, const CurveCounts& canonical,
                                          const TemplateOptions& options);

struct Region;
class MeshBuilder;

// One template of the catalogue.
struct TemplateRow {
  TemplateKind kind;
  int curves;        // of the regions it meshes: 2, 3 or 4
  int fewest_edges;  // per curve, for every template of that many curves
  // Whether it meshes a region of these counts (within the minimums), and the
  // rotation to its canonical form (TemplateChoice).
  std::optional<int> (*applies)(const CurveCounts& counts, const TemplateOptions& options);
  // Its count rule: the subregions' counts from canonical counts, in realization order.
  std::vector<CurveCounts> (*children)(const CurveCounts& canonical, const TemplateOptions& options);
  // Its realization on a canonical region: the nodes and quads it adds, and the
  // subregions in the order `children` lists them (none for T0).
  std::vector<Region> (*realize)(const Region& canonical, MeshBuilder& builder, const TemplateOptions& options);
};

// The catalogue, in the order select_template tries the rows: T0, T1, T2 (four
// curves), T4 before T3 (three), T5 (two).
const std::vector<TemplateRow>& template_table();
const TemplateRow& template_row(TemplateKind kind);

// Rotates counts (or any per-curve list) so that element i is old element i + rotation.
template <typename T>
std::vector<T> rotate_curves(const std::vector<T>& v, int rotation) {
  std::vector<T> out(v.size());
  const int n = static_cast<int>(v.size());
  for (int i = 0; i < n; ++i) out[i] = v[(i + rotation) % n];
  return out;
}

}  // namespace tquad
