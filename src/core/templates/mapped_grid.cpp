#include "core/templates/mapped_grid.h"
#include "core/cancellation.h"

#include <vector>

#include "core/geometry/curve_geometry.h"

namespace tquad {

void mesh_mapped_grid(const Region& region, MeshBuilder& builder) {
  const auto& bottom = region.curves[0];  // i = 0..n at j = 0
  const auto& right = region.curves[1];   // j = 0..m at i = n
  const auto& top = region.curves[2];     // runs i = n..0 at j = m
  const auto& left = region.curves[3];    // runs j = m..0 at i = 0
  const int n = static_cast<int>(bottom.size()) - 1;
  const int m = static_cast<int>(right.size()) - 1;
  std::vector<Vec3>& nodes = builder.nodes();

  // Normalized arc-length parameters of each side's nodes.
  const CurveGeometry tb(bottom, nodes), tr(right, nodes), ttop(top, nodes), tleft(left, nodes);
  const Vec3 p00 = nodes[bottom[0]], p10 = nodes[right[0]], p11 = nodes[top[0]],
             p01 = nodes[left[0]];

  std::vector<NodeId> below(bottom.begin(), bottom.end());
  std::vector<NodeId> row(static_cast<std::size_t>(n) + 1);
  auto& quads = builder.quads();
  for (int j = 1; j <= m; ++j) {
    if (j == m) {
      for (int i = 0; i <= n; ++i) row[i] = top[n - i];
    } else {
      row[0] = left[m - j];
      row[n] = right[j];
      const double vl = 1.0 - tleft.param(m - j), vr = tr.param(j);
      const Vec3 L = nodes[left[m - j]], R = nodes[right[j]];
      for (int i = 1; i < n; ++i) {
        const double ub = tb.param(i), ut = 1.0 - ttop.param(n - i);
        // Intersection of u = ub + v (ut - ub) with v = vl + u (vr - vl).
        const double u = (ub + vl * (ut - ub)) / (1.0 - (ut - ub) * (vr - vl));
        const double v = vl + u * (vr - vl);
        const Vec3& B = nodes[bottom[i]];
        const Vec3& T = nodes[top[n - i]];
        const Vec3 p = (1 - v) * B + v * T + (1 - u) * L + u * R -
                       ((1 - u) * (1 - v) * p00 + u * (1 - v) * p10 + u * v * p11 +
                        (1 - u) * v * p01);
        row[i] = builder.add_node(p);
      }
    }
    for (int i = 0; i < n; ++i) quads.push_back({below[i], below[i + 1], row[i + 1], row[i]});
    below.swap(row);
    poll_cancellation(static_cast<std::size_t>(n));
  }
}

}  // namespace tquad
