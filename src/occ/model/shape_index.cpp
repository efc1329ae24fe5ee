#include "occ/model/shape_index.h"

#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>

namespace tquad {

ShapeIndex::ShapeIndex(const TopoDS_Shape& shape) {
  TopExp::MapShapes(shape, TopAbs_FACE, faces_);
  TopExp::MapShapes(shape, TopAbs_EDGE, edges_);
  TopExp::MapShapes(shape, TopAbs_VERTEX, vertices_);
  TopTools_IndexedDataMapOfShapeListOfShape ancestors;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, ancestors);
  faces_of_edge_.resize(edges_.Extent());
  for (int e = 1; e <= edges_.Extent(); ++e) {
    const int k = ancestors.FindIndex(edges_(e));
    if (k == 0) continue;
    std::vector<int>& list = faces_of_edge_[e - 1];
    for (const TopoDS_Shape& f : ancestors(k)) {
      const int index = faces_.FindIndex(f) - 1;
      if (std::find(list.begin(), list.end(), index) == list.end()) list.push_back(index);
    }
    std::sort(list.begin(), list.end());
  }
}

const TopoDS_Face& ShapeIndex::face(int i) const { return TopoDS::Face(faces_(i + 1)); }
const TopoDS_Edge& ShapeIndex::edge(int i) const { return TopoDS::Edge(edges_(i + 1)); }
const TopoDS_Vertex& ShapeIndex::vertex(int i) const { return TopoDS::Vertex(vertices_(i + 1)); }

void ShapeIndex::contract_edges(const std::vector<int>& edges) {
  contracted_.clear();
  joined_.clear();
  if (edges.empty()) return;
  contracted_.assign(edges_.Extent(), 0);
  std::vector<int> parent(vertices_.Extent());
  for (std::size_t v = 0; v < parent.size(); ++v) parent[v] = static_cast<int>(v);
  const auto root = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (int e : edges) {
    contracted_[e] = 1;
    TopoDS_Vertex first, last;
    TopExp::Vertices(edge(e), first, last);
    const int a = root(vertices_.FindIndex(first) - 1), b = root(vertices_.FindIndex(last) - 1);
    parent[std::max(a, b)] = std::min(a, b);  // the lowest index is the group's
  }
  joined_.resize(parent.size());
  for (std::size_t v = 0; v < parent.size(); ++v) joined_[v] = root(static_cast<int>(v));
}

void ShapeIndex::merge_edge(int merged, int kept, bool reversed) {
  if (merged_.empty()) merged_.assign(edges_.Extent(), MergedInto{});
  merged_[merged] = MergedInto{kept, reversed};
}

std::vector<int> ShapeIndex::outer_wire_vertices(int i) const {
  std::vector<int> out;
  try {
    const TopoDS_Wire wire = BRepTools::OuterWire(face(i));
    if (wire.IsNull()) return out;
    for (BRepTools_WireExplorer it(wire, face(i)); it.More(); it.Next()) {
      const int v = vertex_index(it.CurrentVertex());
      if (v >= 0 && std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
    }
  } catch (const Standard_Failure&) {  // a damaged wire: the refusal names the face alone
    out.clear();
  }
  return out;
}

}  // namespace tquad
