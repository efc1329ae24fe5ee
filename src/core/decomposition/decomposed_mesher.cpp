#include "core/decomposition/decomposed_mesher.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/decomposition/cut_intervals.h"
#include "core/decomposition/hole_rings.h"
#include "core/input_error.h"
#include "core/decomposition/patch_stitching.h"
#include "core/mesh/quality.h"
#include "core/repair/untangle.h"

namespace tquad {

namespace {

// Mean length of the boundary segments at domain node `node`; `offsets[l]` is loop
// l's first node (and offsets.back() the point count).
double spacing_at(const PlanarDomain& domain, const std::vector<int>& offsets, int node) {
  const int loop = static_cast<int>(std::upper_bound(offsets.begin(), offsets.end(), node) - offsets.begin()) - 1;
  const std::vector<Vec3>& p = domain.loops[loop].points;
  const int n = static_cast<int>(p.size()), i = node - offsets[loop];
  return 0.5 * (distance(p[i], p[(i + 1) % n]) + distance(p[i], p[(i + n - 1) % n]));
}

// Inner nodes of a straight cut, spaced from the boundary spacing at one end to that
// at the other (linearly), so graded boundaries stay graded across the cut.
std::vector<int> add_cut_nodes(const PlanarDomain& domain, const std::vector<int>& offsets, const CutCurve& cut,
                               int edges, QuadMesh& mesh) {
  const double ha = spacing_at(domain, offsets, cut.from), hb = spacing_at(domain, offsets, cut.to);
  std::vector<double> at{0.0};
  for (int j = 0; j < edges; ++j) at.push_back(at.back() + ha + (hb - ha) * (j + 0.5) / edges);
  const Vec3 a = mesh.nodes[cut.from], b = mesh.nodes[cut.to];
  std::vector<int> nodes{cut.from};
  for (int k = 1; k < edges; ++k) {
    const double t = at[k] / at.back();
    nodes.push_back(static_cast<int>(mesh.nodes.size()));
    mesh.nodes.push_back((1 - t) * a + t * b);
  }
  nodes.push_back(cut.to);
  return nodes;
}

// Fewer inverted quads, then fewer collapsed ones, then the better worst scaled
// Jacobian.
bool better_planar_mesh(const QuadMesh& a, const QuadMesh& b) {
  const Vec3 up{0, 0, 1};
  const QualitySummary qa = summarize_quality(a, up), qb = summarize_quality(b, up);
  if (qa.inverted != qb.inverted) return qa.inverted < qb.inverted;
  if (qa.collapsed != qb.collapsed) return qa.collapsed < qb.collapsed;
  return qa.scaled_jacobian.min > qb.scaled_jacobian.min;
}

}  // namespace

QuadMesh mesh_decomposed_domain(const PlanarDomain& domain, const FaceDecomposition& d,
                                const std::vector<int>& cut_counts, const MeshOptions& options, PatchMeshMemo* memo) {
  if (cut_counts.size() != d.cuts.size()) {
    throw std::logic_error("decomposition has " + std::to_string(d.cuts.size()) + " cuts but " +
                           std::to_string(cut_counts.size()) + " counts");
  }
  QuadMesh mesh;
  std::vector<int> offsets{0};
  for (const DomainLoop& loop : domain.loops) {
    mesh.nodes.insert(mesh.nodes.end(), loop.points.begin(), loop.points.end());
    offsets.push_back(offsets.back() + static_cast<int>(loop.points.size()));
  }
  std::vector<std::vector<int>> cut_nodes;
  for (std::size_t c = 0; c < d.cuts.size(); ++c) {
    cut_nodes.push_back(add_cut_nodes(domain, offsets, d.cuts[c], cut_counts[c], mesh));
    mesh.subregion_cuts.emplace_back(cut_nodes.back().begin(), cut_nodes.back().end());
  }
  std::string trees;
  for (std::size_t p = 0; p < d.patches.size(); ++p) {
    std::vector<NodeId> loop;
    std::vector<int> corners;
    for (const PatchSide& side : d.patches[p].sides) {
      const std::vector<int> nodes = side_nodes(domain, d, side, cut_nodes);
      corners.push_back(static_cast<int>(loop.size()));
      loop.insert(loop.end(), nodes.begin(), nodes.end() - 1);
    }
    std::string tree;
    try {
      tree = append_patch(mesh, loop, corners, options, memo);
    } catch (const InputError& e) {
      throw InputError("patch " + std::to_string(p) + " of the decomposition: " + e.what());
    }
    if (static_cast<long long>(mesh.quads.size()) > options.max_quads) {
      throw InputError("the mesh would have more than " + std::to_string(options.max_quads) + " quads");
    }
    trees += (trees.empty() ? "" : ",") + tree;
  }
  // Templates repaired each patch with its cut nodes fixed. Corners still inverted or
  // at a straight angle get a repair of the whole face (untangle.h) that may move cut
  // nodes too. Its Laplacian pulls nodes together on a face with holes (kept always,
  // it collapsed quads into triangles in many of the generated domains), so its
  // result is kept only when it leaves fewer inverted quads, or as many and no more
  // collapsed ones with a better worst corner.
  if (options.untangle) {
    const Vec3 up{0, 0, 1};
    const QualitySummary before = summarize_quality(mesh, up);
    if (before.inverted > 0 || before.degenerate > 0) {
      QuadMesh repaired = mesh;
      untangle_mesh(repaired, domain.point_count(), up);
      const QualitySummary after = summarize_quality(repaired, up);
      if (after.inverted < before.inverted ||
          (after.inverted == before.inverted && after.collapsed <= before.collapsed &&
           after.scaled_jacobian.min > before.scaled_jacobian.min)) {
        mesh = std::move(repaired);
      }
    }
  }
  mesh.template_tree = "D" + std::to_string(d.patches.size()) + "[" + trees + "]";
  const long long expected = 1 + static_cast<long long>(mesh.quads.size()) + domain.point_count() / 2 - domain.hole_count();
  if (static_cast<long long>(mesh.nodes.size()) != expected) {
    throw std::logic_error("decomposed mesh has " + std::to_string(mesh.nodes.size()) + " nodes, expected " +
                           std::to_string(expected));
  }
  return mesh;
}

QuadMesh mesh_planar_domain(const PlanarDomain& domain, double size, const MeshOptions& options,
                            const DecompositionOptions& decomposition) {
  if (!(size > 0) || !std::isfinite(size)) throw InputError("the target size must be a positive number");
  check_planar_domain(domain);
  const RingedDomain ringed = ring_holes(domain);
  PatchMeshMemo memo;
  const auto mesh_of = [&](const FaceDecomposition& d) {
    return mesh_decomposed_domain(ringed.inner, d, assign_cut_intervals(ringed.inner, d, size), options, &memo);
  };
  const FaceDecomposition plain = decompose_domain(ringed.inner, decomposition);
  QuadMesh inner = mesh_of(plain);
  // On the generated domains of the tests, with sliver pairs alone more meshes came
  // out inverted or with collapsed quads than with these variants tried too.
  for (const DecompositionOptions& variant : decomposition_variants(decomposition, &plain)) {
    QuadMesh other = mesh_of(decompose_domain(ringed.inner, variant));
    if (better_planar_mesh(other, inner)) inner = std::move(other);
  }
  return join_rings(domain, ringed, inner);
}

}  // namespace tquad
