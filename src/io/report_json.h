// mesh_report_json: the object `tquad mesh --report json` prints (docs/design.md,
// "Public contracts"):
//   {"nodes": n, "quads": m, "triangles": 0,
//    "quality": {"lee_lo": {"min","avg","max","std"}, "scaled_jacobian": {...},
//                "inverted": i, "degenerate": d, "collapsed": c,
//                "jacobian_histogram": [...]},
//    "faces": [{"face": 0, "template_tree": "T2[T0,T0,T1[T0,T0,T0,T0]]"}, ...],
//    "refused_faces": [{"face": 3, "code": "...", "reason": "...", "vertices": [...]},
//                      ...]}
// "faces" has one entry per face record, "refused_faces" one per refused face, both in
// the ShapeMesh's order (a boundary input is face 0 and refuses nothing).
// Keys keep this order (ordered_json) so the printed report reads top-down.
#pragma once

#include <nlohmann/json.hpp>

#include "core/mesh/shape_mesh.h"
#include "core/mesh/quality.h"

namespace tquad {

nlohmann::ordered_json quality_stats_json(const QualityStats& stats);

// `quality` is the summary over all of the mesh's quads.
nlohmann::ordered_json mesh_report_json(const ShapeMesh& mesh, const QualitySummary& quality);

}  // namespace tquad
