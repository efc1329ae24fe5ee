#include "core/templates/template_catalogue.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/templates/mapped_grid.h"
#include "core/templates/template_realization.h"

namespace tquad {

std::string template_name(TemplateKind kind) {
  return "T" + std::to_string(static_cast<int>(kind));
}

namespace {

[[noreturn]] void below_minimum(const CurveCounts& counts) {
  std::string text;
  for (int c : counts) text += (text.empty() ? "" : ",") + std::to_string(c);
  throw std::logic_error("no template for counts (" + text + "); regroup the region first");
}

// Four curves: T0 with both opposite pairs equal, T1 with one, T2 with none.
std::optional<int> t0_applies(const CurveCounts& n, const TemplateOptions&) {
  if (n[0] == n[2] && n[1] == n[3]) return 0;
  return std::nullopt;
}

std::optional<int> t1_applies(const CurveCounts& n, const TemplateOptions&) {
  const bool pair02 = n[0] == n[2], pair13 = n[1] == n[3];
  if (pair02 == pair13) return std::nullopt;
  if (pair13) return n[0] > n[2] ? 0 : 2;  // canonical s0 is the long side
  return n[1] > n[3] ? 1 : 3;
}

std::optional<int> t2_applies(const CurveCounts& n, const TemplateOptions&) {
  if (n[0] == n[2] || n[1] == n[3]) return std::nullopt;
  // The long side of each pair; they are adjacent, and the one first in loop order
  // becomes s0 so that s1 is the other.
  const int long02 = n[0] > n[2] ? 0 : 2;
  const int long13 = n[1] > n[3] ? 1 : 3;
  return (long02 + 1) % 4 == long13 ? long02 : long13;
}

// Trimapping lines before the offset correction (eq. 6): the line to curve i's
// split node has (n[i+1] + n[i+2] - n[i]) / 2 edges.
std::array<int, 3> trimap_lines(const CurveCounts& n) {
  return {(n[1] + n[2] - n[0]) / 2, (n[2] + n[0] - n[1]) / 2, (n[0] + n[1] - n[2]) / 2};
}

// Three curves: T4 when one curve is much shorter (k C <= A and k C <= B), else T3.
std::optional<int> t4_applies(const CurveCounts& n, const TemplateOptions& options) {
  const int shortest = static_cast<int>(std::min_element(n.begin(), n.end()) - n.begin());
  const int c = n[shortest];
  const int a = n[(shortest + 1) % 3];
  const int b = n[(shortest + 2) % 3];
  const long long kc = static_cast<long long>(options.t4_ratio) * c;  // k and C are each under 2^31
  if (kc <= a && kc <= b) return (shortest + 1) % 3;                // canonical s2 is the short curve
  return std::nullopt;
}

std::optional<int> t3_applies(const CurveCounts& n, const TemplateOptions&) {
  const auto lines = trimap_lines(n);
  for (int i = 0; i < 3; ++i) {
    if (lines[i] <= 0) return i;  // s0 takes the offset excess
  }
  return 0;
}

std::optional<int> t5_applies(const CurveCounts&, const TemplateOptions&) { return 0; }

}  // namespace

TemplateChoice select_template(const CurveCounts& counts, const TemplateOptions& options) {
  const int curves = static_cast<int>(counts.size());
  bool known = false;
  for (const TemplateRow& row : template_table()) {
    if (row.curves != curves) continue;
    if (!known) {
      for (int c : counts) if (c < row.fewest_edges) below_minimum(counts);
      known = true;
    }
    if (const std::optional<int> rotation = row.applies(counts, options)) return {row.kind, *rotation};
  }
  below_minimum(counts);
}

T1Split split_t1(const CurveCounts& n) { return {(n[0] - n[2]) / 2}; }

T2Split split_t2(const CurveCounts& n) { return {std::min(n[0] - n[2], n[1] - n[3])}; }

T3Split split_t3(const CurveCounts& n) {
  auto lines = trimap_lines(n);
  // Offset correction (Figure 4): only s0 can have a line <= 0 in canonical form
  // (any two lines add up to a curve's count, so at most one is <= 0).
  if (lines[0] <= 0) {
    const int offset = 1 - lines[0];
    lines[0] += offset;
    lines[1] -= offset;
    lines[2] -= offset;
  }
  const int excess = n[0] - lines[1] - lines[2];  // even, and 0 without offset
  // Curve s0 is split between the corner regions at V0 (opposite line 2) and at V1
  // (opposite line 1). The excess goes whole to one of them, which becomes a T1, as in
  // Table 1 ("T3, T1 (bottom-right region)"); it goes to the region with the longer
  // opposite line, where the T1's stretch is milder. (Giving it always to V0, always
  // to V1, or half to each when both halves stay even barely changed the number of
  // three-curve property cases with an inverted quad before repair.)
  const int first_part_s0 = lines[2] + (lines[2] > lines[1] ? excess : 0);
  return {lines, {first_part_s0, lines[0], lines[1]}};
}

T4Split split_t4(const CurveCounts& n) {
  T4Split s{n[2], n[2], n[2]};
  if ((s.a + s.b + s.c) % 2 != 0) {
    if (n[0] > n[1]) ++s.a; else ++s.b;  // parity fix of section 3
  }
  return s;
}

T5Split split_t5(const CurveCounts& n, double cut_hint) {
  const int a = n[0] / 2;
  const int b = n[1] / 2;
  if (cut_hint <= 0) cut_hint = 2.0 * std::min(n[0], n[1]) / M_PI;
  // Both three-curve subregions need at least 2 edges per curve, and an even total:
  // a + c + (B - b) even. Take the admissible c nearest to the hint.
  const int parity = (a + n[1] - b) % 2;
  int c = std::max(2, static_cast<int>(std::lround(cut_hint)));
  if ((c + parity) % 2 != 0) {
    c = (c - 1 >= 2 && std::abs(cut_hint - (c - 1)) < std::abs(cut_hint - (c + 1))) ? c - 1 : c + 1;
  }
  return {a, b, c};
}

namespace {

// The count rules (subregion counts in realization order), per template.
std::vector<CurveCounts> t0_children(const CurveCounts&, const TemplateOptions&) { return {}; }

std::vector<CurveCounts> t1_children(const CurveCounts& n, const TemplateOptions&) {
  const int b = split_t1(n).b, A = n[2], C = n[1];
  return {{A, b, A, b}, {b, C, b, C}, {A, C, A, C}, {b, C, b, C}};
}

std::vector<CurveCounts> t2_children(const CurveCounts& n, const TemplateOptions&) {
  const int b = split_t2(n).b, A = n[2], C = n[3];
  return {{A, b, A, b}, {b, C, b, C}, {n[0] - b, n[1] - b, A, C}};
}

std::vector<CurveCounts> t3_children(const CurveCounts& n, const TemplateOptions&) {
  const T3Split s = split_t3(n);
  const auto& l = s.lines;
  const auto& p = s.first_part;
  return {{n[2] - p[2], p[0], l[0], l[2]}, {n[0] - p[0], p[1], l[1], l[0]}, {n[1] - p[1], p[2], l[2], l[1]}};
}

std::vector<CurveCounts> t4_children(const CurveCounts& n, const TemplateOptions&) {
  const T4Split s = split_t4(n);
  return {{s.a, s.b, s.c}, {n[0] - s.a, s.c, n[1] - s.b, n[2]}};
}

std::vector<CurveCounts> t5_children(const CurveCounts& n, const TemplateOptions& options) {
  const T5Split s = split_t5(n, options.t5_cut_hint);
  return {{s.a, s.c, n[1] - s.b}, {n[0] - s.a, s.b, s.c}};
}

// The realizations (template_realization.h), per template.
std::vector<Region> t0_realize(const Region& canonical, MeshBuilder& builder, const TemplateOptions&) {
  mesh_mapped_grid(canonical, builder);
  return {};
}
std::vector<Region> t1_realize(const Region& canonical, MeshBuilder& builder, const TemplateOptions&) {
  return split_t1(canonical, builder);
}
std::vector<Region> t2_realize(const Region& canonical, MeshBuilder& builder, const TemplateOptions&) {
  return split_t2(canonical, builder);
}
std::vector<Region> t3_realize(const Region& canonical, MeshBuilder& builder, const TemplateOptions&) {
  return split_t3(canonical, builder);
}
std::vector<Region> t4_realize(const Region& canonical, MeshBuilder& builder, const TemplateOptions&) {
  return split_t4(canonical, builder);
}
std::vector<Region> t5_realize(const Region& canonical, MeshBuilder& builder, const TemplateOptions& options) {
  return split_t5(canonical, builder, options);
}

}  // namespace

const std::vector<TemplateRow>& template_table() {
  //                                         kind            curves fewest applies     children     realize
  static const std::vector<TemplateRow> table{{TemplateKind::T0, 4, 1, t0_applies, t0_children, t0_realize},
                                              {TemplateKind::T1, 4, 1, t1_applies, t1_children, t1_realize},
                                              {TemplateKind::T2, 4, 1, t2_applies, t2_children, t2_realize},
                                              {TemplateKind::T4, 3, 2, t4_applies, t4_children, t4_realize},
                                              {TemplateKind::T3, 3, 2, t3_applies, t3_children, t3_realize},
                                              {TemplateKind::T5, 2, 4, t5_applies, t5_children, t5_realize}};
  return table;
}

const TemplateRow& template_row(TemplateKind kind) {
  for (const TemplateRow& row : template_table()) {
    if (row.kind == kind) return row;
  }
  throw std::logic_error("no template row for " + template_name(kind));
}

std::vector<CurveCounts> subregion_counts(TemplateKind kind, const CurveCounts& n, const TemplateOptions& options) {
  return template_row(kind).children(n, options);
}

}  // namespace tquad
