// ShapeIndex: the faces, edges and vertices of a shape, numbered once (0-based, in
// TopExp::MapShapes order, which is FreeCAD's Shape.Faces order), and which faces
// each edge bounds.
#pragma once

#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Vertex.hxx>

#include <vector>

namespace tquad {

class ShapeIndex {
 public:
  explicit ShapeIndex(const TopoDS_Shape& shape);

  int face_count() const { return faces_.Extent(); }
  int edge_count() const { return edges_.Extent(); }
  int vertex_count() const { return vertices_.Extent(); }

  const TopoDS_Face& face(int i) const;
  const TopoDS_Edge& edge(int i) const;
  const TopoDS_Vertex& vertex(int i) const;

  int face_index(const TopoDS_Shape& face) const { return faces_.FindIndex(face) - 1; }
  int edge_index(const TopoDS_Shape& edge) const { return edges_.FindIndex(edge) - 1; }
  // A vertex's index; after contract_edges, the index its group of joined vertices
  // goes by (the lowest), so every edge and face sees one node there.
  int vertex_index(const TopoDS_Shape& vertex) const {
    const int v = vertices_.FindIndex(vertex) - 1;
    return v < 0 || joined_.empty() ? v : joined_[v];
  }

  // Contracts `edges` (edge_contraction.h): each one's two vertices are joined into one
  // node and the edge is no side of any face, with no segment. Called before any
  // count or node is made; a later call replaces the earlier one's contraction.
  void contract_edges(const std::vector<int>& edges);
  bool contracted(int edge) const { return !contracted_.empty() && contracted_[edge]; }

  // Merges edge `merged` into edge `kept` (strip_absorption.h): merged's nodes are
  // kept's, in reverse order when `reversed`; merged keeps its own curve parameters.
  void merge_edge(int merged, int kept, bool reversed);
  struct MergedInto {
    int edge = -1;  // -1: not merged
    bool reversed = false;
  };
  MergedInto merged_into(int edge) const { return merged_.empty() ? MergedInto{} : merged_[edge]; }

  // Indices of the distinct faces an edge bounds (a seam edge bounds its face once).
  const std::vector<int>& faces_of_edge(int edge) const { return faces_of_edge_[edge]; }

  // The distinct vertices of face i's outer wire, in the wire's order (what a user picks
  // corners from); empty when the face has no readable outer wire (a damaged face).
  std::vector<int> outer_wire_vertices(int i) const;

 private:
  TopTools_IndexedMapOfShape faces_, edges_, vertices_;
  std::vector<std::vector<int>> faces_of_edge_;
  std::vector<int> joined_;        // per vertex, its group's index (empty: none joined)
  std::vector<char> contracted_;   // per edge (empty: none contracted)
  std::vector<MergedInto> merged_;  // per edge (empty: none merged)
};

}  // namespace tquad
