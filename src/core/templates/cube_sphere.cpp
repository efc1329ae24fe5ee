#include "core/templates/cube_sphere.h"

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace tquad {

CubeSphere cube_sphere(int m) {
  if (m < 2 || m % 2 != 0) {
    throw std::invalid_argument("cube_sphere: m must be even and at least 2, got " + std::to_string(m));
  }
  const int h = m / 2;
  CubeSphere out;
  // Nodes keyed by their integer point on the cube [-h, h]^3, so a node shared by two
  // or three cube faces is one node; its direction takes each coordinate c to
  // tan(c / h * pi / 4) (the equal angles), then unit length.
  std::map<std::array<int, 3>, NodeId> id;
  const auto node = [&](const std::array<int, 3>& c) {
    const auto found = id.find(c);
    if (found != id.end()) return found->second;
    const auto warp = [&](int k) { return std::tan(static_cast<double>(k) / h * M_PI / 4); };
    const Vec3 p{warp(c[0]), warp(c[1]), warp(c[2])};
    const NodeId n = static_cast<NodeId>(out.nodes.size());
    out.nodes.push_back((1.0 / norm(p)) * p);
    id.emplace(c, n);
    return n;
  };
  // Cube face `a` at side `s`: tangent axes b, c with e_b x e_c = e_a, so the cells
  // (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1) in (b, c) run counter-clockwise
  // seen from +e_a; reversed on the side -e_a.
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (const int s : {1, -1}) {
      for (int i = -h; i < h; ++i) {
        for (int j = -h; j < h; ++j) {
          std::array<std::array<int, 3>, 4> corner{};
          const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
          for (int k = 0; k < 4; ++k) {
            corner[k][a] = s * h;
            corner[k][b] = i + di[k];
            corner[k][c] = j + dj[k];
          }
          Quad q{node(corner[0]), node(corner[1]), node(corner[2]), node(corner[3])};
          if (s < 0) q = {q[0], q[3], q[2], q[1]};
          out.quads.push_back(q);
        }
      }
    }
  }
  // The seam: across the bottom face from its centre to x = h, up the face x = h,
  // across the top face back to its centre.
  for (int x = 0; x < h; ++x) out.seam.push_back(id.at({x, 0, -h}));
  for (int z = -h; z < h; ++z) out.seam.push_back(id.at({h, 0, z}));
  for (int x = h; x >= 0; --x) out.seam.push_back(id.at({x, 0, h}));
  return out;
}

}  // namespace tquad
