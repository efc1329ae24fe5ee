#include "core/decomposition/hole_rings.h"
#include "core/cancellation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "core/decomposition/face_decomposition.h"
#include "core/input_error.h"
#include "core/mesh/quality.h"

namespace tquad {

namespace {

// A ring quad's worst corner must reach this (a rectangle scores 1; a ring around a
// notch in the rim folds first).
constexpr double kRingMinCorner = 0.3;

// The domain's boundary points bucketed in square cells, for the clearance check.
class PointGrid {
 public:
  PointGrid(const PlanarDomain& domain, double cell) : cell_(cell) {
    for (int l = 0; l < domain.loop_count(); ++l) {
      for (const Vec3& p : domain.loops[l].points) cells_[key(p.x, p.y)].push_back({p, l});
    }
  }

  // Whether a point of a loop other than `loop` lies within `radius` (at most one
  // cell) of p.
  bool other_loop_near(const Vec3& p, int loop, double radius) const {
    const long long cx = index(p.x), cy = index(p.y);
    for (long long i = cx - 1; i <= cx + 1; ++i) {
      for (long long j = cy - 1; j <= cy + 1; ++j) {
        const auto it = cells_.find(pack(i, j));
        if (it == cells_.end()) continue;
        for (const auto& [q, l] : it->second) if (l != loop && distance(p, q) < radius) return true;
      }
    }
    return false;
  }

 private:
  long long index(double x) const { return static_cast<long long>(std::floor(x / cell_)); }
  static long long pack(long long i, long long j) { return i * 4'000'037LL + j; }
  long long key(double x, double y) const { return pack(index(x), index(y)); }

  double cell_;
  std::unordered_map<long long, std::vector<std::pair<Vec3, int>>> cells_;
};

// How far ring `layer` lies from the rim, in rim spacings: one spacing per ring
// (square quads), or with `graded` rings each kRingGrowth times as thick as the one
// inside it.
double ring_offset(int layer, bool graded) {
  return graded ? (std::pow(kRingGrowth, layer) - 1.0) / (kRingGrowth - 1.0) : static_cast<double>(layer);
}

double mean_spacing(const std::vector<Vec3>& points) {
  double sum = 0;
  for (std::size_t i = 0; i < points.size(); ++i) sum += distance(points[i], points[(i + 1) % points.size()]);
  return points.empty() ? 0.0 : sum / static_cast<double>(points.size());
}

// Hole loop `points` (clockwise, the domain on its left) offset into the domain by
// `factor` times each point's spacing, along the bisector of its sides' normals (the
// miter at most twice the thickness).
std::vector<Vec3> offset_loop(const std::vector<Vec3>& points, double factor) {
  const std::size_t n = points.size();
  std::vector<Vec3> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = points[(i + n - 1) % n];
    const Vec3& p = points[i];
    const Vec3& b = points[(i + 1) % n];
    const Vec3 d1 = p - a, d2 = b - p;
    const double l1 = norm(d1), l2 = norm(d2);
    const Vec3 n1{-d1.y / l1, d1.x / l1, 0.0}, n2{-d2.y / l2, d2.x / l2, 0.0};
    Vec3 m = n1 + n2;
    const double lm = norm(m);
    m = lm > 0 ? (1.0 / lm) * m : n1;
    const double miter = 1.0 / std::max(0.5, dot(m, n1));
    out[i] = p + (factor * 0.5 * (l1 + l2) * miter) * m;
  }
  return out;
}

double largest_spacing(const std::vector<Vec3>& points) {
  double largest = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    largest = std::max(largest, distance(points[i], points[(i + 1) % points.size()]));
  }
  return largest;
}

// The quads between two consecutive rings (`inside` nearer the hole), counter-clockwise.
bool ring_quads_fit(const std::vector<Vec3>& inside, const std::vector<Vec3>& outside) {
  const std::size_t n = inside.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const std::array<Vec3, 4> q{inside[i], inside[j], outside[j], outside[i]};
    if (scaled_jacobian(q, Vec3{0, 0, 1}) < kRingMinCorner) return false;
  }
  return true;
}

// The rings hole `loop` asks for: `layers`, or, where its rim is over
// kGradedRingContrast times finer than the outer loop (a local size on the hole), as
// many graded rings as reach the outer loop's spacing: the fine rim's
// quads then grow outward by the growth rate instead of stretching across the domain
// (kMaxHoleRingLayers at most). Returns {count, graded}.
std::pair<int, bool> wanted_rings(const PlanarDomain& domain, int loop, int layers) {
  const double rim = mean_spacing(domain.loops[loop].points), outer = mean_spacing(domain.loops[0].points);
  if (!(rim > 0) || !(outer > kGradedRingContrast * rim)) return {layers, false};
  const int count = static_cast<int>(std::ceil(std::log(outer / rim) / std::log(kRingGrowth)));
  return {std::min(kMaxHoleRingLayers, std::max(layers, count)), true};
}

