// mesh_shape: all-quad meshes of the faces of a CAD shape, conforming across shared
// edges. The stages: index the shape; choose edge counts from the size and make every
// face's total even (interval_assignment.h); discretize every edge once; then, per
// face and in parallel, build the boundary loop, choose corners and run the templates
// in the face's parameter space; finally number the interior nodes face by face, so
// the output is the same whatever the number of threads.
#pragma once

#include <TopoDS_Shape.hxx>

#include <map>
#include <vector>

#include "core/mesher.h"
#include "core/shape_mesh.h"
#include "occ/interval_assignment.h"

namespace tquad {

struct ShapeMeshOptions {
  // Target edge length; <= 0 uses the shape's bounding-box diagonal / 25.
  double size = 0.0;
  // Faces to mesh (0-based); empty: all.
  std::vector<int> faces;
  // Per face, the shape vertices to use as corners (2 to 4).
  std::map<int, std::vector<int>> corners;
  MeshOptions templates;
  // Worker threads for the faces; <= 0: all cores.
  int threads = 0;
  // Mesh the other faces when one is refused (and list it); otherwise refuse all.
  bool keep_going = false;
  // Keep a face whose mesh still has inverted quads after repair (counted in
  // ShapeMeshResult::inverted) instead of refusing it.
  bool allow_inverted = false;
};

struct ShapeMeshResult {
  ShapeMesh mesh;
  double size = 0.0;                     // the target size used
  std::vector<IntervalChange> changes;   // edge counts changed for parity
  long long projected_faces = 0;         // faces meshed by the 3D route
  long long inverted = 0;                // quads still inverted after repair
  int refinement_rounds = 0;             // times edges of faces with inverted quads were doubled
  double template_seconds = 0;           // summed over faces (all threads)
  double placement_seconds = 0;          // interior nodes onto the surfaces, summed
};

// Throws InputError (a face index out of range; without keep_going, a refused face,
// naming it and the reason).
ShapeMeshResult mesh_shape(const TopoDS_Shape& shape, const ShapeMeshOptions& options);

}  // namespace tquad
