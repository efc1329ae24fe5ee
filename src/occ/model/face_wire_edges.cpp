#include "occ/model/face_wire_edges.h"

#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>

#include "occ/face/face_boundary.h"

namespace tquad {

WireEdges face_wires_with_poles(const ShapeIndex& index, int face) {
  const TopoDS_Face& f = index.face(face);
  WireEdges wires;
  const TopoDS_Wire outer = BRepTools::OuterWire(f);
  for (TopExp_Explorer w(f, TopAbs_WIRE); w.More(); w.Next()) {
    const TopoDS_Wire wire = TopoDS::Wire(w.Current());
    std::vector<int> edges;
    for (BRepTools_WireExplorer it(wire, f); it.More(); it.Next()) {
      const TopoDS_Edge& edge = it.Current();
      if (!BRep_Tool::Degenerated(edge)) {
        if (!index.contracted(index.edge_index(edge))) edges.push_back(index.edge_index(edge));
      }
      else if (is_pole_edge(edge, f)) edges.push_back(kPoleEdge);
      // A degenerate edge that is a point of the chart is no side of the face, nor a
      // contracted edge (edge_contraction.h).
    }
    if (wire.IsSame(outer)) wires.insert(wires.begin(), std::move(edges));
    else wires.push_back(std::move(edges));
  }
  return wires;
}

std::optional<WireEdges> face_wire_edges(const ShapeIndex& index, int face) {
  WireEdges wires = face_wires_with_poles(index, face);
  for (const auto& wire : wires) {
    for (int e : wire) if (e == kPoleEdge) return std::nullopt;
  }
  return wires;
}

const std::optional<WireEdges>& FaceWireEdges::of(int face) {
  if (!known_[face]) {
    wires_[face] = face_wire_edges(index_, face);
    known_[face] = 1;
  }
  return wires_[face];
}

}  // namespace tquad
