// orient_shells on generated shells: the six faces of a cube's surface grid, each face
// given its outward or inward turn at random, come out with every shared edge run in
// opposite directions by its two quads and a positive enclosed volume; an open box
// keeps the larger area's side; anchored faces never turn; second-order middles stay
// on their edges; a one-sided band (Moebius) is reported, not forced.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include "case_stride.h"
#include "core/mesh/shell_orientation.h"

namespace tquad {
namespace {

// The surface of an n x n x n lattice cube, face by face (axis a, side 0 or n), quads
// outward; the nodes on the cube's edges are numbered first. `inward[f]` reverses face
// f's quads; `skip` leaves out one face (-1: none), making an open box.
struct Cube {
  ShapeMesh mesh;
  NodeId boundary_nodes = 0;
};

Cube cube(int n, const std::vector<bool>& inward, int skip = -1, bool second_order = false) {
  Cube c;
  std::map<std::array<int, 3>, NodeId> id;
  auto on_edge = [n](const std::array<int, 3>& p) {
    int bounds = 0;
    for (int v : p) bounds += (v == 0 || v == n);
    return bounds >= 2;
  };
  // Lattice points of the surface: edge points first, then the rest.
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) {
        for (int k = 0; k <= n; ++k) {
          const std::array<int, 3> p{i, j, k};
          const bool surface = i == 0 || i == n || j == 0 || j == n || k == 0 || k == n;
          if (!surface || on_edge(p) != (pass == 0)) continue;
          id[p] = static_cast<NodeId>(c.mesh.nodes.size());
          c.mesh.nodes.push_back(Vec3{double(i), double(j), double(k)});
        }
      }
    }
    if (pass == 0) c.boundary_nodes = static_cast<NodeId>(c.mesh.nodes.size());
  }
  std::map<std::pair<NodeId, NodeId>, NodeId> middle;
  int face = 0;
  for (int a = 0; a < 3; ++a) {
    for (int side : {0, n}) {
      const int f = face++;
      if (f == skip) continue;
      const int b = (a + 1) % 3, cc = (a + 2) % 3;
      FaceMesh fm;
      fm.face = f;
      fm.first_quad = static_cast<std::int64_t>(c.mesh.quads.size());
      for (int u = 0; u < n; ++u) {
        for (int v = 0; v < n; ++v) {
          auto at = [&](int du, int dv) {
            std::array<int, 3> p{};
            p[a] = side;
            p[b] = u + du;
            p[cc] = v + dv;
            return id.at(p);
          };
          // e_b x e_c = e_a: outward on side n, inward on side 0.
          Quad q{at(0, 0), at(1, 0), at(1, 1), at(0, 1)};
          if ((side == 0) != static_cast<bool>(inward[f])) q = {q[0], q[3], q[2], q[1]};
          c.mesh.quads.push_back(q);
        }
      }
      fm.quad_count = static_cast<std::int64_t>(c.mesh.quads.size()) - fm.first_quad;
      c.mesh.faces.push_back(fm);
    }
  }
  if (second_order) {
    for (const Quad& q : c.mesh.quads) {
      Quad m{};
      for (int i = 0; i < 4; ++i) {
        const auto key = std::minmax(q[i], q[(i + 1) % 4]);
        auto it = middle.find(key);
        if (it == middle.end()) {
          it = middle.emplace(key, static_cast<NodeId>(c.mesh.nodes.size())).first;
          c.mesh.nodes.push_back(0.5 * (c.mesh.nodes[q[i]] + c.mesh.nodes[q[(i + 1) % 4]]));
        }
        m[i] = it->second;
      }
      c.mesh.mid_nodes.push_back(m);
    }
  }
  return c;
}

// Shared edges run the same way by their two quads (faces that disagree there).
int same_way_edges(const ShapeMesh& mesh) {
  std::map<std::pair<NodeId, NodeId>, int> runs;
  for (const Quad& q : mesh.quads) {
    for (int i = 0; i < 4; ++i) ++runs[{q[i], q[(i + 1) % 4]}];
  }
  int same = 0;
  for (const auto& [edge, count] : runs) same += count - 1;
  return same;
}

double volume(const ShapeMesh& mesh) {
  double v = 0;
  for (const Quad& q : mesh.quads) {
    const Vec3 p0 = mesh.nodes[q[0]], p1 = mesh.nodes[q[1]], p2 = mesh.nodes[q[2]], p3 = mesh.nodes[q[3]];
    v += (dot(p0, cross(p1, p2)) + dot(p0, cross(p2, p3))) / 6.0;
  }
  return v;
}

std::vector<bool> random_turns(std::mt19937& rng) {
  std::vector<bool> inward(6);
  std::bernoulli_distribution coin(0.5);
  for (int f = 0; f < 6; ++f) inward[f] = coin(rng);
  return inward;
}

TEST(ShellOrientation, ClosedShellsComeOutConsistentAndOutward) {
  for (int c : testing::cases(64)) {
    SCOPED_TRACE(testing::case_trace(c));
    std::mt19937 rng(c);
    const int n = 1 + c % 4;
    const std::vector<bool> inward = random_turns(rng);
    Cube box = cube(n, inward);
    const ShellOrientation result = orient_shells(box.mesh, box.boundary_nodes, {});
    EXPECT_TRUE(result.conflicts.empty());
    EXPECT_EQ(same_way_edges(box.mesh), 0);
    EXPECT_NEAR(volume(box.mesh), double(n) * n * n, 1e-9 * n * n * n);
    std::vector<int> expected;
    for (int f = 0; f < 6; ++f) if (inward[f]) expected.push_back(f);
    EXPECT_EQ(result.turned_faces, expected);
  }
}

