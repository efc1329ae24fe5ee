#include "occ/intervals/pole_rims.h"

#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

#include "occ/face/face_boundary.h"
#include "occ/face/pole_to_pole.h"

namespace tquad {

namespace {

// The rim's edges of a face with one wire, a degenerate edge and a seam: the edges
// that are neither; nothing for any other face.
std::vector<int> pole_rim_edges(const ShapeIndex& index, int f) {
  const TopoDS_Face& face = index.face(f);
  int wires = 0;
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) ++wires;
  if (wires != 1) return {};
  bool pole = false, seam = false;
  std::vector<int> rim;
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    if (BRep_Tool::Degenerated(edge)) {
      pole = pole || is_pole_edge(edge, face);
    } else if (BRep_Tool::IsClosed(edge, face)) {
      seam = true;
    } else {
      const int e = index.edge_index(edge);
      if (std::find(rim.begin(), rim.end(), e) == rim.end()) rim.push_back(e);
    }
  }
  return pole && seam ? rim : std::vector<int>{};
}

}  // namespace

int quarter_pole_rims(const ShapeIndex& index, const std::vector<char>& meshed, const std::vector<double>& goals,
                      const std::vector<int>& floors, std::vector<int>& segments,
                      const std::vector<std::vector<int>>& chains) {
  std::vector<int> chain_of(segments.size(), -1);
  for (std::size_t c = 0; c < chains.size(); ++c) {
    for (int e : chains[c]) chain_of[e] = static_cast<int>(c);
  }
  int changed = 0;
  for (int f = 0; f < index.face_count(); ++f) {
    if (!meshed[f]) continue;
    // A face closed around two poles takes the cube sphere, whose seam has 2m
    // segments, m even (pole_to_pole.h): its seam's count, in no other face, goes to
    // the nearest multiple of 4 at or above its floor, 4 at least.
    const int seam = closed_seam_edge(index, f);
    if (seam >= 0) {
      const int low = std::max(4, floors[seam]);
      int count = 4 * static_cast<int>(std::lround(segments[seam] / 4.0));
      while (count < low) count += 4;
      if (count != segments[seam]) {
        segments[seam] = count;
        ++changed;
      }
      continue;
    }
    const std::vector<int> rim = pole_rim_edges(index, f);
    int total = 0;
    for (int e : rim) total += segments[e];
    if (rim.empty() || total % 4 == 0 || face_pole_angle(index.face(f)) < kQuarterRimFrom) continue;
    // The unit (a rim edge's chain, or the edge alone) and step that move the counts
    // least from their goals, relative to each goal; every count stays at its floor
    // or above.
    std::vector<int> best_unit;
    int best_step = 0;
    double best_cost = std::numeric_limits<double>::infinity();
    for (int e : rim) {
      const std::vector<int> unit = chain_of[e] >= 0 ? chains[chain_of[e]] : std::vector<int>{e};
      for (int step : {2, -2}) {
        double cost = 0;
        bool allowed = true;
        for (int m : unit) {
          const int count = segments[m] + step;
          allowed = allowed && count >= std::max(1, floors[m]);
          cost += (std::abs(count - goals[m]) - std::abs(segments[m] - goals[m])) / std::max(goals[m], 1.0);
        }
        if (allowed && cost < best_cost) best_cost = cost, best_unit = unit, best_step = step;
      }
    }
    if (best_unit.empty()) continue;  // no count may move: the disk keeps its near node
    for (int m : best_unit) segments[m] += best_step;
    ++changed;
  }
  return changed;
}

}  // namespace tquad
