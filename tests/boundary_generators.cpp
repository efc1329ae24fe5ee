#include "boundary_generators.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"

namespace tquad::testing {

std::vector<double> spacing_params(int n, Spacing kind, double ratio, std::mt19937& rng) {
  std::vector<double> sizes(n, 1.0);
  if (kind == Spacing::Graded) {
    for (int i = 1; i < n; ++i) sizes[i] = sizes[i - 1] * ratio;
  } else if (kind == Spacing::Random) {
    std::uniform_real_distribution<double> size(1.0, 3.0);
    for (double& s : sizes) s = size(rng);
  }
  std::vector<double> t{0.0};
  double total = 0;
  for (double s : sizes) total += s;
  for (int i = 0; i < n; ++i) t.push_back(t.back() + sizes[i] / total);
  t.back() = 1.0;
  return t;
}

BoundaryLoop sample_loop(const std::vector<Curve>& curves, const std::vector<int>& counts,
                         const std::vector<std::vector<double>>& params) {
  BoundaryLoop loop;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    loop.corners.push_back(static_cast<int>(loop.points.size()));
    for (int i = 0; i < counts[k]; ++i) loop.points.push_back(curves[k](params[k][i]));
  }
  return loop;
}

Curve line(Vec3 a, Vec3 b) {
  return [a, b](double t) { return (1 - t) * a + t * b; };
}

Curve arc(Vec3 a, Vec3 b, double sagitta) {
  if (sagitta == 0) return line(a, b);
  return [a, b, sagitta](double t) {
    const Vec3 chord = b - a;
    const double c = norm(chord);
    const Vec3 left{-chord.y / c, chord.x / c, 0};
    const double h = sagitta * c;  // signed height of the arc's midpoint
    // Circle through a, b and the midpoint raised by h: radius and centre offset.
    const double radius = (h * h + c * c / 4) / (2 * std::abs(h));
    const double sign = h > 0 ? 1.0 : -1.0;
    const Vec3 mid = 0.5 * (a + b);
    const Vec3 centre = mid + (sign * (std::abs(h) - radius)) * left;
    const double half = std::asin(std::min(1.0, (c / 2) / radius));
    const double sweep = std::abs(h) > radius ? 2 * (M_PI - half) : 2 * half;
    const Vec3 ua = (1.0 / radius) * (a - centre);
    // A left bulge puts the centre on the right: the arc turns clockwise from a to b.
    const double angle = -sign * sweep * t;
    const Vec3 u{ua.x * std::cos(angle) - ua.y * std::sin(angle),
                 ua.x * std::sin(angle) + ua.y * std::cos(angle), 0};
    return Vec3{centre.x + radius * u.x, centre.y + radius * u.y, a.z};
  };
}

namespace {

std::vector<std::vector<double>> uniform_params(const std::vector<int>& counts) {
  std::mt19937 unused(0);
  std::vector<std::vector<double>> p;
  for (int n : counts) p.push_back(spacing_params(n, Spacing::Uniform, 1.0, unused));
  return p;
}

}  // namespace

BoundaryLoop square_boundary(int A, int B, int C, int D) {
  const Vec3 p0{0, 0, 0}, p1{1, 0, 0}, p2{1, 1, 0}, p3{0, 1, 0};
  const std::vector<int> counts{A, C, B, D};
  return sample_loop({line(p0, p1), line(p1, p2), line(p2, p3), line(p3, p0)}, counts,
                     uniform_params(counts));
}

BoundaryLoop triangle_boundary(int A, int B, int C) {
  const Vec3 p0{0, 0, 0}, p1{1, 0, 0}, p2{0.5, std::sqrt(3.0) / 2, 0};
  const std::vector<int> counts{A, B, C};
  return sample_loop({line(p0, p1), line(p1, p2), line(p2, p0)}, counts, uniform_params(counts));
}

namespace {

// Random counts in 1..40 (2..40 for two curves) with an even total.
std::vector<int> random_counts(int curves, std::mt19937& rng) {
  std::uniform_int_distribution<int> count(curves == 2 ? 2 : 1, 40);
  std::vector<int> n(curves);
  for (int& c : n) c = count(rng);
  int total = 0;
  for (int c : n) total += c;
  if (total % 2 != 0) {
    int& c = n[std::uniform_int_distribution<int>(0, curves - 1)(rng)];
    c += c < 40 ? 1 : -1;
  }
  return n;
}

// Corners of a convex polygon: a regular polygon with jittered vertex angles and radii.
std::vector<Vec3> convex_corners(int k, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.35, 0.35), radius(0.7, 1.3);
  std::vector<Vec3> c;
  for (int i = 0; i < k; ++i) {
    const double angle = 2 * M_PI * (i + jitter(rng)) / k;
    const double r = k == 4 ? radius(rng) : 1.0;
    c.push_back({r * std::cos(angle), r * std::sin(angle), 0});
  }
  return c;
}