TEST(ShellOrientation, AnOpenBoxKeepsTheSideOfTheLargerArea) {
  for (int c : testing::cases(64)) {
    SCOPED_TRACE(testing::case_trace(c));
    std::mt19937 rng(1000 + c);
    const int n = 2 + c % 3;
    const std::vector<bool> inward = random_turns(rng);
    const int skip = c % 6;
    Cube box = cube(n, inward, skip);
    int inward_faces = 0;
    for (int f = 0; f < 6; ++f) inward_faces += f != skip && inward[f];
    const ShellOrientation result = orient_shells(box.mesh, box.boundary_nodes, {});
    EXPECT_TRUE(result.conflicts.empty());
    EXPECT_EQ(same_way_edges(box.mesh), 0);
    // Five faces of equal area: the side three or more of them face wins.
    EXPECT_EQ(static_cast<int>(result.turned_faces.size()), inward_faces >= 3 ? 5 - inward_faces : inward_faces);
  }
}

TEST(ShellOrientation, AnchoredFacesNeverTurn) {
  for (int c : testing::cases(32)) {
    SCOPED_TRACE(testing::case_trace(c));
    std::mt19937 rng(2000 + c);
    std::vector<bool> inward = random_turns(rng);
    const int anchor = c % 6;
    inward[anchor] = false;  // the solid's face: outward
    Cube box = cube(2, inward);
    std::vector<char> anchored(6, 0);
    anchored[anchor] = 1;
    const ShellOrientation result = orient_shells(box.mesh, box.boundary_nodes, anchored);
    EXPECT_TRUE(result.conflicts.empty());
    EXPECT_EQ(same_way_edges(box.mesh), 0);
    EXPECT_GT(volume(box.mesh), 0);
    EXPECT_EQ(std::count(result.turned_faces.begin(), result.turned_faces.end(), anchor), 0);
  }
  // Two anchored faces that disagree: reported, and neither turned.
  std::vector<bool> inward(6, false);
  inward[0] = true;
  Cube box = cube(2, inward);
  const ShellOrientation result = orient_shells(box.mesh, box.boundary_nodes, std::vector<char>(6, 1));
  EXPECT_TRUE(result.turned_faces.empty());
  ASSERT_FALSE(result.conflicts.empty());
  for (const auto& [a, b] : result.conflicts) EXPECT_TRUE(a == 0 || b == 0) << a << " " << b;
}

TEST(ShellOrientation, SecondOrderMiddlesStayOnTheirEdges) {
  for (int c : testing::cases(16)) {
    SCOPED_TRACE(testing::case_trace(c));
    std::mt19937 rng(3000 + c);
    Cube box = cube(1 + c % 3, random_turns(rng), -1, /*second_order=*/true);
    orient_shells(box.mesh, box.boundary_nodes, {});
    EXPECT_EQ(same_way_edges(box.mesh), 0);
    for (std::size_t q = 0; q < box.mesh.quads.size(); ++q) {
      for (int i = 0; i < 4; ++i) {
        const Vec3 a = box.mesh.nodes[box.mesh.quads[q][i]], b = box.mesh.nodes[box.mesh.quads[q][(i + 1) % 4]];
        const Vec3 m = box.mesh.nodes[box.mesh.mid_nodes[q][i]];
        EXPECT_LT(norm(m - 0.5 * (a + b)), 1e-12);
      }
    }
  }
}

TEST(ShellOrientation, AOneSidedBandIsReportedNotForced) {
  // A Moebius band one quad wide, m quads in three faces: node (i, s) for i < m; the
  // band's end (m, s) is node (0, 1 - s).
  const int m = 12;
  ShapeMesh mesh;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < m; ++i) {
    for (int s = 0; s < 2; ++s) {
      const double t = 2 * pi * i / m, w = s ? 0.3 : -0.3;
      mesh.nodes.push_back(Vec3{(1 + w * std::cos(t / 2)) * std::cos(t), (1 + w * std::cos(t / 2)) * std::sin(t),
                                w * std::sin(t / 2)});
    }
  }
  auto node = [&](int i, int s) { return static_cast<NodeId>(i < m ? 2 * i + s : 2 * 0 + (1 - s)); };
  for (int f = 0; f < 3; ++f) {
    FaceMesh fm;
    fm.face = f;
    fm.first_quad = static_cast<std::int64_t>(mesh.quads.size());
    for (int i = f * m / 3; i < (f + 1) * m / 3; ++i) mesh.quads.push_back({node(i, 0), node(i + 1, 0), node(i + 1, 1), node(i, 1)});
    fm.quad_count = m / 3;
    mesh.faces.push_back(fm);
  }
  const ShellOrientation result = orient_shells(mesh, static_cast<NodeId>(mesh.nodes.size()), {});
  ASSERT_EQ(result.conflicts.size(), 1u);
  EXPECT_EQ(same_way_edges(mesh), 1);  // the one edge where the band meets its other side
}

}  // namespace
}  // namespace tquad
