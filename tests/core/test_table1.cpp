// Table 1 of the paper: the root and branch templates of its twelve cases (unit
// square with counts A, B, C, D and equilateral triangle with A, B, C; straight sides,
// uniform spacing), both at the level of counts and on the real geometry.
#include <gtest/gtest.h>

#include "boundary_generators.h"
#include "core/mesh/mesh_validation.h"
#include "core/templates/mesher.h"
#include "core/templates/template_plan.h"

namespace tquad {
namespace {

struct Table1Row {
  const char* figure;
  std::vector<int> counts;  // A, B, C[, D]
  const char* tree;         // the paper's root and branch templates, as a tree
};

// The branch templates the paper lists, as our tree strings: e.g. 8(d) "T2, T1
// (bottom-right region)" is a T2 whose third subregion is a T1.
const std::vector<Table1Row> kRows = {
    {"8(a)", {4, 4, 4, 4}, "T0"},
    {"8(b)", {4, 6, 4, 4}, "T1[T0,T0,T0,T0]"},
    {"8(c)", {4, 6, 4, 6}, "T2[T0,T0,T0]"},
    {"8(d)", {4, 8, 4, 6}, "T2[T0,T0,T1[T0,T0,T0,T0]]"},
    {"9(a)", {4, 4, 4}, "T3[T0,T0,T0]"},
    {"9(b)", {6, 4, 4}, "T3[T0,T0,T0]"},
    {"9(c)", {8, 4, 4}, "T3[T0,T1[T0,T0,T0,T0],T0]"},
    {"9(d)", {10, 4, 4}, "T3[T0,T1[T0,T0,T0,T0],T0]"},
    {"9(e)", {10, 6, 4}, "T3[T1[T0,T0,T0,T0],T0,T0]"},
    {"9(f)", {10, 8, 4}, "T4[T3[T0,T0,T0],T1[T0,T0,T0,T0]]"},
    {"9(g)", {10, 10, 4}, "T4[T3[T0,T0,T0],T0]"},
    {"9(h)", {10, 10, 6}, "T3[T0,T0,T0]"},
};

// Test names and failures show the figure, not the row's bytes.
void PrintTo(const Table1Row& row, std::ostream* os) { *os << row.figure; }

BoundaryLoop row_boundary(const Table1Row& row) {
  const auto& n = row.counts;
  return n.size() == 4 ? testing::square_boundary(n[0], n[1], n[2], n[3])
                       : testing::triangle_boundary(n[0], n[1], n[2]);
}

// Root template and the multiset of templates one level down, as the paper states them.
std::string root_and_branches(const PlanNode& node) {
  std::string text = template_name(node.choice.kind);
  for (const PlanNode& child : node.children) {
    if (child.choice.kind != TemplateKind::T0) text += " " + template_name(child.choice.kind);
  }
  return text;
}

class Table1 : public ::testing::TestWithParam<Table1Row> {};

TEST_P(Table1, RootAndBranchTemplatesAreThePapers) {
  const Table1Row& row = GetParam();
  const BoundaryLoop loop = row_boundary(row);
  const TemplatePlan plan = plan_templates(curve_segment_counts(loop.corners, loop.points.size()), {});
  EXPECT_EQ(template_tree_string(plan.root), row.tree) << "figure " << row.figure;

  const QuadMesh mesh = mesh_boundary(loop);
  EXPECT_EQ(mesh.template_tree, row.tree) << "figure " << row.figure;
  EXPECT_EQ(check_disk_mesh(mesh, static_cast<int>(loop.points.size())), "") << "figure " << row.figure;
}

TEST(Table1Reading, BranchesMatchThePapersWording) {
  // Root template followed by the non-T0 branch templates, one level down.
  const std::vector<std::pair<std::vector<int>, std::string>> expected = {
      {{4, 4, 4, 4}, "T0"},  {{4, 6, 4, 4}, "T1"},  {{4, 6, 4, 6}, "T2"},
      {{4, 8, 4, 6}, "T2 T1"}, {{4, 4, 4}, "T3"},   {{6, 4, 4}, "T3"},
      {{8, 4, 4}, "T3 T1"},  {{10, 4, 4}, "T3 T1"}, {{10, 6, 4}, "T3 T1"},
      {{10, 8, 4}, "T4 T3 T1"}, {{10, 10, 4}, "T4 T3"}, {{10, 10, 6}, "T3"}};
  for (const auto& [counts, text] : expected) {
    CurveCounts loop_order = counts.size() == 4 ? CurveCounts{counts[0], counts[2], counts[1], counts[3]}
                                                : counts;
    EXPECT_EQ(root_and_branches(plan_templates(loop_order, {}).root), text);
  }
}

INSTANTIATE_TEST_SUITE_P(Rows, Table1, ::testing::ValuesIn(kRows),
                         [](const ::testing::TestParamInfo<Table1Row>& info) {
                           std::string name = info.param.figure;
                           for (char& c : name) if (c == '(' || c == ')') c = '_';
                           return name;
                         });

}  // namespace
}  // namespace tquad
