#include "core/mesh/quality.h"
#include "core/cancellation.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace tquad {

namespace {

// The formulas, each written once; the whole-quad measures below share sides and cross
// products through them.

// Lee-Lo's alpha of a corner whose sides are a and b, c the diagonal between their
// ends, twice_area = (a x b) . normal.
double lee_lo_alpha(const Vec3& a, const Vec3& b, const Vec3& c, double twice_area) {
  const double squares = dot(a, a) + dot(b, b) + dot(c, c);
  return squares > 0 ? std::sqrt(3.0) * twice_area / squares : 0.0;
}

// Lee-Lo of a quad from its corners' alphas: sorted a0 >= a1 >= a2 >= a3, (a2 a3) / (a0 a1),
// or a3 / a0 where a3 <= 0. The order found by minima and maxima, without branches:
// with std::sort this was about half of the quality stage on large meshes, and this
// order costs far less.
double lee_lo_of(const std::array<double, 4>& alpha) {
  const double low01 = std::min(alpha[0], alpha[1]), high01 = std::max(alpha[0], alpha[1]);
  const double low23 = std::min(alpha[2], alpha[3]), high23 = std::max(alpha[2], alpha[3]);
  const double a0 = std::max(high01, high23), a3 = std::min(low01, low23);
  const double middle_high = std::min(high01, high23), middle_low = std::max(low01, low23);
  if (a3 <= 0) {
    if (a3 == 0) {
      // A zero's sign as a stable sort leaves it last: the last zero's.
      for (int i = 3; i >= 0; --i) {
        if (alpha[i] == 0) return a0 > 0 ? std::max(-1.0, alpha[i] / a0) : -1.0;
      }
    }
    return a0 > 0 ? std::max(-1.0, a3 / a0) : -1.0;
  }
  return (std::min(middle_high, middle_low) * a3) / (a0 * std::max(middle_high, middle_low));
}

// A corner's scaled Jacobian from (a x b) . normal, |a| |b| and |normal|.
double corner_jacobian(double twice_area, double lengths, double normal_length) {
  if (lengths == 0) return -1.0;
  return normal_length > 0 ? twice_area / (lengths * normal_length) : 0.0;
}

// Whether the smallest of a quad's corner areas |e_i x e_(i-1)| (the bilinear map's
// Jacobian determinant at the corners) is under kCollapsedAreaRatio of the largest.
bool collapsed_corners(const std::array<double, 4>& area) {
  const double low = std::min(std::min(area[0], area[1]), std::min(area[2], area[3]));
  const double high = std::max(std::max(area[0], area[1]), std::max(area[2], area[3]));
  return !(low >= kCollapsedAreaRatio * high) || high == 0;
}

// A quad's sides, edge[i] from corner i to corner i + 1, their lengths, the shortest
// and the longest.
struct QuadSides {
  std::array<Vec3, 4> edge;
  std::array<double, 4> length;
  double shortest = INFINITY, longest = 0;
};
QuadSides quad_sides(const std::array<Vec3, 4>& p) {
  QuadSides s;
  for (int i = 0; i < 4; ++i) {
    s.edge[i] = p[(i + 1) % 4] - p[i];
    s.length[i] = norm(s.edge[i]);
    s.shortest = std::min(s.shortest, s.length[i]);
    s.longest = std::max(s.longest, s.length[i]);
  }
  return s;
}

}  // namespace

double lee_lo_quality(const std::array<Vec3, 4>& p, const Vec3& normal) {
  std::array<double, 4> alpha;
  for (int i = 0; i < 4; ++i) {
    const Vec3& prev = p[(i + 3) % 4];
    const Vec3& here = p[i];
    const Vec3& next = p[(i + 1) % 4];
    const Vec3 a = next - here, b = prev - here;
    alpha[i] = lee_lo_alpha(a, b, next - prev, dot(cross(a, b), normal));
  }
  return lee_lo_of(alpha);
}

double corner_scaled_jacobian(const std::array<Vec3, 4>& p, int i, const Vec3& normal) {
  const Vec3 a = p[(i + 1) % 4] - p[i], b = p[(i + 3) % 4] - p[i];
  return corner_jacobian(dot(cross(a, b), normal), norm(a) * norm(b), norm(normal));
}

double scaled_jacobian(const std::array<Vec3, 4>& p, const Vec3& normal) {
  double worst = 1.0;
  for (int i = 0; i < 4; ++i) worst = std::min(worst, corner_scaled_jacobian(p, i, normal));
  return worst;
}

