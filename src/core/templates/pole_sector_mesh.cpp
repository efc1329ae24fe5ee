#include "core/templates/pole_sector_mesh.h"

#include <cmath>
#include <string>

#include "core/input_error.h"
#include "core/decomposition/patch_stitching.h"

namespace tquad {

namespace {

// Positions from `from` forward to `to` around a loop of n points.
int steps_forward(int from, int to, int n) { return ((to - from) % n + n) % n; }

double angle_of(const Vec3& v) { return std::atan2(v.y, v.x); }

}  // namespace

std::optional<QuadMesh> mesh_sector_in_halves(const std::vector<Vec3>& loop, int apex, int rim_start, int rim_end,
                                              const MeshOptions& options) {
  const int n = static_cast<int>(loop.size());
  if (n < 8 || apex < 0 || apex >= n || rim_start < 0 || rim_start >= n || rim_end < 0 || rim_end >= n) {
    return std::nullopt;
  }
  const int side = steps_forward(apex, rim_start, n), rim = steps_forward(rim_start, rim_end, n);
  if (side < 1 || rim < 4 || rim % 2 != 0 || side + rim + side != n || steps_forward(rim_end, apex, n) != side) {
    return std::nullopt;
  }
  // The rim node at an even count from rim_start whose direction from the apex is
  // nearest half the sector's angle (the rim's turn seen from the apex, unwrapped
  // node by node: any angle under a full turn).
  const Vec3& tip = loop[apex];
  std::vector<double> turned{0.0};
  for (int k = 1; k <= rim; ++k) {
    const double step = angle_of(loop[(rim_start + k) % n] - tip) - angle_of(loop[(rim_start + k - 1) % n] - tip);
    turned.push_back(turned.back() + std::remainder(step, 2 * M_PI));
  }
  int split = 2;
  for (int k = 4; k <= rim - 2; k += 2) {
    if (std::abs(turned[k] - 0.5 * turned[rim]) < std::abs(turned[split] - 0.5 * turned[rim])) split = k;
  }
  const int middle = (rim_start + split) % n;

  QuadMesh mesh;
  mesh.nodes = loop;
  // The bisector from the apex to the middle rim node, spaced as the first side.
  const double side_length = distance(loop[rim_start], tip);
  if (!(side_length > 0)) return std::nullopt;
  std::vector<NodeId> bisector{static_cast<NodeId>(apex)};
  for (int i = 1; i < side; ++i) {
    const double t = distance(loop[(apex + i) % n], tip) / side_length;
    mesh.nodes.push_back(tip + t * (loop[middle] - tip));
    bisector.push_back(static_cast<NodeId>(mesh.nodes.size() - 1));
  }
  bisector.push_back(static_cast<NodeId>(middle));
  const auto walk = [&](int from, int count, std::vector<NodeId>& ids) {
    for (int i = 0; i < count; ++i) ids.push_back(static_cast<NodeId>((from + i) % n));
  };
  try {
    // First half: apex, first side, rim up to the middle, bisector back.
    std::vector<NodeId> ids;
    walk(apex, side + split, ids);
    for (int i = side; i >= 1; --i) ids.push_back(bisector[i]);
    const std::string first_tree = append_patch(mesh, ids, {0, side, side + split}, options);
    // Second half: apex, bisector out, the rest of the rim, second side.
    ids.assign(bisector.begin(), bisector.end() - 1);
    walk(middle, rim - split + side, ids);
    const std::string second_tree = append_patch(mesh, ids, {0, side, side + rim - split}, options);
    mesh.template_tree = "S2[" + first_tree + "," + second_tree + "]";
  } catch (const InputError&) {
    return std::nullopt;
  }
  return mesh;
}

}  // namespace tquad
