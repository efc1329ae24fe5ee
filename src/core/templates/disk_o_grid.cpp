#include "core/templates/disk_o_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/input_error.h"
#include "core/decomposition/patch_stitching.h"
#include "core/geometry/planar_predicates.h"
#include "core/geometry/planar_self_intersection.h"

namespace tquad {

namespace {

// Area centroid of a simple polygon (z ignored).
Vec3 centroid(const std::vector<Vec3>& p) {
  double twice = 0, cx = 0, cy = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& a = p[i];
    const Vec3& b = p[(i + 1) % p.size()];
    const double w = a.x * b.y - b.x * a.y;
    twice += w;
    cx += (a.x + b.x) * w;
    cy += (a.y + b.y) * w;
  }
  return {cx / (3 * twice), cy / (3 * twice), 0.0};
}

// Nodes from a to b (both excluded), `segments` equal steps.
std::vector<Vec3> between(const Vec3& a, const Vec3& b, int segments) {
  std::vector<Vec3> out;
  for (int k = 1; k < segments; ++k) out.push_back(a + (static_cast<double>(k) / segments) * (b - a));
  return out;
}

// Whether every turn of the loop is to the left (or straight): then the loop's arcs
// scaled towards the centroid, and any blend of them with the square's sides, stay
// inside it.
bool is_convex(const std::vector<Vec3>& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (orient2d(p[i], p[(i + 1) % n], p[(i + 2) % n]) < 0) return false;
  }
  return true;
}

}  // namespace

std::optional<QuadMesh> mesh_disk_o_grid(const PlanarDomain& domain, const MeshOptions& options) {
  if (domain.loop_count() != 1) return std::nullopt;
  const DomainLoop& loop = domain.loops[0];
  const std::vector<Vec3>& p = loop.points;
  const int n = static_cast<int>(p.size());
  if (n < 8 || n % 2 != 0) return std::nullopt;
  if (std::find(loop.vertex.begin(), loop.vertex.end(), 1) != loop.vertex.end()) {
    // A CAD vertex is allowed only where the loop runs straight on (a circle split
    // in two edges): the corners of the patches would otherwise miss it.
    for (int i = 0; i < n; ++i) {
      if (!loop.vertex.empty() && loop.vertex[i] &&
          std::abs(signed_angle(p[i] - p[(i + n - 1) % n], p[(i + 1) % n] - p[i])) > M_PI / 6) {
        return std::nullopt;
      }
    }
  }
  // With a and b both even (possible when n / 2 is), the middle square has a grid
  // node at its centre: the pole of a disk around one (a cone's tip), with four
  // quads around it alike. Otherwise the node nearest the pole is moved onto it and
  // its quads differ: at the tip of a cone of half-angle 45 degrees (52 points,
  // 13 + 13) the worst corner there was 0.64 where four alike give 0.87.
  int a = n / 4;
  if ((n / 2) % 2 == 0 && a % 2 == 1) --a;
  const int b = n / 2 - a;
  const std::array<int, 4> corner{0, a, a + b, 2 * a + b};
  const std::array<int, 4> arc{a, b, a, b};
  const Vec3 c = centroid(p);
  std::array<Vec3, 4> square;
  for (int k = 0; k < 4; ++k) square[k] = c + kSquareScale * (p[corner[k]] - c);
  // The square must be a convex counter-clockwise quad, and each connector must stay
  // inside the loop (a non-convex outline could cut across).
  for (int k = 0; k < 4; ++k) {
    if (orient2d(square[k], square[(k + 1) % 4], square[(k + 2) % 4]) <= 0) return std::nullopt;
  }
  double perimeter = 0;
  for (int i = 0; i < n; ++i) perimeter += distance(p[i], p[(i + 1) % n]);
  const double spacing = perimeter / n;
  std::vector<std::array<Vec3, 2>> connectors;
  for (int k = 0; k < 4; ++k) connectors.push_back({square[k], p[corner[k]]});
  for (int k = 0; k < 4; ++k) {
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      if (i == corner[k] || j == corner[k]) continue;
      if (segments_meet(connectors[k][0], connectors[k][1], p[i], p[j])) return std::nullopt;
    }
  }

  QuadMesh mesh;
  mesh.nodes = p;
  const auto add = [&](const Vec3& v) {
    mesh.nodes.push_back(v);
    return static_cast<NodeId>(mesh.nodes.size() - 1);
  };
  std::array<NodeId, 4> q;
  for (int k = 0; k < 4; ++k) q[k] = add(square[k]);
  // Connector k from the square's corner k out to the loop's corner point.
  std::array<std::vector<NodeId>, 4> spoke;
  int layers = 1;
  for (int k = 0; k < 4; ++k) layers = std::max(layers, static_cast<int>(std::lround(distance(square[k], p[corner[k]]) / spacing)));
  for (int k = 0; k < 4; ++k) {
    spoke[k].push_back(q[k]);
    for (const Vec3& v : between(square[k], p[corner[k]], layers)) spoke[k].push_back(add(v));
    spoke[k].push_back(corner[k]);
  }
  // Square side k from q[k] to q[k+1], arc[k] segments, bowed towards the loop's arc
  // on a convex loop (bowed_side).
  const bool bow = is_convex(p);
  std::array<std::vector<NodeId>, 4> side;
  for (int k = 0; k < 4; ++k) {
    side[k].push_back(q[k]);
    std::vector<Vec3> inner = between(square[k], square[(k + 1) % 4], arc[k]);
    if (bow) {
      for (int i = 1; i < arc[k]; ++i) {
        const Vec3 on_arc = c + kSquareScale * (p[(corner[k] + i) % n] - c);
        inner[i - 1] = inner[i - 1] + kSideBow * (on_arc - inner[i - 1]);
      }
    }
    for (const Vec3& v : inner) side[k].push_back(add(v));
    side[k].push_back(q[(k + 1) % 4]);
  }

  // Each patch as a loop of node ids with its corners, meshed by the templates.
  const auto mesh_patch = [&](const std::vector<std::vector<NodeId>>& sides) {
    std::vector<NodeId> ids;
    std::vector<int> corners;
    for (const std::vector<NodeId>& s : sides) {
      corners.push_back(static_cast<int>(ids.size()));
      ids.insert(ids.end(), s.begin(), s.end() - 1);
    }
    return append_patch(mesh, ids, corners, options);
  };
  const auto reversed = [](std::vector<NodeId> v) {
    std::reverse(v.begin(), v.end());
    return v;
  };
  std::string trees = mesh_patch({side[0], side[1], side[2], side[3]});
  for (int k = 0; k < 4; ++k) {
    std::vector<NodeId> outer;
    for (int i = 0; i <= arc[k]; ++i) outer.push_back(static_cast<NodeId>((corner[k] + i) % n));
    trees += "," + mesh_patch({outer, reversed(spoke[(k + 1) % 4]), reversed(side[k]), spoke[k]});
  }
  mesh.template_tree = "O5[" + trees + "]";
  return mesh;
}

}  // namespace tquad
