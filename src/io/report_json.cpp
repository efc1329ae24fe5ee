#include "io/report_json.h"

namespace tquad {

nlohmann::ordered_json quality_stats_json(const QualityStats& stats) {
  nlohmann::ordered_json j;
  j["min"] = stats.min;
  j["avg"] = stats.avg;
  j["max"] = stats.max;
  j["std"] = stats.std;
  return j;
}

nlohmann::ordered_json mesh_report_json(const QuadMesh& mesh, const QualitySummary& quality) {
  nlohmann::ordered_json report;
  report["nodes"] = mesh.nodes.size();
  report["quads"] = mesh.quads.size();
  report["triangles"] = 0;
  nlohmann::ordered_json q;
  q["lee_lo"] = quality_stats_json(quality.lee_lo);
  q["scaled_jacobian"] = quality_stats_json(quality.scaled_jacobian);
  q["inverted"] = quality.inverted;
  q["degenerate"] = quality.degenerate;
  report["quality"] = q;
  nlohmann::ordered_json face;
  face["face"] = 0;
  face["template_tree"] = mesh.template_tree;
  report["faces"] = nlohmann::ordered_json::array({face});
  report["refused_faces"] = nlohmann::ordered_json::array();
  return report;
}

}  // namespace tquad
