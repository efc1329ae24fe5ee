// domain_figure: the mesh of a generated planar domain (tests/domain_generators.h) as
// JSON {"nodes", "quads", "cuts"}, for drawing with tools/draw_mesh.py.
//   build/bin/domain_figure 236 > d236.json && python3 tools/draw_mesh.py d236.json d236.png
#include <cstdio>
#include <exception>
#include <cstdlib>
#include <iostream>

#include <nlohmann/json.hpp>

#include "core/decomposition/decomposed_mesher.h"
#include "domain_generators.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: domain_figure INDEX\n");
    return 2;
  }
  const tquad::testing::GeneratedDomain g = tquad::testing::generated_domain(std::atoi(argv[1]));
  nlohmann::json out;
  tquad::QuadMesh mesh;
  try {
    mesh = tquad::mesh_planar_domain(g.domain, g.size);
  } catch (const std::exception& e) {
    // Draw the decomposition alone: boundary loops and straight cuts.
    std::fprintf(stderr, "domain_figure: %s\n", e.what());
    const tquad::FaceDecomposition d = tquad::decompose_domain(g.domain);
    for (const auto& loop : g.domain.loops) mesh.nodes.insert(mesh.nodes.end(), loop.points.begin(), loop.points.end());
    for (const auto& cut : d.cuts) mesh.subregion_cuts.push_back({cut.from, cut.to});
    for (int l = 0; l < g.domain.loop_count(); ++l) {
      std::vector<tquad::NodeId> ring;
      for (int i = 0; i <= static_cast<int>(g.domain.loops[l].points.size()); ++i)
        ring.push_back(g.domain.offset(l) + i % static_cast<int>(g.domain.loops[l].points.size()));
      mesh.subregion_cuts.push_back(ring);
    }
    out["error"] = e.what();
  }
  out["description"] = g.description;
  out["template_tree"] = mesh.template_tree;
  for (const tquad::Vec3& p : mesh.nodes) out["nodes"].push_back({p.x, p.y, p.z});
  for (const tquad::Quad& q : mesh.quads) out["quads"].push_back({q[0], q[1], q[2], q[3]});
  for (const auto& cut : mesh.subregion_cuts) out["cuts"].push_back(cut);
  std::cout << out.dump() << "\n";
  return 0;
}
