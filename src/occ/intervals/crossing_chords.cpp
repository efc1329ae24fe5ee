#include "occ/intervals/crossing_chords.h"

#include <algorithm>

#include "core/geometry/planar_self_intersection.h"
#include "occ/intervals/edge_discretization.h"

namespace tquad {

namespace {

// One loop's segments appended: segment k runs from point k to point k + 1 (closing),
// on the shape edge whose occurrence starts at or before k.
void add_loop(const std::vector<Vec3>& uv, const std::vector<NodeId>& nodes, const std::vector<int>& edge_start,
              const std::vector<int>& edge_index, int loop, std::vector<PlanarSegment>& segments,
              std::vector<int>& loop_of, std::vector<int>& edge_of, std::vector<std::pair<NodeId, NodeId>>& ends) {
  const int n = static_cast<int>(uv.size());
  std::size_t occurrence = 0;
  for (int k = 0; k < n; ++k) {
    while (occurrence + 1 < edge_start.size() && edge_start[occurrence + 1] <= k) ++occurrence;
    segments.push_back({uv[k], uv[(k + 1) % n]});
    ends.push_back({nodes[k], nodes[(k + 1) % n]});
    loop_of.push_back(loop);
    edge_of.push_back(edge_index.empty() ? -1 : edge_index[occurrence]);
  }
}

}  // namespace

std::vector<int> edges_of_crossing_chords(const ShapeIndex& index, int face, const FaceBoundary& b) {
  if (b.polar || b.has_degenerate_edge || b.uv.size() != b.nodes.size() || b.edge_index.empty()) return {};
  std::vector<PlanarSegment> segments;
  std::vector<int> loop_of, edge_of, first_of_loop;
  std::vector<std::pair<NodeId, NodeId>> ends;
  first_of_loop.push_back(0);
  add_loop(b.uv, b.nodes, b.edge_start, b.edge_index, 0, segments, loop_of, edge_of, ends);
  for (std::size_t h = 0; h < b.holes.size(); ++h) {
    const NodeLoop& hole = b.holes[h];
    if (hole.uv.size() != hole.nodes.size() || hole.edge_index.empty()) return {};
    first_of_loop.push_back(static_cast<int>(segments.size()));
    add_loop(hole.uv, hole.nodes, hole.edge_start, hole.edge_index, static_cast<int>(h) + 1, segments, loop_of,
             edge_of, ends);
  }
  first_of_loop.push_back(static_cast<int>(segments.size()));
  const auto crossing = find_segment_crossing(segments, [&](int i, int j) {
    // Segments meeting at one node (a hole touching the outer loop at a vertex of the
    // shape) touch there at any count: no refinement parts them.
    const auto [i0, i1] = ends[i];
    const auto [j0, j1] = ends[j];
    if (i0 == j0 || i0 == j1 || i1 == j0 || i1 == j1) return true;
    if (loop_of[i] != loop_of[j]) return false;
    const int first = first_of_loop[loop_of[i]], last = first_of_loop[loop_of[i] + 1] - 1;
    return j == i + 1 || (i == first && j == last);  // neighbours in one loop share a point
  });
  if (!crossing) return {};
  const int a = edge_of[crossing->first], b_edge = edge_of[crossing->second];
  if (a < 0 || b_edge < 0) return {};
  const auto straight = [&](int e) { return is_line_on_plane(index, face, e); };
  if (straight(a) && straight(b_edge)) return {};
  std::vector<int> curved;
  for (int e : {a, b_edge}) {
    if (!straight(e) && std::find(curved.begin(), curved.end(), e) == curved.end()) curved.push_back(e);
  }
  return curved;
}

}  // namespace tquad
