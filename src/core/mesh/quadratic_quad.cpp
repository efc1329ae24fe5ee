#include "core/mesh/quadratic_quad.h"

#include <algorithm>
#include <cmath>

namespace tquad {

namespace {

// Reference coordinates of the eight nodes.
constexpr double kXi[8] = {-1, 1, 1, -1, 0, 1, 0, -1};
constexpr double kEta[8] = {-1, -1, 1, 1, -1, 0, 1, 0};

// Derivatives of the serendipity shape functions at (xi, eta).
void shape_derivatives(double xi, double eta, double d_xi[8], double d_eta[8]) {
  for (int i = 0; i < 4; ++i) {  // corners: N = (1 + xi xi_i)(1 + eta eta_i)(xi xi_i + eta eta_i - 1) / 4
    const double a = kXi[i], b = kEta[i];
    d_xi[i] = 0.25 * a * (1 + eta * b) * (2 * xi * a + eta * b);
    d_eta[i] = 0.25 * b * (1 + xi * a) * (xi * a + 2 * eta * b);
  }
  for (int i = 4; i < 8; ++i) {
    const double a = kXi[i], b = kEta[i];
    if (a == 0) {  // N = (1 - xi^2)(1 + eta eta_i) / 2
      d_xi[i] = -xi * (1 + eta * b);
      d_eta[i] = 0.5 * b * (1 - xi * xi);
    } else {  // N = (1 + xi xi_i)(1 - eta^2) / 2
      d_xi[i] = 0.5 * a * (1 - eta * eta);
      d_eta[i] = -eta * (1 + xi * a);
    }
  }
}

}  // namespace

std::array<Vec3, 8> element_positions(const ShapeMesh& mesh, std::size_t k) {
  std::array<Vec3, 8> p;
  for (int i = 0; i < 4; ++i) {
    p[i] = mesh.nodes[mesh.quads[k][i]];
    p[4 + i] = mesh.nodes[mesh.mid_nodes[k][i]];
  }
  return p;
}

namespace {

// The middle of quad k's straight edge i (from corner i to corner i + 1).
Vec3 chord_middle(const ShapeMesh& mesh, std::size_t k, int i) {
  return 0.5 * (mesh.nodes[mesh.quads[k][i]] + mesh.nodes[mesh.quads[k][(i + 1) % 4]]);
}

// Whether quad k's middles are on its chords (up to rounding: a plane's middles come
// from its parameters): such a quad folds only if its corners do.
bool straight_edges(const ShapeMesh& mesh, std::size_t k) {
  for (int i = 0; i < 4; ++i) {
    const double length = distance(mesh.nodes[mesh.quads[k][i]], mesh.nodes[mesh.quads[k][(i + 1) % 4]]);
    if (distance(mesh.nodes[mesh.mid_nodes[k][i]], chord_middle(mesh, k, i)) > 1e-9 * length) return false;
  }
  return true;
}

}  // namespace

long long straighten_folded_quads(ShapeMesh& mesh) {
  long long straightened = 0;
  for (int pass = 0; pass < 4; ++pass) {
    bool changed = false;
    for (std::size_t k = 0; k < mesh.quads.size(); ++k) {
      if (straight_edges(mesh, k) || quadratic_quad_min_scaled_jacobian(element_positions(mesh, k)) > 0) continue;
      for (int i = 0; i < 4; ++i) {
        const Vec3 chord = chord_middle(mesh, k, i);
        Vec3& middle = mesh.nodes[mesh.mid_nodes[k][i]];
        if (distance(middle, chord) > 0) {
          middle = chord;
          ++straightened;
          changed = true;
        }
      }
    }
    if (!changed) break;
  }
  return straightened;
}

double quadratic_quad_min_scaled_jacobian(const std::array<Vec3, 8>& p) {
  Vec3 normal = cross(p[2] - p[0], p[3] - p[1]);
  const double length = norm(normal);
  if (length == 0) return -1.0;
  normal = (1.0 / length) * normal;
  const double g = 1.0 / std::sqrt(3.0);
  static const double kSamples[13][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1},
                                         {-1, 0},  {0, 0},  {-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  double worst = 1.0;
  for (int s = 0; s < 13; ++s) {
    const double scale = s >= 9 ? g : 1.0;  // the last four: the Gauss points
    const double xi = scale * kSamples[s][0], eta = scale * kSamples[s][1];
    double d_xi[8], d_eta[8];
    shape_derivatives(xi, eta, d_xi, d_eta);
    Vec3 x_xi, x_eta;
    for (int i = 0; i < 8; ++i) {
      x_xi += d_xi[i] * p[i];
      x_eta += d_eta[i] * p[i];
    }
    const double lengths = norm(x_xi) * norm(x_eta);
    worst = std::min(worst, lengths > 0 ? dot(cross(x_xi, x_eta), normal) / lengths : -1.0);
  }
  return worst;
}

}  // namespace tquad