// How many rings hole `loop` takes (0 to `layers`).
int rings_that_fit(const PlanarDomain& domain, const PointGrid& grid, int loop, int layers, bool graded) {
  const std::vector<Vec3>& rim = domain.loops[loop].points;
  const double spacing = largest_spacing(rim);
  for (int count = layers; count > 0; --count) {
    // Room for this hole's rings, a neighbour's as many, and one more ring between.
    const double clearance = (2 * ring_offset(count, graded) + 1) * spacing;  // at most `cell`, by its choice
    bool fits = true;
    std::vector<Vec3> inside = rim;
    for (int layer = 1; layer <= count && fits; ++layer) {
      const std::vector<Vec3> outside = offset_loop(rim, ring_offset(layer, graded));
      fits = ring_quads_fit(inside, outside);
      inside = outside;
    }
    for (const Vec3& p : rim) fits = fits && !grid.other_loop_near(p, loop, clearance);
    if (fits) return count;
  }
  return 0;
}

RingedDomain without_rings(const PlanarDomain& domain) {
  RingedDomain r;
  r.inner = domain;
  r.inner_node.resize(domain.point_count());
  for (int i = 0; i < domain.point_count(); ++i) r.inner_node[i] = i;
  return r;
}

}  // namespace

RingedDomain ring_holes(const PlanarDomain& domain, int layers) {
  if (domain.hole_count() == 0 || layers <= 0) return without_rings(domain);
  // Cells as large as the largest clearance asked for, so a query looks one cell around.
  double cell = 0;
  std::vector<std::pair<int, bool>> wanted(domain.loop_count(), {0, false});
  for (int l = 1; l < domain.loop_count(); ++l) {
    wanted[l] = wanted_rings(domain, l, layers);
    cell = std::max(cell, (2 * ring_offset(wanted[l].first, wanted[l].second) + 1) *
                              largest_spacing(domain.loops[l].points));
  }
  if (!(cell > 0) || !std::isfinite(cell)) return without_rings(domain);
  const PointGrid grid(domain, cell);

  RingedDomain r;
  r.inner.loops.push_back(domain.loops[0]);
  for (int i = 0; i < static_cast<int>(domain.loops[0].points.size()); ++i) r.inner_node.push_back(i);
  const NodeId first_ring_node = domain.point_count();
  for (int l = 1; l < domain.loop_count(); ++l) {
    const DomainLoop& hole = domain.loops[l];
    const int n = static_cast<int>(hole.points.size());
    const auto [asked, graded] = wanted[l];
    const int count = rings_that_fit(domain, grid, l, asked, graded);
    std::vector<NodeId> inside(n);
    for (int i = 0; i < n; ++i) inside[i] = domain.offset(l) + i;
    DomainLoop outermost = hole;
    for (int layer = 1; layer <= count; ++layer) {
      outermost.points = offset_loop(hole.points, ring_offset(layer, graded));
      std::vector<NodeId> outside(n);
      for (int i = 0; i < n; ++i) {
        outside[i] = first_ring_node + static_cast<NodeId>(r.ring_nodes.size());
        r.ring_nodes.push_back(outermost.points[i]);
      }
      for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        r.ring_quads.push_back({inside[i], inside[j], outside[j], outside[i]});
      }
      inside = outside;
      ++r.rings;
    }
    r.inner.loops.push_back(std::move(outermost));
    r.inner_node.insert(r.inner_node.end(), inside.begin(), inside.end());
  }
  if (r.rings == 0) return r;
  try {
    check_planar_domain(r.inner);
  } catch (const InputError&) {  // a boundary segment passes a ring: no rings at all
    return without_rings(domain);
  }
  return r;
}

QuadMesh join_rings(const PlanarDomain& domain, const RingedDomain& ringed, const QuadMesh& inner) {
  const int inner_points = ringed.inner.point_count();
  if (static_cast<int>(inner.nodes.size()) < inner_points) {
    throw std::logic_error("the inner mesh lacks its domain's points");
  }
  QuadMesh mesh;
  mesh.template_tree = inner.template_tree;
  for (const DomainLoop& loop : domain.loops) mesh.nodes.insert(mesh.nodes.end(), loop.points.begin(), loop.points.end());
  mesh.nodes.insert(mesh.nodes.end(), ringed.ring_nodes.begin(), ringed.ring_nodes.end());
  const NodeId base = static_cast<NodeId>(mesh.nodes.size());
  mesh.nodes.insert(mesh.nodes.end(), inner.nodes.begin() + inner_points, inner.nodes.end());
  mesh.quads = ringed.ring_quads;
  const auto whole = [&](NodeId v) { return v < inner_points ? ringed.inner_node[v] : base + (v - inner_points); };
  for (Quad q : inner.quads) {
    poll_cancellation(1);
    for (NodeId& v : q) v = whole(v);
    mesh.quads.push_back(q);
  }
  for (const std::vector<NodeId>& cut : inner.subregion_cuts) {
    std::vector<NodeId> c;
    for (NodeId v : cut) c.push_back(whole(v));
    mesh.subregion_cuts.push_back(std::move(c));
  }
  return mesh;
}

}  // namespace tquad
