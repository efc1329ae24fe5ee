#include "io/report_json.h"

#include <utility>

namespace tquad {

nlohmann::ordered_json quality_stats_json(const QualityStats& stats) {
  nlohmann::ordered_json j;
  j["min"] = stats.min;
  j["avg"] = stats.avg;
  j["max"] = stats.max;
  j["std"] = stats.std;
  return j;
}

nlohmann::ordered_json mesh_report_json(const ShapeMesh& mesh, const QualitySummary& quality) {
  nlohmann::ordered_json report;
  report["nodes"] = mesh.nodes.size();
  report["quads"] = mesh.quads.size();
  report["triangles"] = 0;
  nlohmann::ordered_json q;
  q["lee_lo"] = quality_stats_json(quality.lee_lo);
  q["scaled_jacobian"] = quality_stats_json(quality.scaled_jacobian);
  q["inverted"] = quality.inverted;
  q["degenerate"] = quality.degenerate;
  q["collapsed"] = quality.collapsed;
  // The quads below 0, then per tenth from [0, 0.1) to [0.9, 1] (quality.h).
  q["jacobian_histogram"] = quality.jacobian_histogram;
  report["quality"] = q;
  nlohmann::ordered_json faces = nlohmann::ordered_json::array();
  for (const FaceMesh& f : mesh.faces) {
    nlohmann::ordered_json face;
    face["face"] = f.face;
    face["template_tree"] = f.template_tree;
    if (!f.route.empty()) face["route"] = f.route;
    if (f.corner_search) {
      const CornerSearch& c = *f.corner_search;
      nlohmann::ordered_json search;
      search["tried"] = c.tried;
      // "asked" (--corners best), or "inverted": the given corners left an inverted quad.
      search["reason"] = c.after_inverted ? "inverted" : "asked";
      search["changed"] = c.changed;
      search["natural"] = {{"min", c.natural_worst}, {"mean", c.natural_mean}};
      search["chosen"] = {{"min", c.chosen_worst}, {"mean", c.chosen_mean}};
      face["corner_search"] = std::move(search);
    }
    faces.push_back(std::move(face));
  }
  report["faces"] = std::move(faces);
  nlohmann::ordered_json refused = nlohmann::ordered_json::array();
  for (const RefusedFace& f : mesh.refused_faces) {
    nlohmann::ordered_json face;
    face["face"] = f.face;
    face["code"] = refusal_code_name(f.code);
    face["reason"] = f.reason;
    face["vertices"] = f.vertices;
    refused.push_back(std::move(face));
  }
  report["refused_faces"] = std::move(refused);
  return report;
}

}  // namespace tquad
