// TemplatePlan: the whole hierarchical decomposition of a region at the level of edge
// counts (paper, section 2: "the hierarchical decomposition"), computed before any
// node is placed. It gives the template tree, the exact number of quads (so memory is
// reserved once) and the guarantee that every leaf is a T0 with >= 1 edge per side.
#pragma once

#include <string>
#include <vector>

#include "core/templates/template_catalogue.h"

namespace tquad {

struct PlanNode {
  TemplateChoice choice;
  CurveCounts canonical_counts;  // the region's counts rotated by choice.rotation
  std::vector<PlanNode> children;
};

struct TemplatePlan {
  // Corner offsets along the root loop actually used (see region_regrouping.h).
  std::vector<int> corner_offsets;
  PlanNode root;
  long long quad_count = 0;
  int depth = 0;  // template levels above the T0 leaves; the paper's bound is 3
};

// Plans the decomposition of a region with the given curve counts (>= 1 each, even
// total). Throws InputError when no quad mesh exists (two curves of one edge).
TemplatePlan plan_templates(const CurveCounts& counts, const TemplateOptions& options);

// "T2[T0,T0,T1[T0,T0,T0,T0]]"
std::string template_tree_string(const PlanNode& node);

}  // namespace tquad
