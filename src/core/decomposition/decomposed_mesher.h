// mesh_planar_domain: the quad mesh of a planar domain with any outline and any number
// of holes. The domain is cut into patches (face_decomposition.h), the cuts get their
// counts (cut_intervals.h), and every patch is meshed by the templates
// (mesher.h) with the cut nodes shared between the patches on both sides.
//
//   PlanarDomain domain{{outer, hole}};          // outer counter-clockwise, hole clockwise
//   QuadMesh mesh = mesh_planar_domain(domain, 0.1);
//   // mesh.nodes starts with the domain's boundary points, loop after loop, bit-exact.
#pragma once

#include "core/decomposition/face_decomposition.h"
#include "core/templates/mesher.h"
#include "core/decomposition/patch_memo.h"

namespace tquad {

// The mesh of a decomposed domain with the given cut counts. Nodes: the boundary
// points (bit-exact), then the cuts' inner nodes, then the patches' interior nodes.
// Quads are counter-clockwise. The template tree reads "D<patches>[tree,tree,...]".
// Satisfies nodes = 1 + quads + boundary_edges / 2 - holes.
// `memo`: patches meshed before by another decomposition of the same domain.
QuadMesh mesh_decomposed_domain(const PlanarDomain& domain, const FaceDecomposition& decomposition,
                                const std::vector<int>& cut_counts, const MeshOptions& options,
                                PatchMeshMemo* memo = nullptr);

// Rings the holes (hole_rings.h), decomposes the rest (with `decomposition`, and
// with its decomposition_variants too: the mesh with the fewest inverted, then
// collapsed quads, then the best worst corner kept), assigns the cut counts from the
// target edge length `size`, and meshes.
QuadMesh mesh_planar_domain(const PlanarDomain& domain, double size, const MeshOptions& options = {},
                            const DecompositionOptions& decomposition = {});

}  // namespace tquad
