#include "domain_generators.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "core/geometry/planar_predicates.h"
#include "boundary_generators.h"

namespace tquad::testing {

namespace {

using Polygon = std::vector<Vec3>;

Polygon orthogonal_outline(int kind, std::mt19937& rng, std::string& name) {
  std::uniform_real_distribution<double> u(0.2, 0.8);
  const double W = 1.0 + 2 * u(rng), H = 1.0 + u(rng);
  const double a = u(rng) * W * 0.45, b = u(rng) * H * 0.8;
  switch (kind) {
    case 0:
      name = "L";
      return {{0, 0}, {W, 0}, {W, b}, {a, b}, {a, H}, {0, H}};
    case 1: {
      name = "T";
      const double x0 = W / 2 - a / 2, x1 = W / 2 + a / 2;
      return {{x0, 0}, {x1, 0}, {x1, b}, {W, b}, {W, H}, {0, H}, {0, b}, {x0, b}};
    }
    case 2:
      name = "U";
      return {{0, 0}, {W, 0}, {W, H}, {W - a, H}, {W - a, b}, {a, b}, {a, H}, {0, H}};
    case 3: {
      name = "H";
      const double m0 = H * 0.5 * u(rng), m1 = H - H * 0.5 * u(rng);
      return {{0, 0}, {a, 0}, {a, m0}, {W - a, m0}, {W - a, 0}, {W, 0},
              {W, H}, {W - a, H}, {W - a, m1}, {a, m1}, {a, H}, {0, H}};
    }
    default: {
      const int teeth = 2 + static_cast<int>(rng() % 4);
      name = "comb" + std::to_string(teeth);
      const double pitch = W / (2 * teeth - 1), base = H * 0.3;
      Polygon p{{0, 0}, {W, 0}};
      for (int t = teeth - 1; t >= 0; --t) {
        const double x1 = (2 * t + 1) * pitch, x0 = 2 * t * pitch;
        p.push_back({x1, H});
        p.push_back({x0, H});
        if (t > 0) {
          p.push_back({x0, base});
          p.push_back({x0 - pitch, base});
        }
      }
      // Drop the duplicate corner (W, 0) -> (W, H) is the last tooth's right side.
      return p;
    }
  }
}

Polygon star_outline(std::mt19937& rng, std::string& name) {
  const int k = 5 + static_cast<int>(rng() % 10);
  std::uniform_real_distribution<double> r(0.45, 1.0), jitter(-0.3, 0.3);
  Polygon p;
  for (int i = 0; i < k; ++i) {
    const double t = 2 * M_PI * (i + 0.5 + jitter(rng)) / k, radius = 1.5 * r(rng);
    p.push_back({radius * std::cos(t), radius * std::sin(t), 0});
  }
  name = "star" + std::to_string(k);
  return p;
}

bool inside(const Polygon& p, const Vec3& q) {
  bool in = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    if ((p[i].y > q.y) != (p[j].y > q.y) &&
        q.x < (p[j].x - p[i].x) * (q.y - p[i].y) / (p[j].y - p[i].y) + p[i].x) in = !in;
  }
  return in;
}

double distance_to_segment(const Vec3& a, const Vec3& b, const Vec3& q) {
  const Vec3 d = b - a;
  const double t = std::clamp(dot(q - a, d) / dot(d, d), 0.0, 1.0);
  return distance(q, a + t * d);
}

double distance_to_outline(const Polygon& p, const Vec3& q) {
  double best = INFINITY;
  for (std::size_t i = 0; i < p.size(); ++i) best = std::min(best, distance_to_segment(p[i], p[(i + 1) % p.size()], q));
  return best;
}

// A hole of radius about r around c, clockwise: circle, square or slot.
struct Hole {
  Vec3 centre;
  double radius;
  int kind;
  double angle;
};

// Samples a polygon loop with about `size` per segment; polygon corners are flagged
// as vertices. `graded` grows each side's segments geometrically by 1.15.
DomainLoop sample_polygon(const Polygon& p, double size, bool graded, std::mt19937& rng) {
  DomainLoop loop;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 a = p[i], b = p[(i + 1) % p.size()];
    const int n = std::max(1, static_cast<int>(std::lround(distance(a, b) / size)));
    const std::vector<double> t = spacing_params(n, graded ? Spacing::Graded : Spacing::Uniform, 1.15, rng);
    for (int k = 0; k < n; ++k) {
      loop.points.push_back((1 - t[k]) * a + t[k] * b);
      loop.vertex.push_back(k == 0);
    }
  }
  return loop;
}

