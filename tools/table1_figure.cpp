// table1_figure: meshes the twelve cases of the paper's Table 1 (Figures 8 and 9 of
// the extracted text: a unit square and an equilateral triangle, straight sides,
// uniform spacing) and draws them in one SVG, like the paper's figures: thick lines
// are the boundaries of the template subregions.
//
//   table1_figure docs/table1_meshes.svg
//
// Prints each case's template tree next to the paper's root template; exit status 1
// when a root template differs from the table or a mesh fails its checks.
#include <cmath>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "core/mesh/mesh_validation.h"
#include "core/templates/mesher.h"
#include "io/svg_writer.h"

namespace {

using tquad::BoundaryLoop;
using tquad::Vec3;

struct Table1Case {
  std::string figure;
  std::vector<int> counts;  // A, B, C (, D) as in the table
  std::string root;         // the paper's root template
  std::string branches;     // the paper's branch templates, for the printout
};

const std::vector<Table1Case> table1 = {
    {"8(a)", {4, 4, 4, 4}, "T0", "-"},
    {"8(b)", {4, 6, 4, 4}, "T1", "-"},
    {"8(c)", {4, 6, 4, 6}, "T2", "-"},
    {"8(d)", {4, 8, 4, 6}, "T2", "T1 (bottom-right region)"},
    {"9(a)", {4, 4, 4}, "T3", "-"},
    {"9(b)", {6, 4, 4}, "T3", "-"},
    {"9(c)", {8, 4, 4}, "T3", "T1 (bottom-right region)"},
    {"9(d)", {10, 4, 4}, "T3", "T1 (bottom-right region)"},
    {"9(e)", {10, 6, 4}, "T3", "T1 (bottom-right region)"},
    {"9(f)", {10, 8, 4}, "T4", "T3 (top region) and T1 (bottom region)"},
    {"9(g)", {10, 10, 4}, "T4", "T3 (top region)"},
    {"9(h)", {10, 10, 6}, "T3", "-"},
};

// Straight sides between consecutive corners, counts[i] uniform segments on side i.
BoundaryLoop straight_polygon(const std::vector<Vec3>& corners, const std::vector<int>& counts) {
  BoundaryLoop loop;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3& a = corners[i];
    const Vec3& b = corners[(i + 1) % corners.size()];
    loop.corners.push_back(static_cast<int>(loop.points.size()));
    for (int j = 0; j < counts[i]; ++j) {
      const double t = static_cast<double>(j) / counts[i];
      loop.points.push_back(a + t * (b - a));
    }
  }
  return loop;
}

// The square's curves in loop order are A, C, B, D (A opposite B, C opposite D); the
// triangle's are A, B, C.
BoundaryLoop table1_boundary(const std::vector<int>& c) {
  if (c.size() == 4) {
    return straight_polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {c[0], c[2], c[1], c[3]});
  }
  return straight_polygon({{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}}, c);
}

std::string caption_counts(const Table1Case& t) {
  static const char* const names[] = {"A", "B", "C", "D"};
  std::string text = t.figure;
  for (std::size_t i = 0; i < t.counts.size(); ++i) {
    text += std::string(" ") + names[i] + "=" + std::to_string(t.counts[i]);
  }
  return text;
}

int run(const std::string& output) {
  std::vector<tquad::QuadMesh> meshes;
  std::vector<int> boundary_points;
  bool all_match = true;
  for (const Table1Case& t : table1) {
    const BoundaryLoop loop = table1_boundary(t.counts);
    meshes.push_back(tquad::mesh_boundary(loop));
    boundary_points.push_back(static_cast<int>(loop.points.size()));
    const tquad::QuadMesh& mesh = meshes.back();
    const std::string problem = tquad::check_disk_mesh(mesh, boundary_points.back());
    const bool root_ok = mesh.template_tree.compare(0, t.root.size(), t.root) == 0;
    all_match = all_match && root_ok && problem.empty();
    std::cout << caption_counts(t) << ": " << mesh.template_tree << " (" << mesh.quads.size()
              << " quads); paper: " << t.root << ", branches " << t.branches
              << (root_ok ? "" : "  <-- root differs") << (problem.empty() ? "" : "  <-- " + problem)
              << "\n";
  }
  std::vector<tquad::SvgPanel> panels;
  for (std::size_t i = 0; i < table1.size(); ++i) {
    panels.push_back({&meshes[i], boundary_points[i],
                      caption_counts(table1[i]) + ":\n" + meshes[i].template_tree});
  }
  tquad::SvgOptions options;
  options.columns = 4;
  options.panel_size = 260;
  tquad::write_svg_file(output, panels, options);
  std::cout << "wrote " << output << "\n";
  return all_match ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: table1_figure OUTPUT.svg\n";
    return 2;
  }
  try {
    return run(argv[1]);
  } catch (const std::exception& e) {
    std::cerr << "table1_figure: " << e.what() << "\n";
    return 1;
  }
}
