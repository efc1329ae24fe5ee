// write_svg: line drawings of meshes, like the paper's figures. Each mesh gets a
// panel; quad edges are thin, the boundary loop and the subregion cuts of the template
// tree (QuadMesh::subregion_cuts) thick, the corners the root template used are dots,
// and an optional caption goes under the panel.
//
//   write_svg_file("fig.svg", {{&mesh, n, "T2[T0,T0,T1[T0,T0,T0,T0]]"}}, {});
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/mesh/quad_mesh.h"

namespace tquad {

struct SvgPanel {
  const QuadMesh* mesh = nullptr;
  // The first `boundary_points` nodes are the boundary loop, in order (0: none drawn).
  int boundary_points = 0;
  // Lines are split at '\n' and wrapped to the panel width.
  std::string caption;
};

struct SvgOptions {
  int columns = 4;
  double panel_size = 260;  // px, the square drawing area of a panel
  // Nodes are projected on the plane of this normal, seen from its tip (the loop of
  // a counter-clockwise boundary then appears counter-clockwise). Default: the z
  // axis, i.e. the x/y plane with y up.
  std::optional<Vec3> view_normal;
};

void write_svg(std::ostream& out, const std::vector<SvgPanel>& panels, const SvgOptions& options = {});

// Writes PATH atomically (see atomic_file_writer.h).
void write_svg_file(const std::string& path, const std::vector<SvgPanel>& panels,
                    const SvgOptions& options = {});

}  // namespace tquad
