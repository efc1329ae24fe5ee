#include "core/templates/tip_strip.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/decomposition/planar_domain.h"
#include "core/mesh/quality.h"

namespace tquad {

std::optional<QuadMesh> mesh_tip_strip(const std::vector<Vec3>& points, int tip_a, int tip_b) {
  const int count = static_cast<int>(points.size());
  if (tip_a < 0 || tip_b < 0 || tip_a >= count || tip_b >= count || tip_a == tip_b) return std::nullopt;
  const int n = ((tip_b - tip_a) % count + count) % count;  // segments of chain A (and of chain B)
  if (2 * n != count || n < 3) return std::nullopt;
  const Vec3 up{0, 0, twice_signed_area(points) > 0 ? 1.0 : -1.0};  // the loop's way round
  const auto a = [&](int i) { return (tip_a + i) % count; };          // chain A, forward
  const auto b = [&](int i) { return ((tip_a - i) % count + count) % count; };  // chain B, backward
  QuadMesh mesh;
  mesh.nodes = points;
  const auto m = [&](int i) { return static_cast<NodeId>(count + i - 1); };  // m_1 .. m_{n-1}
  std::vector<Vec3> middle(n);
  for (int i = 1; i < n; ++i) middle[i] = 0.5 * (points[a(i)] + points[b(i)]);
  for (int i = 1; i < n; ++i) mesh.nodes.push_back(middle[i]);
  // Each tip's kite: m past the middle of a_1 b_1, along the band, where its corner
  // takes a third of what the tip leaves (360 degrees less the tip's angle), as its
  // corners at a_1 and b_1 then about do.
  const auto kite = [&](int tip, int first_a, int first_b, int inner, NodeId node) {
    const Vec3 &t = points[tip], &pa = points[first_a], &pb = points[first_b];
    const Vec3 ta = pa - t, tb = pb - t;
    const double tip_angle = std::acos(std::clamp(dot(ta, tb) / (norm(ta) * norm(tb)), -1.0, 1.0));
    const Vec3 mid = 0.5 * (pa + pb);
    const Vec3 along = middle[inner] - mid;
    const double room = norm(along);
    if (room == 0) return;
    const double half_corner = (2 * M_PI - tip_angle) / 6;
    const double past = std::min(0.5 * distance(pa, pb) / std::tan(half_corner), 0.5 * room);
    mesh.nodes[node] = mid + (past / room) * along;
  };
  kite(a(0), a(1), b(1), 2, m(1));
  kite(a(n), a(n - 1), b(n - 1), n - 2, m(n - 1));
  mesh.quads.push_back({static_cast<NodeId>(b(1)), static_cast<NodeId>(a(0)), static_cast<NodeId>(a(1)), m(1)});
  for (int i = 1; i + 1 < n; ++i) {
    mesh.quads.push_back({static_cast<NodeId>(a(i)), static_cast<NodeId>(a(i + 1)), m(i + 1), m(i)});
    mesh.quads.push_back({static_cast<NodeId>(b(i + 1)), static_cast<NodeId>(b(i)), m(i), m(i + 1)});
  }
  mesh.quads.push_back(
      {static_cast<NodeId>(a(n - 1)), static_cast<NodeId>(a(n)), static_cast<NodeId>(b(n - 1)), m(n - 1)});
  for (const Quad& q : mesh.quads) {
    const std::array<Vec3, 4> p{mesh.nodes[q[0]], mesh.nodes[q[1]], mesh.nodes[q[2]], mesh.nodes[q[3]]};
    if (!(scaled_jacobian(p, up) > 0)) return std::nullopt;  // a corner turning the wrong way, or flat
  }
  mesh.template_tree = "S" + std::to_string(n);
  return mesh;
}

}  // namespace tquad