namespace {

// A cross product of two vectors of the z = 0 plane: its z component alone, the x and
// y ones being zero.
struct AlongZ {
  double z;
};
AlongZ operator*(double s, AlongZ a) { return {s * a.z}; }
double dot(AlongZ a, AlongZ b) { return a.z * b.z; }
double norm(AlongZ a) { return std::sqrt(a.z * a.z); }  // as norm(Vec3) of (0, 0, z)

// quad_corners' arithmetic for either kind of cross product: `cross_of(a, b)` gives a
// Vec3, or an AlongZ in the z = 0 plane; `signed_by(turn, i, own)` corner i's value
// from its turn (e_next x e_prev, unit sides) and its value `own` against the quad's
// own normal.
template <typename CrossOf, typename SignedBy>
QuadCorners corners_from(const std::array<Vec3, 4>& p, const CrossOf& cross_of, const SignedBy& signed_by) {
  const auto [edge, length, shortest, longest] = quad_sides(p);
  QuadCorners out;
  out.edge_ratio = longest > 0 ? shortest / longest : 0.0;
  auto own = cross_of(p[2] - p[0], p[3] - p[1]);  // the diagonals' normal
  const double own_length = norm(own);
  if (own_length > 0) own = (1.0 / own_length) * own;
  std::array<double, 4> area{};
  for (int i = 0; i < 4; ++i) {
    const double lengths = length[i] * length[(i + 3) % 4];
    if (lengths == 0) {
      out.jacobian[i] = out.own_jacobian[i] = -1.0;
      continue;
    }
    // (e_next x e_prev) with e_prev = -edge[i - 1].
    const auto corner = cross_of(edge[i], edge[(i + 3) % 4]);
    area[i] = norm(corner);
    const auto turn = (-1.0 / lengths) * corner;
    out.own_jacobian[i] = dot(turn, own);
    out.jacobian[i] = signed_by(turn, i, out.own_jacobian[i]);
  }
  out.collapsed = collapsed_corners(area);
  return out;
}

}  // namespace

QuadCorners quad_corners(const std::array<Vec3, 4>& p, const std::array<Vec3, 4>& unit_normal) {
  return corners_from(
      p, [](const Vec3& a, const Vec3& b) { return cross(a, b); },
      [&](const Vec3& turn, int i, double own) {
        const Vec3& n = unit_normal[i];
        return n.x == 0 && n.y == 0 && n.z == 0 ? own : dot(turn, n);
      });
}

QuadCorners planar_quad_corners(const std::array<Vec3, 4>& p) {
  return corners_from(
      p, [](const Vec3& a, const Vec3& b) { return AlongZ{a.x * b.y - a.y * b.x}; },
      [](AlongZ turn, int, double) { return turn.z; });
}

QuadQuality quad_quality(const std::array<Vec3, 4>& p, const Vec3& normal) {
  // The side before corner i, p[i - 1] - p[i], is exactly minus edge i - 1, so its
  // length is length[i - 1]; the corner's cross product serves both measures.
  const auto [edge, length, shortest, longest] = quad_sides(p);
  const double normal_length = norm(normal);
  std::array<double, 4> alpha, area;
  QuadQuality out;
  out.scaled_jacobian = 1.0;
  for (int i = 0; i < 4; ++i) {
    const Vec3& a = edge[i];
    const Vec3 b = p[(i + 3) % 4] - p[i];
    const Vec3 turn = cross(a, b);
    area[i] = norm(turn);
    const double twice_area = dot(turn, normal);
    alpha[i] = lee_lo_alpha(a, b, p[(i + 1) % 4] - p[(i + 3) % 4], twice_area);
    out.scaled_jacobian =
        std::min(out.scaled_jacobian, corner_jacobian(twice_area, length[i] * length[(i + 3) % 4], normal_length));
  }
  out.lee_lo = lee_lo_of(alpha);
  out.collapsed = collapsed_corners(area);
  return out;
}

bool is_collapsed(const std::array<Vec3, 4>& p) {
  std::array<double, 4> area;
  for (int i = 0; i < 4; ++i) area[i] = norm(cross(p[(i + 1) % 4] - p[i], p[(i + 3) % 4] - p[i]));
  return collapsed_corners(area);
}

double own_scaled_jacobian(const std::array<Vec3, 4>& p) {
  return scaled_jacobian(p, cross(p[2] - p[0], p[3] - p[1]));
}

