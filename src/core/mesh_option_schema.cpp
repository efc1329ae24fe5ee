#include "core/mesh_option_schema.h"

#include <sstream>
#include <stdexcept>

namespace tquad {

const std::vector<MeshOptionField>& mesh_option_schema() {
  // Defaults are ShapeMeshOptions' and MeshOptions' (test_option_schema checks them).
  static const std::vector<MeshOptionField> fields = {
      {"size", "--size", "CharacteristicLengthMax", "float", "0.0",
       "Target edge length; 0 uses the shape's bounding-box diagonal / 25. Each edge gets "
       "round(length / size) segments, at least 1, then counts change by one where a face's total "
       "would be odd."},
      {"faces", "--faces", "Faces", "Optional[Iterable[int]]", "None",
       "The faces to mesh (0-based, in the order of FreeCAD's Shape.Faces); none given meshes all."},
      {"corners", "--corners", "Corners", "Optional[Mapping[int, Sequence[int]]]", "None",
       "Per face, the shape vertices (0-based) where its 2, 3 or 4 curves begin."},
      {"keep_going", "--keep-going", "", "bool", "False",
       "Mesh the other faces when one is refused, and list the refused faces; otherwise a refused "
       "face stops the job."},
      {"allow_inverted", "--allow-inverted", "", "bool", "False",
       "Keep a face whose mesh still has inverted, degenerate, folded or collapsed quads after "
       "repair (a corner's scaled Jacobian at or below 1e-6 against the surface normal or the "
       "quad's own, or a corner's Jacobian under 1/1000 of another's; reported per face) instead "
       "of refusing it."},
      {"threads", "--threads", "", "int", "0",
       "Threads meshing faces; 0 uses all cores. The output is the same for any number."},
      {"t4_ratio", "--t4-ratio", "T4Ratio", "int", "2",
       "The k of the T4 template's test k*C <= A and k*C <= B (at least 2)."},
      {"t5_cut_edges", "--t5-cut-edges", "", "int", "0",
       "Edges on the T5 cut of a two-curve region (0 or more); 0 takes them from the geometry."},
      {"max_quads", "--max-quads", "", "int", "100000000",
       "Refuse an input whose mesh would have more than this many quads (at least 1), from an "
       "estimate made before meshing."},
      {"smooth", "--no-smooth", "Smooth", "bool", "True",
       "Smooth each face's mesh on its surface: interior nodes move where that raises the worst "
       "corner around them, never lowering it."},
      {"progress", "--progress", "", "Optional[Callable[[str, int, int], Optional[bool]]]", "None",
       "Report each stage, and the faces meshed, as they go."},
      {"read_timeout", "--read-timeout", "", "Optional[float]", "None",
       "Seconds the reader (a child process, so that a damaged file cannot take the caller down) "
       "may take before the file is refused as damaged; by default 30 plus 30 per megabyte of "
       "the file."},
      {"best_corners", "--corners best", "BestCorners", "bool", "False",
       "Try more corner sets (2, 3 or 4 curves) on every face without given corners (the face's "
       "own when it has no holes, and each poor patch's of its decomposition) and keep the best "
       "worst, then mean, scaled Jacobian; each such face's corner_search gives the natural "
       "choice's figures beside the chosen ones."},
      {"min_size", "--min-size", "CharacteristicLengthMin", "float", "0.0",
       "The target edge length never goes below this, given or automatic (0: no floor; above a "
       "given size it is an error); curved and short edges may still get shorter segments."},
      {"order", "--order", "ElementOrder", "int", "1",
       "1: four-node quads; 2: eight-node quads, a node in the middle of each edge on the CAD "
       "curve or surface it stands for."},
      {"sew", "--sew", "Sew", "bool", "False",
       "First join faces that touch without sharing their edge (an IGES file of trimmed "
       "surfaces), so the mesh is connected there; face numbers stay the shape's."},
      {"sizes", "--size-at", "MeshRegionList", "Optional[Dict[str, float]]", "None",
       "Local target edge lengths under the size, per face, edge or vertex (0-based), as "
       "face3, edge7 or vertex1 with its length: the edges of a face take its size, and the "
       "sizes around grow from there by at most the growth rate per segment."},
      {"curvature_segments", "--curvature-segments", "MeshSizeFromCurvature", "int", "8",
       "The fewest segments a curved edge gets per full turn of its curve (8 to 1000; 8 is one "
       "per 45 degrees)."},
      {"growth_rate", "--growth-rate", "GrowthRate", "float", "1.3",
       "The most one segment may be longer than its neighbour where local sizes make them "
       "differ (over 1, at most 10)."},
  };
  return fields;
}

const MeshOptionField& mesh_option(const std::string& name) {
  for (const MeshOptionField& field : mesh_option_schema()) {
    if (field.name == name) return field;
  }
  throw std::out_of_range("no mesh option '" + name + "' in the schema");
}

std::string wrap_text(const std::string& text, std::size_t width) {
  std::istringstream words(text);
  std::string word, out, line;
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line;
}

}  // namespace tquad
