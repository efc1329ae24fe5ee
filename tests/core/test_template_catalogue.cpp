// The count-level rules: every even boundary decomposes into T0 leaves with at least
// one edge per side, within the paper's depth bound, whatever the counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <optional>
#include <numeric>

#include "core/input_error.h"
#include "core/templates/region_regrouping.h"
#include "core/templates/template_catalogue.h"
#include "core/templates/template_plan.h"

namespace tquad {
namespace {

// Walks a plan: every leaf is a T0 with opposite counts equal and >= 1, every inner
// node's children have even totals, and the leaves' quads add up to the plan's count.
void expect_sound(const PlanNode& node, long long& quads, const std::string& where) {
  const auto& n = node.canonical_counts;
  const int total = std::accumulate(n.begin(), n.end(), 0);
  ASSERT_EQ(total % 2, 0) << where;
  if (node.choice.kind == TemplateKind::T0) {
    ASSERT_EQ(n.size(), 4u) << where;
    ASSERT_EQ(n[0], n[2]) << where;
    ASSERT_EQ(n[1], n[3]) << where;
    ASSERT_GE(n[0], 1) << where;
    ASSERT_GE(n[1], 1) << where;
    quads += static_cast<long long>(n[0]) * n[1];
    return;
  }
  ASSERT_FALSE(node.children.empty()) << where;
  for (const PlanNode& child : node.children) expect_sound(child, quads, where);
}

void expect_plan_sound(const CurveCounts& counts, const TemplateOptions& options) {
  std::string where = "counts";
  for (int c : counts) where += " " + std::to_string(c);
  const TemplatePlan plan = plan_templates(counts, options);
  long long quads = 0;
  expect_sound(plan.root, quads, where);
  EXPECT_EQ(quads, plan.quad_count) << where;
  EXPECT_LE(plan.depth, 3) << where << " tree " << template_tree_string(plan.root);
}

TEST(TemplateCatalogue, TheTableHasOneRowPerTemplate) {
  std::vector<int> rows(6, 0);
  for (const TemplateRow& row : template_table()) {
    ++rows[static_cast<int>(row.kind)];
    EXPECT_EQ(template_row(row.kind).kind, row.kind);
    EXPECT_NE(row.applies, nullptr);
    EXPECT_NE(row.children, nullptr);
    EXPECT_NE(row.realize, nullptr);
  }
  for (int kind = 0; kind < 6; ++kind) EXPECT_EQ(rows[kind], 1) << "T" << kind;
}

TEST(TemplateCatalogue, ExactlyOneFourCurveRowAppliesToAnyCounts) {
  // T0, T1 and T2 split the four-curve counts between them (no order needed); each
  // rotation brings the counts to its template's canonical form.
  const TemplateOptions options;
  for (int a = 1; a <= 8; ++a) for (int b = 1; b <= 8; ++b) for (int c = 1; c <= 8; ++c) for (int d = 1; d <= 8; ++d) {
    const CurveCounts n{a, b, c, d};
    int applying = 0;
    for (const TemplateRow& row : template_table()) {
      if (row.curves != 4) continue;
      const std::optional<int> rotation = row.applies(n, options);
      if (!rotation) continue;
      ++applying;
      const CurveCounts k = rotate_curves(n, *rotation);
      if (row.kind == TemplateKind::T1) EXPECT_TRUE(k[1] == k[3] && k[0] > k[2]);
      if (row.kind == TemplateKind::T2) EXPECT_TRUE(k[0] > k[2] && k[1] > k[3]);
    }
    EXPECT_EQ(applying, 1) << a << "," << b << "," << c << "," << d;
  }
}

TEST(TemplateCatalogue, TheThreeCurveRowsFallBackToT3) {
  // T4 is tried first and T3 takes every three-curve region T4 leaves, so a region
  // within the minimums always has a template; in T4's canonical form s2 is the short
  // curve.
  TemplateOptions options;
  for (int k = 2; k <= 4; ++k) {
    options.t4_ratio = k;
    for (int a = 2; a <= 20; ++a) for (int b = 2; b <= 20; ++b) for (int c = 2; c <= 20; ++c) {
      const CurveCounts n{a, b, c};
      const TemplateChoice choice = select_template(n, options);
      const CurveCounts canonical = rotate_curves(n, choice.rotation);
      if (choice.kind == TemplateKind::T4) {
        EXPECT_LE(k * canonical[2], std::min(canonical[0], canonical[1]));
      } else {
        EXPECT_EQ(choice.kind, TemplateKind::T3);
        EXPECT_FALSE(template_row(TemplateKind::T4).applies(n, options));
      }
    }
  }
}

TEST(TemplateCatalogue, EveryFourCurveCountUpTo24Decomposes) {
  for (int a = 1; a <= 24; ++a)
    for (int b = 1; b <= 24; ++b)
      for (int c = 1; c <= 24; ++c)
        for (int d = 1; d <= 24; ++d)
          if ((a + b + c + d) % 2 == 0) expect_plan_sound({a, b, c, d}, {});
}

TEST(TemplateCatalogue, EveryThreeCurveCountUpTo60DecomposesForSeveralT4Ratios) {
  for (int k : {2, 3, 5}) {
    TemplateOptions options;
    options.t4_ratio = k;
    for (int a = 1; a <= 60; ++a)
      for (int b = 1; b <= 60; ++b)
        for (int c = 1; c <= 60; ++c)
          if ((a + b + c) % 2 == 0) expect_plan_sound({a, b, c}, options);
  }
}

TEST(TemplateCatalogue, EveryTwoCurveCountUpTo200DecomposesForSeveralCuts) {
  for (double hint : {0.0, 1.0, 2.6, 7.0, 31.0}) {
    TemplateOptions options;
    options.t5_cut_hint = hint;
    for (int a = 1; a <= 200; ++a)
      for (int b = 1; b <= 200; ++b)
        if ((a + b) % 2 == 0 && a + b > 2) expect_plan_sound({a, b}, options);
  }
}

TEST(TemplateCatalogue, TwoCurvesOfOneEdgeAreRefused) {
  EXPECT_THROW(plan_templates({1, 1}, {}), InputError);
}

TEST(TemplateCatalogue, TemplatesWithinMinimumsAreNotRegrouped) {
  EXPECT_EQ(regroup_curves({3, 5, 2, 4}), (std::vector<int>{0, 3, 8, 10}));
  EXPECT_EQ(regroup_curves({2, 2, 4}), (std::vector<int>{0, 2, 4}));
  EXPECT_EQ(regroup_curves({4, 6}), (std::vector<int>{0, 4}));
}

TEST(TemplateCatalogue, OneEdgeCurveOfThreeMergesIntoTheBalancedTwoCurveRegion) {
  // (1, 5, 6): merging the 1 into the 5 gives (6, 6), a T5 region.
  const auto offsets = regroup_curves({1, 5, 6});
  EXPECT_EQ(counts_from_offsets(offsets, 12), (CurveCounts{6, 6}));
  EXPECT_EQ(template_tree_string(plan_templates({1, 5, 6}, {}).root).substr(0, 2), "T5");
}

TEST(TemplateCatalogue, TooSmallRegionsAreRegroupedIntoFourCurves) {
  EXPECT_EQ(counts_from_offsets(regroup_curves({1, 1, 2}), 4).size(), 4u);
  EXPECT_EQ(counts_from_offsets(regroup_curves({1, 3}), 4), (CurveCounts{1, 1, 1, 1}));
  EXPECT_EQ(counts_from_offsets(regroup_curves({5, 1}), 6), (CurveCounts{2, 1, 2, 1}));
  EXPECT_EQ(counts_from_offsets(regroup_curves({3, 3}), 6), (CurveCounts{1, 2, 1, 2}));
}

TEST(TemplateCatalogue, T3OffsetCorrectionFollowsFigure4) {
  // docs/design.md, "Template catalogue": (10, 4, 4) gives interior lines 1, 3, 3 after the offset.
  const T3Split s = split_t3({10, 4, 4});
  EXPECT_EQ(s.lines, (std::array<int, 3>{1, 3, 3}));
  // Without offset the lines are eq. 6's: (4, 4, 4) -> 2, 2, 2.
  EXPECT_EQ(split_t3({4, 4, 4}).lines, (std::array<int, 3>{2, 2, 2}));
}

TEST(TemplateCatalogue, T4ParityFixAddsOneOnTheLongerCurve) {
  const T4Split s = split_t4({12, 9, 3});  // C = 3 odd: a + b + c must become even
  EXPECT_EQ(s.a, 4);
  EXPECT_EQ(s.b, 3);
  EXPECT_EQ(s.c, 3);
}

TEST(TemplateCatalogue, T5CutIsTheNearestEvenCompletionOfTheHint) {
  EXPECT_EQ(split_t5({10, 10}, 6.2).c, 6);
  EXPECT_EQ(split_t5({10, 10}, 6.9).c, 6);   // 7 would make both halves odd
  EXPECT_EQ(split_t5({10, 10}, 0.3).c, 2);   // at least 2
  EXPECT_EQ(split_t5({9, 11}, 4.4).c, 4);
}

}  // namespace
}  // namespace tquad
