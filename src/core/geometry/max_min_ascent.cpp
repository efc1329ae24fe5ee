#include "core/geometry/max_min_ascent.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tquad {

namespace {

double smallest_rate(const std::vector<Vec3>& gradients, const Vec3& d) {
  double rate = std::numeric_limits<double>::infinity();
  for (const Vec3& g : gradients) rate = std::min(rate, g.x * d.x + g.y * d.y);
  return rate;
}

}  // namespace

Ascent max_min_ascent(const std::vector<Vec3>& gradients) {
  Ascent best;
  const auto consider = [&](double x, double y) {
    const double length = std::hypot(x, y);
    if (!(length > 0) || !std::isfinite(length)) return;
    const Vec3 d{x / length, y / length, 0.0};
    const double rate = smallest_rate(gradients, d);
    if (rate > best.rate) best = {d, rate};
  };
  for (std::size_t i = 0; i < gradients.size(); ++i) {
    consider(gradients[i].x, gradients[i].y);
    for (std::size_t j = i + 1; j < gradients.size(); ++j) {
      // Along these two directions g_i . d = g_j . d.
      const double dx = gradients[i].x - gradients[j].x, dy = gradients[i].y - gradients[j].y;
      consider(-dy, dx);
      consider(dy, -dx);
    }
  }
  return best;
}

}  // namespace tquad
