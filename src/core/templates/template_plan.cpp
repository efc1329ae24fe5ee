#include "core/templates/template_plan.h"

#include <numeric>
#include <stdexcept>

#include "core/input_error.h"
#include "core/templates/region_regrouping.h"

namespace tquad {

namespace {

PlanNode plan_node(const CurveCounts& counts, const TemplateOptions& options, long long& quads,
                   int& depth, int level) {
  PlanNode node;
  node.choice = select_template(counts, options);
  node.canonical_counts = rotate_curves(counts, node.choice.rotation);
  if (node.choice.kind == TemplateKind::T0) {
    quads += static_cast<long long>(node.canonical_counts[0]) * node.canonical_counts[1];
    depth = std::max(depth, level);
    return node;
  }
  for (const CurveCounts& child : subregion_counts(node.choice.kind, node.canonical_counts, options)) {
    node.children.push_back(plan_node(child, options, quads, depth, level + 1));
  }
  return node;
}

}  // namespace

TemplatePlan plan_templates(const CurveCounts& counts, const TemplateOptions& options) {
  const int total = std::accumulate(counts.begin(), counts.end(), 0);
  if (total % 2 != 0) throw InputError("odd number of boundary edges: " + std::to_string(total));
  if (counts.size() == 2 && total == 2) {
    throw InputError("two curves of one edge each have no quad mesh");
  }
  TemplatePlan plan;
  plan.corner_offsets = regroup_curves(counts);
  const CurveCounts grouped = counts_from_offsets(plan.corner_offsets, total);
  plan.root = plan_node(grouped, options, plan.quad_count, plan.depth, 0);
  return plan;
}

std::string template_tree_string(const PlanNode& node) {
  std::string text = template_name(node.choice.kind);
  if (node.children.empty()) return text;
  text += "[";
  for (std::size_t i = 0; i < node.children.size(); ++i) {
    if (i > 0) text += ",";
    text += template_tree_string(node.children[i]);
  }
  return text + "]";
}

}  // namespace tquad
