#include "core/geometry/mean_value_surface.h"

#include <cmath>

#include "core/geometry/mean_plane.h"

namespace tquad {

MeanValueSurface::MeanValueSurface(const MeanPlane& plane, const std::vector<Vec3>& loop_points) : plane_(plane) {
  for (const Vec3& p : loop_points) {
    const Vec3 local = plane.local(p);
    xs_.push_back(local.x);
    ys_.push_back(local.y);
    heights_.push_back(local.z);
  }
}

namespace {

// tan(a / 2) of the angle a that an edge subtends at the point, and its derivatives
// in the point's x and y.
struct HalfTangent {
  double value = 0, dx = 0, dy = 0;
};

// Loop point i at (dx, dy) from the point, at distance r = 1 / inverse_r; (rx, ry)
// the distance's derivatives.
struct Spoke {
  double dx = 0, dy = 0, r = 0, inverse_r = 0, rx = 0, ry = 0;
};

}  // namespace

bool MeanValueSurface::height(double x, double y, double& h, double& hx, double& hy) const {
  // Weights w_i = (tan(a_{i-1} / 2) + tan(a_i / 2)) / r_i, with a_i the angle the edge
  // (i, i + 1) subtends at the point and tan(a / 2) = sin a / (1 + cos a) = s / (r_i
  // r_{i+1} + c) (s, c: cross and dot products of the vectors to the two ends); the
  // derivatives by the quotient rule, each vector to a loop point changing by -1 along
  // the axis the point moves on.
  const int n = static_cast<int>(xs_.size());
  double weighted = 0, total = 0, weighted_x = 0, weighted_y = 0, total_x = 0, total_y = 0;
  const auto spoke_to = [&](int i, Spoke& spoke) {
    spoke.dx = xs_[i] - x, spoke.dy = ys_[i] - y;
    spoke.r = std::sqrt(spoke.dx * spoke.dx + spoke.dy * spoke.dy);
    if (spoke.r == 0) return false;  // on a loop point
    spoke.inverse_r = 1 / spoke.r;
    spoke.rx = -spoke.dx * spoke.inverse_r, spoke.ry = -spoke.dy * spoke.inverse_r;
    return true;
  };
  const auto add = [&](int i, const Spoke& spoke, const HalfTangent& before, const HalfTangent& after) {
    const double sum = before.value + after.value;
    const double w = sum * spoke.inverse_r;
    const double wx = (before.dx + after.dx - w * spoke.rx) * spoke.inverse_r;
    const double wy = (before.dy + after.dy - w * spoke.ry) * spoke.inverse_r;
    weighted += w * heights_[i], total += w;
    weighted_x += wx * heights_[i], total_x += wx;
    weighted_y += wy * heights_[i], total_y += wy;
  };
  Spoke first_spoke, here, next;
  if (!spoke_to(0, first_spoke)) return false;
  here = first_spoke;
  HalfTangent first, before;
  for (int i = 0; i < n; ++i) {
    if (!spoke_to(i + 1 < n ? i + 1 : 0, next)) return false;
    const double s = here.dx * next.dy - here.dy * next.dx, c = here.dx * next.dx + here.dy * next.dy;
    const double d = here.r * next.r + c;
    if (d <= 1e-14 * here.r * next.r) return false;  // on the edge (i, i + 1)
    const double inverse_d = 1 / d, t = s * inverse_d;
    const double sx = here.dy - next.dy, sy = next.dx - here.dx;
    const double dx_d = here.rx * next.r + here.r * next.rx - here.dx - next.dx;
    const double dy_d = here.ry * next.r + here.r * next.ry - here.dy - next.dy;
    const HalfTangent edge{t, (sx - t * dx_d) * inverse_d, (sy - t * dy_d) * inverse_d};
    if (i == 0) {
      first = edge;
    } else {
      add(i, here, before, edge);
    }
    before = edge;
    here = next;
  }
  add(0, first_spoke, before, first);  // between edges (n - 1, 0) and (0, 1)
  if (!(total != 0)) return false;
  h = weighted / total;
  hx = (weighted_x - h * total_x) / total;
  hy = (weighted_y - h * total_y) / total;
  return std::isfinite(h) && std::isfinite(hx) && std::isfinite(hy);
}

bool MeanValueSurface::place(const Vec3& param, Vec3& position, Vec3& normal) const {
  double h, hx, hy;
  if (!height(param.x, param.y, h, hx, hy)) return false;
  position = plane_.point_at(param.x, param.y, h);
  normal = plane_.normal_of_slopes(hx, hy);
  return true;
}

}  // namespace tquad
