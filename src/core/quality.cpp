#include "core/quality.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace tquad {

double lee_lo_quality(const std::array<Vec3, 4>& p, const Vec3& normal) {
  std::array<double, 4> alpha;
  for (int i = 0; i < 4; ++i) {
    const Vec3& prev = p[(i + 3) % 4];
    const Vec3& here = p[i];
    const Vec3& next = p[(i + 1) % 4];
    const Vec3 a = next - here, b = prev - here, c = next - prev;
    const double twice_area = dot(cross(a, b), normal);
    const double squares = dot(a, a) + dot(b, b) + dot(c, c);
    alpha[i] = squares > 0 ? std::sqrt(3.0) * twice_area / squares : 0.0;
  }
  std::sort(alpha.begin(), alpha.end(), std::greater<double>());
  if (alpha[3] <= 0) return alpha[0] > 0 ? std::max(-1.0, alpha[3] / alpha[0]) : -1.0;
  return (alpha[2] * alpha[3]) / (alpha[0] * alpha[1]);
}

double corner_scaled_jacobian(const std::array<Vec3, 4>& p, int i, const Vec3& normal) {
  const Vec3 a = p[(i + 1) % 4] - p[i], b = p[(i + 3) % 4] - p[i];
  const double lengths = norm(a) * norm(b), normal_length = norm(normal);
  if (lengths == 0) return -1.0;
  return normal_length > 0 ? dot(cross(a, b), normal) / (lengths * normal_length) : 0.0;
}

double scaled_jacobian(const std::array<Vec3, 4>& p, const Vec3& normal) {
  double worst = 1.0;
  for (int i = 0; i < 4; ++i) worst = std::min(worst, corner_scaled_jacobian(p, i, normal));
  return worst;
}

QuadCorners quad_corners(const std::array<Vec3, 4>& p, const std::array<Vec3, 4>& unit_normal) {
  std::array<Vec3, 4> edge;  // edge[i] from corner i to corner i + 1
  std::array<double, 4> length;
  double shortest = INFINITY, longest = 0;
  for (int i = 0; i < 4; ++i) {
    edge[i] = p[(i + 1) % 4] - p[i];
    length[i] = norm(edge[i]);
    shortest = std::min(shortest, length[i]);
    longest = std::max(longest, length[i]);
  }
  QuadCorners out;
  out.collapsed = shortest < kCollapsedEdgeRatio * longest;
  Vec3 own;  // the diagonals' normal, only where a node's normal is zero
  for (int i = 0; i < 4; ++i) {
    const Vec3& a = edge[i];
    const Vec3 b = -1.0 * edge[(i + 3) % 4];
    const double lengths = length[i] * length[(i + 3) % 4];
    if (lengths == 0) {
      out.jacobian[i] = -1.0;
      continue;
    }
    Vec3 n = unit_normal[i];
    double n_length = 1.0;
    if (n.x == 0 && n.y == 0 && n.z == 0) {
      if (norm(own) == 0) own = cross(p[2] - p[0], p[3] - p[1]);
      n = own;
      n_length = norm(own);
    }
    out.jacobian[i] = n_length > 0 ? dot(cross(a, b), n) / (lengths * n_length) : 0.0;
  }
  return out;
}

bool is_collapsed(const std::array<Vec3, 4>& p) {
  double shortest = INFINITY, longest = 0;
  for (int i = 0; i < 4; ++i) {
    const double edge = distance(p[i], p[(i + 1) % 4]);
    shortest = std::min(shortest, edge);
    longest = std::max(longest, edge);
  }
  return shortest < kCollapsedEdgeRatio * longest;
}

namespace {

struct Accumulator {
  double min = INFINITY, max = -INFINITY, sum = 0, sum_sq = 0;
  long long n = 0;
  void add(double x) {
    min = std::min(min, x); max = std::max(max, x);
    sum += x; sum_sq += x * x; ++n;
  }
  QualityStats stats() const {
    if (n == 0) return {};
    const double avg = sum / n;
    return {min, avg, max, std::sqrt(std::max(0.0, sum_sq / n - avg * avg))};
  }
};

}  // namespace

QualitySummary summarize_quality(const QuadMesh& mesh, const std::optional<Vec3>& reference) {
  return summarize_quality(mesh.nodes, mesh.quads, reference);
}

QualitySummary summarize_quality(const std::vector<Vec3>& nodes, const std::vector<Quad>& quads,
                                 const std::optional<Vec3>& reference) {
  Accumulator lee_lo, jacobian;
  QualitySummary summary;
  for (const Quad& q : quads) {
    const std::array<Vec3, 4> p{nodes[q[0]], nodes[q[1]], nodes[q[2]], nodes[q[3]]};
    Vec3 normal;
    if (reference) {
      normal = *reference;
    } else {
      normal = cross(p[2] - p[0], p[3] - p[1]);
      const double length = norm(normal);
      normal = length > 0 ? (1.0 / length) * normal : Vec3{0, 0, 0};
    }
    const double j = scaled_jacobian(p, normal);
    lee_lo.add(lee_lo_quality(p, normal));
    jacobian.add(j);
    if (is_collapsed(p)) ++summary.collapsed;
    if (j < -kInvertedBelow) ++summary.inverted;
    else if (j <= kDegenerateUpTo) ++summary.degenerate;
  }
  summary.lee_lo = lee_lo.stats();
  summary.scaled_jacobian = jacobian.stats();
  return summary;
}

void use_scaled_jacobians(QualitySummary& summary, const std::vector<double>& per_quad) {
  Accumulator jacobian;
  summary.inverted = summary.degenerate = 0;
  for (double j : per_quad) {
    jacobian.add(j);
    if (j < -kSurfaceInvertedBelow) ++summary.inverted;
    else if (j <= kDegenerateUpTo) ++summary.degenerate;
  }
  summary.scaled_jacobian = jacobian.stats();
}

}  // namespace tquad