DomainLoop sample_hole(const Hole& h, double size, bool graded, std::mt19937& rng) {
  if (h.kind == 0) {  // circle, clockwise
    const int n = std::max(3, static_cast<int>(std::lround(2 * M_PI * h.radius / size)));
    DomainLoop loop;
    for (int k = 0; k < n; ++k) {
      const double t = h.angle - 2 * M_PI * k / n;
      loop.points.push_back({h.centre.x + h.radius * std::cos(t), h.centre.y + h.radius * std::sin(t), 0});
      loop.vertex.push_back(k == 0);
    }
    return loop;
  }
  // Square (kind 1) or slot (kind 2: 2.5 x 0.8 of the radius), rotated, clockwise.
  const double hx = h.kind == 1 ? h.radius * 0.7 : h.radius, hy = h.kind == 1 ? h.radius * 0.7 : h.radius * 0.32;
  Polygon corners;
  for (const auto& [sx, sy] : std::vector<std::pair<double, double>>{{1, 1}, {1, -1}, {-1, -1}, {-1, 1}}) {
    const double x = sx * hx, y = sy * hy;
    corners.push_back({h.centre.x + x * std::cos(h.angle) - y * std::sin(h.angle),
                       h.centre.y + x * std::sin(h.angle) + y * std::cos(h.angle), 0});
  }
  return sample_polygon(corners, size, graded, rng);
}

}  // namespace

GeneratedDomain generated_domain(int index) {
  std::mt19937 rng(static_cast<unsigned>(index) * 2654435761u + 17u);
  GeneratedDomain out;
  std::string shape;
  const int family = index % 7;
  const Polygon outline = family < 5 ? orthogonal_outline(family, rng, shape) : star_outline(rng, shape);
  double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
  for (const Vec3& p : outline) {
    lo_x = std::min(lo_x, p.x); hi_x = std::max(hi_x, p.x);
    lo_y = std::min(lo_y, p.y); hi_y = std::max(hi_y, p.y);
  }
  const double diagonal = std::hypot(hi_x - lo_x, hi_y - lo_y);
  const int holes_wanted = (index / 7) % 21;
  const bool graded = (index / 147) % 2 == 1;
  out.size = diagonal / (12 + static_cast<int>(rng() % 30));

  std::uniform_real_distribution<double> ux(lo_x, hi_x), uy(lo_y, hi_y), ur(0.02, 0.12), ua(0, M_PI);
  std::vector<Hole> holes;
  for (int attempt = 0; attempt < 400 && static_cast<int>(holes.size()) < holes_wanted; ++attempt) {
    Hole h{{ux(rng), uy(rng), 0}, ur(rng) * diagonal, static_cast<int>(rng() % 3), ua(rng)};
    const double margin = std::max(out.size, 0.3 * h.radius);
    if (!inside(outline, h.centre) || distance_to_outline(outline, h.centre) < h.radius + margin) continue;
    bool apart = true;
    for (const Hole& o : holes) apart = apart && distance(o.centre, h.centre) > o.radius + h.radius + margin;
    if (apart) holes.push_back(h);
  }
  out.domain.loops.push_back(sample_polygon(outline, out.size, graded, rng));
  for (const Hole& h : holes) out.domain.loops.push_back(sample_hole(h, out.size, graded, rng));
  if (out.domain.point_count() % 2 != 0) {  // even total: one more point on the outline's first side
    DomainLoop& outer = out.domain.loops[0];
    outer.points.insert(outer.points.begin() + 1, 0.5 * (outer.points[0] + outer.points[1]));
    outer.vertex.insert(outer.vertex.begin() + 1, 0);
  }
  out.description = "domain " + std::to_string(index) + " (" + shape + ", " + std::to_string(holes.size()) +
                    " holes, " + (graded ? "graded" : "uniform") + ", " +
                    std::to_string(out.domain.point_count()) + " boundary edges)";
  return out;
}

std::vector<int> loop_sizes(const PlanarDomain& domain) {
  std::vector<int> sizes;
  for (const DomainLoop& l : domain.loops) sizes.push_back(static_cast<int>(l.points.size()));
  return sizes;
}

DomainLoop polygon_loop(const std::vector<Vec3>& corners, int per_side) {
  DomainLoop loop;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3 a = corners[i], b = corners[(i + 1) % corners.size()];
    for (int k = 0; k < per_side; ++k) {
      loop.points.push_back(a + (static_cast<double>(k) / per_side) * (b - a));
      loop.vertex.push_back(k == 0);
    }
  }
  return loop;
}

DomainLoop circle_hole(Vec3 centre, double radius, int n) {
  DomainLoop loop;
  for (int k = 0; k < n; ++k) {
    const double t = -2 * M_PI * k / n;
    loop.points.push_back({centre.x + radius * std::cos(t), centre.y + radius * std::sin(t), 0});
  }
  loop.vertex.assign(n, 0);
  return loop;
}

}  // namespace tquad::testing
