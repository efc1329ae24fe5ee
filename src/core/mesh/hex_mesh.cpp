#include "core/mesh/hex_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace tquad {

namespace {

// The three neighbours of each corner, ordered so that a positive hexahedron gives a
// positive determinant at every corner.
constexpr int kCornerNeighbours[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                         {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};

double tetra_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return dot(cross(b - a, c - a), d - a) / 6.0;
}

}  // namespace

double hex_scaled_jacobian(const std::array<Vec3, 8>& p) {
  double worst = 1.0;
  for (int i = 0; i < 8; ++i) {
    const Vec3 a = p[kCornerNeighbours[i][0]] - p[i];
    const Vec3 b = p[kCornerNeighbours[i][1]] - p[i];
    const Vec3 c = p[kCornerNeighbours[i][2]] - p[i];
    const double lengths = norm(a) * norm(b) * norm(c);
    const double value = lengths > 0 ? dot(cross(a, b), c) / lengths : -1.0;
    worst = std::min(worst, value);
  }
  return worst;
}

double hex20_jacobian_ratio(const std::array<Vec3, 20>& p) {
  // Natural coordinates of the nodes: corners, then edge middles (one coordinate 0).
  static constexpr double kNode[20][3] = {
      {-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1},
      {0, -1, -1},  {1, 0, -1},  {0, 1, -1}, {-1, 0, -1}, {0, -1, 1},  {1, 0, 1},  {0, 1, 1}, {-1, 0, 1},
      {-1, -1, 0},  {1, -1, 0},  {1, 1, 0},  {-1, 1, 0}};
  const double g = std::sqrt(0.6);
  const double points[3] = {-g, 0.0, g};
  double lowest = INFINITY, highest = -INFINITY;
  for (double x : points) {
    for (double y : points) {
      for (double z : points) {
        Vec3 dx, dy, dz;  // the columns of the Jacobian: d position / d (x, y, z)
        for (int i = 0; i < 20; ++i) {
          const double xi = kNode[i][0], yi = kNode[i][1], zi = kNode[i][2];
          double nx, ny, nz;
          if (i < 8) {
            const double a = 1 + x * xi, b = 1 + y * yi, c = 1 + z * zi, s = x * xi + y * yi + z * zi - 2;
            nx = xi * b * c * (s + a) / 8;
            ny = yi * a * c * (s + b) / 8;
            nz = zi * a * b * (s + c) / 8;
          } else if (xi == 0) {
            nx = -x * (1 + y * yi) * (1 + z * zi) / 2;
            ny = (1 - x * x) * yi * (1 + z * zi) / 4;
            nz = (1 - x * x) * (1 + y * yi) * zi / 4;
          } else if (yi == 0) {
            nx = (1 - y * y) * xi * (1 + z * zi) / 4;
            ny = -y * (1 + x * xi) * (1 + z * zi) / 2;
            nz = (1 - y * y) * (1 + x * xi) * zi / 4;
          } else {
            nx = (1 - z * z) * xi * (1 + y * yi) / 4;
            ny = (1 - z * z) * (1 + x * xi) * yi / 4;
            nz = -z * (1 + x * xi) * (1 + y * yi) / 2;
          }
          dx = dx + nx * p[i];
          dy = dy + ny * p[i];
          dz = dz + nz * p[i];
        }
        const double det = dot(cross(dx, dy), dz);
        lowest = std::min(lowest, det);
        highest = std::max(highest, det);
      }
    }
  }
  return highest > 0 ? lowest / highest : -1.0;
}

double hex_volume(const std::array<Vec3, 8>& p) {
  // Six tetrahedra around the diagonal 0-6.
  return tetra_volume(p[0], p[1], p[2], p[6]) + tetra_volume(p[0], p[2], p[3], p[6]) +
         tetra_volume(p[0], p[3], p[7], p[6]) + tetra_volume(p[0], p[7], p[4], p[6]) +
         tetra_volume(p[0], p[4], p[5], p[6]) + tetra_volume(p[0], p[5], p[1], p[6]);
}

void merge_shared_face_nodes(HexMesh& mesh) {
  std::map<int, std::vector<std::size_t>> lists;  // face -> its entries in face_nodes
  for (std::size_t i = 0; i < mesh.face_nodes.size(); ++i) lists[mesh.face_nodes[i].first].push_back(i);
  std::vector<NodeId> into(mesh.nodes.size());
  for (std::size_t n = 0; n < into.size(); ++n) into[n] = static_cast<NodeId>(n);
  bool merged = false;
  for (const auto& [face, entries] : lists) {
    if (entries.size() < 2) continue;
    std::map<std::array<double, 3>, NodeId> first;
    for (NodeId n : mesh.face_nodes[entries[0]].second) first.emplace(std::array{mesh.nodes[n].x, mesh.nodes[n].y, mesh.nodes[n].z}, n);
    bool unmatched = false;
    for (std::size_t e = 1; e < entries.size(); ++e) {
      for (NodeId n : mesh.face_nodes[entries[e]].second) {
        const auto it = first.find(std::array{mesh.nodes[n].x, mesh.nodes[n].y, mesh.nodes[n].z});
        if (it == first.end()) {
          unmatched = true;
        } else if (it->second != n) {
          into[n] = it->second;
          merged = true;
        }
      }
    }
    if (unmatched) mesh.unshared_faces.push_back(face);
  }
  if (!merged) return;
  // A node merged into one merged in turn (a node on two shared faces): follow it.
  for (std::size_t n = 0; n < into.size(); ++n) {
    while (into[into[n]] != into[n]) into[n] = into[into[n]];
  }
  for (Hex& h : mesh.hexes) {
    for (NodeId& n : h) n = into[n];
  }
  for (auto& m : mesh.mid_nodes) {
    for (NodeId& n : m) n = into[n];
  }
  // Drop the copies: number the nodes still used, in order.
  std::vector<NodeId> renumber(mesh.nodes.size(), -1);
  std::vector<Vec3> kept;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    if (into[n] == static_cast<NodeId>(n)) {
      renumber[n] = static_cast<NodeId>(kept.size());
      kept.push_back(mesh.nodes[n]);
    }
  }
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) renumber[n] = renumber[into[n]];
  mesh.nodes = std::move(kept);
  for (Hex& h : mesh.hexes) {
    for (NodeId& n : h) n = renumber[n];
  }
  for (auto& m : mesh.mid_nodes) {
    for (NodeId& n : m) n = renumber[n];
  }
  for (auto& [face, nodes] : mesh.face_nodes) {
    for (NodeId& n : nodes) n = renumber[n];
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  }
}

}  // namespace tquad
