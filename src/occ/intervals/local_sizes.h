// Local sizes: a target edge length per face, edge or vertex, graded so that
// neighbouring segments differ by at most a growth rate.
//
// The size field lives on the edges (a face's mesh follows its boundary's counts):
//  - an edge's own size is the least of the global size, its own local size and the
//    local sizes of the faces it bounds (never under the minimum size);
//  - a vertex's size is the least of its own local size and the own sizes of the edges
//    that meet there, then lowered along the edges so that it grows by at most
//    ln(rate) per unit of length from any other vertex (the relaxation of shortest
//    paths: a fine vertex makes its neighbours fine enough to grow from it);
//  - along an edge of length L the size at arc length t is
//      s(t) = min(own, first + ln(rate) t, last + ln(rate) (L - t)),
//    and a graded edge gets ceil(F) segments, F the integral of dt / s(t), its nodes
//    where that integral takes equal steps (of F / n <= 1): a linear size k t + a cut
//    so gives segments in the ratio e^(k F / n), at most `rate` from one to the next.
// Without local sizes every edge's size is the global one and nothing is graded: the
// counts and nodes are those of the uniform size.
#pragma once

#include <string>
#include <vector>

#include "occ/model/shape_index.h"

namespace tquad {

struct LocalSize {
  enum class Kind { face, edge, vertex };
  Kind kind = Kind::face;
  int index = 0;  // 0-based, in the shape's order (FreeCAD's Shape.Faces, .Edges, .Vertexes)
  double size = 0.0;
};

// Gmsh's default for the growth of neighbouring elements' sizes.
constexpr double kDefaultGrowthRate = 1.3;

// The size along one edge (its FORWARD orientation).
struct EdgeSizing {
  double own = 0.0;    // 0: no field (the uniform size)
  double first = 0.0;  // the size at its first vertex, at most `own`
  double last = 0.0;   // the size at its last vertex, at most `own`
  double rate = kDefaultGrowthRate;
  bool graded() const { return own > 0 && (first < own || last < own); }
};

struct SizeField {
  std::vector<EdgeSizing> edges;  // per edge
  std::vector<double> faces;      // per face, its own size (the global one or its local)
  double smallest = 0.0;          // the least size anywhere
};

// "face3:0.5", "edge7:0.2", "vertex1:0.1" (0-based): the command's --size-at; throws
// InputError naming the entry when it is not of that form or the size is not > 0.
LocalSize parse_local_size(const std::string& text);
// The same entry as text (for messages).
std::string local_size_name(const LocalSize& s);

// Throws InputError unless 1 < rate <= 10.
void check_growth_rate(double rate);

// The field for `sizes` over the shape (lengths: each edge's arc length, 0 for a
// degenerate or unusable one). Throws InputError naming the entry for an index out of
// the shape's range, a size that is not finite and > 0, or a rate not in (1, 10].
SizeField local_size_field(const ShapeIndex& index, double global, double min_size,
                           const std::vector<LocalSize>& sizes, double rate, const std::vector<double>& lengths);

// The segments an edge of `length` takes under `sizing`: the integral of dt / s(t)
// (not rounded).
double graded_segments(const EdgeSizing& sizing, double length);

// The arc lengths (from the first vertex) of the n - 1 inner nodes of an edge of
// `length` cut into n segments under `sizing`, ascending.
std::vector<double> graded_positions(const EdgeSizing& sizing, double length, int n);

}  // namespace tquad