bool is_bad_quad(const std::array<Vec3, 4>& p, double surface_worst) {
  return !(surface_worst > kDegenerateUpTo) || !(own_scaled_jacobian(p) > kDegenerateUpTo) || is_collapsed(p);
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

int jacobian_bin(double j) {
  if (!(j >= 0)) return 0;
  return 1 + std::min(9, static_cast<int>(j * 10));
}

PerQuadQuality per_quad_quality(const std::vector<Vec3>& nodes, const std::vector<Quad>& quads,
                                const std::optional<Vec3>& reference) {
  PerQuadQuality out;
  out.lee_lo.reserve(quads.size());
  out.scaled_jacobian.reserve(quads.size());
  for (const Quad& q : quads) {
    poll_cancellation(4);
    const std::array<Vec3, 4> p{nodes[q[0]], nodes[q[1]], nodes[q[2]], nodes[q[3]]};
    Vec3 normal;
    if (reference) {
      normal = *reference;
    } else {
      normal = cross(p[2] - p[0], p[3] - p[1]);
      const double length = norm(normal);
      normal = length > 0 ? (1.0 / length) * normal : Vec3{0, 0, 0};
    }
    const QuadQuality quality = quad_quality(p, normal);
    out.lee_lo.push_back(quality.lee_lo);
    out.scaled_jacobian.push_back(quality.scaled_jacobian);
    out.collapsed += quality.collapsed ? 1 : 0;
  }
  return out;
}

namespace {

// The scaled-Jacobian part of a summary from per-quad values; below -inverted_below
// is inverted.
void summarize_jacobians(QualitySummary& summary, const std::vector<double>& per_quad, double inverted_below) {
  Accumulator jacobian;
  summary.inverted = summary.degenerate = 0;
  summary.jacobian_histogram.fill(0);
  for (double j : per_quad) {
    jacobian.add(j);
    ++summary.jacobian_histogram[jacobian_bin(j)];
    if (j < -inverted_below) ++summary.inverted;
    else if (j <= kDegenerateUpTo) ++summary.degenerate;
  }
  summary.scaled_jacobian = jacobian.stats();
}

}  // namespace

QualitySummary summarize_quality(const std::vector<Vec3>& nodes, const std::vector<Quad>& quads,
                                 const std::optional<Vec3>& reference) {
  return summarize_quality(per_quad_quality(nodes, quads, reference));
}

QualitySummary summarize_quality(const PerQuadQuality& per_quad) {
  QualitySummary summary;
  Accumulator lee_lo;
  for (double q : per_quad.lee_lo) lee_lo.add(q);
  summary.lee_lo = lee_lo.stats();
  summarize_jacobians(summary, per_quad.scaled_jacobian, kInvertedBelow);
  summary.collapsed = per_quad.collapsed;
  return summary;
}

void use_scaled_jacobians(QualitySummary& summary, const std::vector<double>& per_quad) {
  summarize_jacobians(summary, per_quad, kSurfaceInvertedBelow);
}

QualitySummary measure_mesh_quality(ShapeMesh& mesh, const std::optional<Vec3>& reference) {
  PerQuadQuality per_quad = per_quad_quality(mesh.nodes, mesh.quads, reference);
  QualitySummary summary = summarize_quality(per_quad);
  mesh.lee_lo = std::move(per_quad.lee_lo);
  if (mesh.scaled_jacobian.size() == mesh.quads.size() && !mesh.quads.empty()) {
    use_scaled_jacobians(summary, mesh.scaled_jacobian);
  } else {
    mesh.scaled_jacobian = std::move(per_quad.scaled_jacobian);
  }
  return summary;
}

std::vector<std::pair<int, long long>> collapsed_quads_per_face(const ShapeMesh& mesh) {
  std::vector<std::pair<int, long long>> out;
  for (const FaceMesh& face : mesh.faces) {
    long long count = 0;
    for (std::int64_t k = face.first_quad; k < face.first_quad + face.quad_count; ++k) {
      const Quad& q = mesh.quads[static_cast<std::size_t>(k)];
      if (is_collapsed({mesh.nodes[q[0]], mesh.nodes[q[1]], mesh.nodes[q[2]], mesh.nodes[q[3]]})) ++count;
    }
    if (count > 0) out.push_back({face.face, count});
  }
  return out;
}

}  // namespace tquad
