#include "core/mesh/hex_mesh.h"

#include <algorithm>
#include <cmath>

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

double hex_volume(const std::array<Vec3, 8>& p) {
  // Six tetrahedra around the diagonal 0-6.
  return tetra_volume(p[0], p[1], p[2], p[6]) + tetra_volume(p[0], p[2], p[3], p[6]) +
         tetra_volume(p[0], p[3], p[7], p[6]) + tetra_volume(p[0], p[7], p[4], p[6]) +
         tetra_volume(p[0], p[4], p[5], p[6]) + tetra_volume(p[0], p[5], p[1], p[6]);
}

}  // namespace tquad
