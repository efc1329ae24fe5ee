#include "core/templates/mesher.h"
#include "core/cancellation.h"

#include "core/templates/count_fitting.h"

#include <stdexcept>
#include <string>

#include "core/input_error.h"
#include "core/geometry/planar_self_intersection.h"
#include "core/templates/region_regrouping.h"
#include "core/templates/template_plan.h"
#include "core/templates/template_realization.h"

namespace tquad {

namespace {

// The region of the boundary loop with corners at the given point indices, in loop
// order from any of them: a regrouped corner can wrap past the last point (corners
// 3, 4, 5, 0 of 8 points), and each curve runs forward to the next corner.
Region loop_region(int point_count, const std::vector<int>& corners) {
  Region region;
  const int k = static_cast<int>(corners.size());
  for (int c = 0; c < k; ++c) {
    const int first = corners[c];
    int last = corners[(c + 1) % k];
    if (last <= first) last += point_count;
    std::vector<NodeId> curve;
    for (int i = first; i <= last; ++i) curve.push_back(i % point_count);
    region.curves.push_back(std::move(curve));
  }
  return region;
}

std::string counts_text(const CurveCounts& counts) {
  std::string text;
  for (int c : counts) text += (text.empty() ? "" : ",") + std::to_string(c);
  return "(" + text + ")";
}

void realize(const Region& region, const PlanNode& plan, MeshBuilder& builder,
             const TemplateOptions& options) {
  const Region canonical{rotate_curves(region.curves, plan.choice.rotation)};
  if (canonical.counts() != plan.canonical_counts) {
    throw std::logic_error("template realization diverged from its plan: region counts " +
                           counts_text(canonical.counts()) + ", planned " +
                           counts_text(plan.canonical_counts));
  }
  const std::vector<Region> children = template_row(plan.choice.kind).realize(canonical, builder, options);
  for (std::size_t i = 0; i < children.size(); ++i) {
    poll_cancellation(64);
    realize(children[i], plan.children[i], builder, options);
  }
}

TemplateOptions template_options(const MeshOptions& options) {
  if (options.t4_ratio < 2) {
    throw InputError("T4 ratio k must be at least 2 (paper, section 3), got " +
                     std::to_string(options.t4_ratio));
  }
  if (options.t5_cut_edges < 0 || options.t5_cut_edges > kMaxCurveSegments) {
    throw InputError("T5 cut edges must be 0 (automatic) or from 1 to 1e8, got " +
                     std::to_string(options.t5_cut_edges));
  }
  TemplateOptions t;
  t.t4_ratio = options.t4_ratio;
  t.t5_cut_hint = options.t5_cut_edges;
  return t;
}

}  // namespace

QuadMesh mesh_boundary(const BoundaryLoop& loop, const MeshOptions& options) {
  UntangleResult ignored;
  return mesh_boundary(loop, options, ignored);
}

QuadMesh mesh_boundary(const BoundaryLoop& loop, const MeshOptions& options, UntangleResult& untangled) {
  const std::vector<int> corners = validate_boundary(loop);
  TemplateOptions topts = template_options(options);
  const int n = static_cast<int>(loop.points.size());
  const CurveCounts counts = curve_segment_counts(corners, n);

  // Corners the templates use (the input's, unless the counts ask for regrouping).
  std::vector<int> corners_used;
  for (int offset : regroup_curves(counts)) corners_used.push_back((corners[0] + offset) % n);
  const Region root = loop_region(n, corners_used);

  QuadMesh mesh;
  mesh.nodes = loop.points;  // boundary nodes first, bit-exact
  if (root.curves.size() == 2 && topts.t5_cut_hint <= 0) {
    topts.t5_cut_hint = t5_cut_hint(root, mesh.nodes);
  }
  const TemplatePlan plan = plan_templates(counts, topts);
  if (plan.quad_count > options.max_quads) {
    throw InputError("the mesh would have " + std::to_string(plan.quad_count) +
                     " quads, more than the limit of " + std::to_string(options.max_quads));
  }
  const long long node_count = 1 + plan.quad_count + n / 2;  // V = 1 + F + E/2 (disk)
  mesh.nodes.reserve(static_cast<std::size_t>(node_count));
  mesh.quads.reserve(static_cast<std::size_t>(plan.quad_count));
  MeshBuilder builder(mesh);
  realize(root, plan.root, builder, topts);

  if (static_cast<long long>(mesh.quads.size()) != plan.quad_count ||
      static_cast<long long>(mesh.nodes.size()) != node_count) {
    throw std::logic_error("mesh has " + std::to_string(mesh.nodes.size()) + " nodes and " +
                           std::to_string(mesh.quads.size()) + " quads; the plan expected " +
                           std::to_string(node_count) + " and " + std::to_string(plan.quad_count));
  }
  if (options.untangle) {
    Vec3 normal;
    const bool planar = planar_normal(loop.points, normal);
    untangled = untangle_mesh(mesh, n, planar ? std::optional<Vec3>(normal) : std::nullopt);
  }
  mesh.template_tree = template_tree_string(plan.root);
  mesh.corners_used = corners_used;
  return mesh;
}

}  // namespace tquad
