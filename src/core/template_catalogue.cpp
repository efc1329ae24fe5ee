#include "core/template_catalogue.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

TemplateChoice select_four_curves(const CurveCounts& n) {
  const bool pair02 = n[0] == n[2];
  const bool pair13 = n[1] == n[3];
  if (pair02 && pair13) return {TemplateKind::T0, 0};
  if (pair13) return {TemplateKind::T1, n[0] > n[2] ? 0 : 2};
  if (pair02) return {TemplateKind::T1, n[1] > n[3] ? 1 : 3};
  // T2: the long side of each pair; they are adjacent, and the one first in loop
  // order becomes s0 so that s1 is the other.
  const int long02 = n[0] > n[2] ? 0 : 2;
  const int long13 = n[1] > n[3] ? 1 : 3;
  const int rotation = (long02 + 1) % 4 == long13 ? long02 : long13;
  return {TemplateKind::T2, rotation};
}

// Trimapping lines before the offset correction (eq. 6): the line to curve i's
// split node has (n[i+1] + n[i+2] - n[i]) / 2 edges.
std::array<int, 3> trimap_lines(const CurveCounts& n) {
  return {(n[1] + n[2] - n[0]) / 2, (n[2] + n[0] - n[1]) / 2, (n[0] + n[1] - n[2]) / 2};
}

TemplateChoice select_three_curves(const CurveCounts& n, const TemplateOptions& options) {
  const int shortest = static_cast<int>(std::min_element(n.begin(), n.end()) - n.begin());
  const int c = n[shortest];
  const int a = n[(shortest + 1) % 3];
  const int b = n[(shortest + 2) % 3];
  const long long kc = static_cast<long long>(options.t4_ratio) * c;  // k and C are each under 2^31
  if (kc <= a && kc <= b) {
    return {TemplateKind::T4, (shortest + 1) % 3};  // canonical s2 is the short curve
  }
  const auto lines = trimap_lines(n);
  for (int i = 0; i < 3; ++i) {
    if (lines[i] <= 0) return {TemplateKind::T3, i};  // s0 takes the offset excess
  }
  return {TemplateKind::T3, 0};
}

}  // namespace

TemplateChoice select_template(const CurveCounts& counts, const TemplateOptions& options) {
  switch (counts.size()) {
    case 4:
      for (int c : counts) if (c < 1) below_minimum(counts);
      return select_four_curves(counts);
    case 3:
      for (int c : counts) if (c < 2) below_minimum(counts);
      return select_three_curves(counts, options);
    case 2:
      if (counts[0] < 4 || counts[1] < 4) below_minimum(counts);
      return {TemplateKind::T5, 0};
    default:
      below_minimum(counts);
  }
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
  // to V1, or half to each when both halves stay even changed the number of
  // three-curve property cases with an inverted quad before repair by under 2%.)
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

std::vector<CurveCounts> subregion_counts(TemplateKind kind, const CurveCounts& n,
                                          const TemplateOptions& options) {
  switch (kind) {
    case TemplateKind::T0:
      return {};
    case TemplateKind::T1: {
      const int b = split_t1(n).b, A = n[2], C = n[1];
      return {{A, b, A, b}, {b, C, b, C}, {A, C, A, C}, {b, C, b, C}};
    }
    case TemplateKind::T2: {
      const int b = split_t2(n).b, A = n[2], C = n[3];
      return {{A, b, A, b}, {b, C, b, C}, {n[0] - b, n[1] - b, A, C}};
    }
    case TemplateKind::T3: {
      const T3Split s = split_t3(n);
      const auto& l = s.lines;
      const auto& p = s.first_part;
      return {{n[2] - p[2], p[0], l[0], l[2]},
              {n[0] - p[0], p[1], l[1], l[0]},
              {n[1] - p[1], p[2], l[2], l[1]}};
    }
    case TemplateKind::T4: {
      const T4Split s = split_t4(n);
      return {{s.a, s.b, s.c}, {n[0] - s.a, s.c, n[1] - s.b, n[2]}};
    }
    case TemplateKind::T5: {
      const T5Split s = split_t5(n, options.t5_cut_hint);
      return {{s.a, s.c, n[1] - s.b}, {n[0] - s.a, s.b, s.c}};
    }
  }
  return {};
}

}  // namespace tquad