// Convex, with every corner between 25 and 170 degrees (so that sides bent inwards
// for the non-convex family do not cross their neighbours).
bool is_convex(const std::vector<Vec3>& c) {
  const int k = static_cast<int>(c.size());
  for (int i = 0; i < k; ++i) {
    const Vec3 a = c[(i + 1) % k] - c[i], b = c[(i + 2) % k] - c[(i + 1) % k];
    const double turn = std::atan2(cross(a, b).z, dot(a, b));  // pi - interior angle
    if (turn < 10 * M_PI / 180 || turn > 155 * M_PI / 180) return false;
  }
  return true;
}

// Curved 3D surfaces the planar shapes are wrapped on.
Vec3 lift(const Vec3& p, int surface) {
  switch (surface) {
    case 0: return {p.x, p.y, 0.3 * std::sin(2 * p.x) * std::cos(1.5 * p.y)};  // wavy sheet
    case 1: {  // cylinder of radius 1.5 around the y axis
      const double r = 1.5;
      return {r * std::sin(p.x / r), p.y, r * std::cos(p.x / r)};
    }
    default: {  // sphere cap of radius 2
      const double r = 2.0, d = std::sqrt(p.x * p.x + p.y * p.y);
      if (d == 0) return {0, 0, r};
      const double polar = d / r;
      return {r * std::sin(polar) * p.x / d, r * std::sin(polar) * p.y / d, r * std::cos(polar)};
    }
  }
}

}  // namespace

namespace {

GeneratedCase generated_case_attempt(int index, unsigned attempt) {
  std::mt19937 rng(static_cast<unsigned>(index) * 2654435761u + 12345u + attempt * 7919u);
  const int curves = 2 + index % 3;
  const int shape = (index / 3) % 4;  // 0, 1: convex; 2: mildly non-convex; 3: curved 3D
  GeneratedCase out;
  const std::vector<int> counts = random_counts(curves, rng);

  std::vector<Curve> sides;
  std::uniform_real_distribution<double> dent(0.03, 0.12);
  if (curves == 2) {
    // A lens: two arcs between (-1, 0) and (1, 0), each turning 2 atan(2 sagitta) at a
    // tip; sagittas up to 0.35 keep the tips' angles under 140 degrees (convex).
    // Non-convex: one arc has an S bend.
    std::uniform_real_distribution<double> sagitta(0.08, 0.35);
    const Vec3 a{-1, 0, 0}, b{1, 0, 0};
    sides = {arc(a, b, -sagitta(rng)), arc(b, a, -sagitta(rng))};
    if (shape == 2) {
      const Curve lower = sides[0];
      const double d = dent(rng);
      sides[0] = [lower, d](double t) { Vec3 p = lower(t); p.y += d * std::sin(2 * M_PI * t); return p; };
    }
  } else {
    std::vector<Vec3> corners;
    do { corners = convex_corners(curves, rng); } while (!is_convex(corners));
    for (int i = 0; i < curves; ++i) {
      const Vec3 a = corners[i], b = corners[(i + 1) % curves];
      // Non-convex: some sides bend slightly inwards.
      sides.push_back(shape == 2 && i % 2 == 0 ? arc(a, b, dent(rng)) : line(a, b));
    }
  }

  std::vector<std::vector<double>> params;
  std::uniform_real_distribution<double> ratio(0.85, 1.15);
  const Spacing kind = static_cast<Spacing>((index / 12) % 3);
  for (int n : counts) params.push_back(spacing_params(n, kind, ratio(rng), rng));
  out.loop = sample_loop(sides, counts, params);

  out.planar = shape != 3;
  out.convex_planar = shape <= 1;
  if (shape == 3) {
    const int surface = (index / 12) % 3;
    for (Vec3& p : out.loop.points) p = lift(p, surface);
  }
  static const char* shape_names[] = {"convex", "convex", "non-convex", "curved-3d"};
  static const char* spacing_names[] = {"uniform", "graded", "random"};
  out.description = "case " + std::to_string(index) + ": " + shape_names[shape] + ", " +
                    spacing_names[static_cast<int>(kind)] + ", counts";
  for (int n : counts) out.description += " " + std::to_string(n);
  return out;
}

}  // namespace

GeneratedCase generated_case(int index) {
  // A shape whose bent sides cross (possible for the non-convex family on narrow
  // corners) is drawn again.
  for (unsigned attempt = 0;; ++attempt) {
    GeneratedCase c = generated_case_attempt(index, attempt);
    try {
      validate_boundary(c.loop);
      return c;
    } catch (const InputError&) {
    }
  }
}

}  // namespace tquad::testing
