#include "core/repair/smoothing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/repair/area_untangling.h"
#include "core/repair/doublets.h"
#include "core/geometry/fitted_surface.h"
#include "core/cancellation.h"
#include "core/geometry/mean_value_surface.h"
#include "core/geometry/max_min_ascent.h"
#include "core/mesh/mesh_validation.h"
#include "core/mesh/node_adjacency.h"
#include "core/mesh/quality.h"
#include "core/repair/reflex_corners.h"

namespace tquad {

namespace {

// The steepest ascents (of the worst corner, of the quads' sum, quad_value): finite differences
// over kGradientStep of the shortest edge around the node (in the mesh coordinates);
// corners within kActiveBand of the worst count as at it; steps from kLargestStep of
// that edge down to kSmallestStep; at most kAscentIterations (kSumAscentIterations)
// steps per visit.
constexpr double kGradientStep = 1.0 / 256;
constexpr double kActiveBand = 0.01;
constexpr double kLargestStep = 0.25;
constexpr double kSmallestStep = 1.0 / 64;
constexpr int kAscentIterations = 8;
constexpr int kSumAscentIterations = 2;

// The compass search's eight directions (unit length, along the mesh coordinates;
// in each node's local frame instead, more of the mildly non-convex generated
// boundaries kept an inverted quad), and how many moves it takes at one step size.
constexpr double kHalfSqrt2 = 0.70710678118654752440;
const std::array<Vec3, 8> kCompass = {Vec3{1, 0, 0},   Vec3{kHalfSqrt2, kHalfSqrt2, 0},
                                      Vec3{0, 1, 0},   Vec3{-kHalfSqrt2, kHalfSqrt2, 0},
                                      Vec3{-1, 0, 0},  Vec3{-kHalfSqrt2, -kHalfSqrt2, 0},
                                      Vec3{0, -1, 0},  Vec3{kHalfSqrt2, -kHalfSqrt2, 0}};
constexpr int kStepsPerSize = 4;

// A move must raise the worst corner around the node by kWorstGain of its value (at
// least of kWorstGainFloor), or keep it and raise the quads' sum there (quad_value)
// by kSumGain: smaller gains cost passes and change nothing one sees. With any
// gain counted, the Laplacian moves rippled through whole O-grid disks (a large share
// of a fine disk's nodes moving in every pass); a relative gain stops that (the smoothing
// then costs less than the meshing) yet lets sliver quads (scaled Jacobian ~0.02)
// keep climbing by small steps. Against any gain counted, it leaves the worst quads
// and the means of CAD parts about as they were, some a little lower, some higher.
constexpr double kWorstGain = 1e-3;
constexpr double kWorstGainFloor = 0.01;
constexpr double kSumGain = 1e-3;

// The scaled Jacobian is blind to a short edge between good angles (a quad turning
// into a triangle): a move may not bring any quad around the node to an edge under
// this fraction of its longest, unless that quad's ratio rises. Without it the
// compass search that preceded the ascents drew interior nodes next to boundary
// nodes, leaving quads with a near-zero scaled Jacobian where there had been none.
constexpr double kShortEdgeRatio = 0.1;

// A move that opens a collapsed quad is taken even where it lowers the worst corner
// around the node, down to this.
constexpr double kCollapseTradeFloor = 0.02;

// A corner as the smoother judges it: the lower of its scaled Jacobian against the
// surface normals and in the quad's own plane (its diagonals' normal, where a shell
// element's Jacobian is taken). They part on a quad spanning a tight curve; with the
// surface's alone, the steepest ascent raised a warped quad against the surface
// normals while in its own plane it fell to a sliver (corners near 17 and 155 degrees).
double judged_corner(const QuadCorners& c, int j) { return std::min(c.jacobian[j], c.own_jacobian[j]); }

// The corners of a quad whose angles its corner i's node decides: its own and its two
// neighbours' (and, alike, the nodes that decide corner i's angle).
std::array<int, 3> decided_by(int i) { return {i, (i + 1) % 4, (i + 3) % 4}; }

// The sum the smoother raises, the worst held: over the quads around a node, each
// quad's lowest corner as judged_corner judges them (the quad's scaled Jacobian, whose
// mean is the mesh's mean quality) plus kCornerWeight times each corner the node
// decides. The quads' values alone are what the mean measures, but they say nothing
// of a quad's other corners, which the next move may need; with the corners alone, a
// move could raise three fair corners while the quad's lowest fell.
constexpr double kCornerWeight = 0.25;
double quad_value(const QuadCorners& c) {
  return std::min(std::min(judged_corner(c, 0), judged_corner(c, 1)), std::min(judged_corner(c, 2), judged_corner(c, 3)));
}

// The corners whose angle a node decides, summarized: the worst, their sum, and
// whether a quad around it is collapsed.
struct LocalQuality {
  double worst = 1.0, sum = 0.0;
  int collapsed = 0;
  double edge_ratio = 1.0;  // the quads' shortest edge over their longest, the lowest

  // Whether this (after a move) is better than `before`.
  bool improves_on(const LocalQuality& before) const {
    if (collapsed > before.collapsed) return false;
    if (edge_ratio < kShortEdgeRatio && edge_ratio < before.edge_ratio) return false;
    // Fewer collapsed quads is a gain of its own, if the worst corner holds or stays
    // over kCollapseTradeFloor: a collapsed quad refuses its face, a sharp corner
    // does not.
    if (collapsed < before.collapsed && (worst >= before.worst || worst > kCollapseTradeFloor)) return true;
    // Around a collapsed quad any gain counts: small steps are what opens it up.
    const double needed =
        before.collapsed > 0 ? 1e-12 : kWorstGain * std::max(std::abs(before.worst), kWorstGainFloor);
    if (worst > before.worst + needed) return true;
    return worst >= before.worst && sum > before.sum + kSumGain;
  }
};

Vec3 unit(const Vec3& v) {
  const double length = norm(v);
  return length > 0 ? (1.0 / length) * v : Vec3{};
}

// The nodes the Smoother moves, on a surface: mesh coordinates, positions and
// normals in arrays of their own, each move placed by a PlaceNode.
class SurfaceNodes {
 public:
  SurfaceNodes(std::vector<Vec3>& param, std::vector<Vec3>& position, std::vector<Vec3>& normal,
               const PlaceNode& place)
      : param_(param), position_(position), normal_(normal), place_(place) {
    unit_normal_.reserve(normal.size());
    for (const Vec3& v : normal) unit_normal_.push_back(unit(v));
  }

  std::size_t size() const { return param_.size(); }
  const Vec3& param(int n) const { return param_[n]; }
  const Vec3& position(int n) const { return position_[n]; }
  const Vec3& unit_normal(int n) const { return unit_normal_[n]; }
  bool singular(int n) const { return norm(normal_[n]) == 0; }  // a node on a pole stays there

  // What a move changes, to be put back.
  struct State {
    Vec3 param, position, normal, unit_normal;
  };
  State state(int n) const { return {param_[n], position_[n], normal_[n], unit_normal_[n]}; }
  void restore(int n, const State& kept) {
    param_[n] = kept.param;
    position_[n] = kept.position;
    normal_[n] = kept.normal;
    unit_normal_[n] = kept.unit_normal;
  }

  // Node n put on the surface at mesh coordinates `param`; false (node unchanged)
  // where the surface cannot take it.
  bool place(int n, const Vec3& param) {
    Vec3 position, normal;
    if (!place_(n, param, position, normal) || norm(normal) == 0) return false;
    param_[n] = param;
    position_[n] = position;
    normal_[n] = normal;
    unit_normal_[n] = unit(normal);
    return true;
  }

 private:
  std::vector<Vec3>& param_;
  std::vector<Vec3>& position_;
  std::vector<Vec3>& normal_;
  const PlaceNode& place_;
  std::vector<Vec3> unit_normal_;  // normal_ of unit length, zero where singular
};

// The nodes of a planar mesh in its plane's frame (x, y, 0): each node's mesh
// coordinates are its position, and the normal is +z everywhere. The same values as
// SurfaceNodes given those (the same smoothed mesh, bit for bit: a test), corners by
// planar_quad_corners, in one array instead of four: on large meshes the copies cost
// much memory and a sizeable share of the smoothing's time, most of it the kernel
// handing out their pages.
class PlanarNodes {
 public:
  explicit PlanarNodes(std::vector<Vec3>& nodes) : nodes_(nodes) {}

  std::size_t size() const { return nodes_.size(); }
  const Vec3& param(int n) const { return nodes_[n]; }
  const Vec3& position(int n) const { return nodes_[n]; }
  const Vec3& unit_normal(int) const { return kUp; }
  bool singular(int) const { return false; }

  using State = Vec3;
  State state(int n) const { return nodes_[n]; }
  void restore(int n, const State& kept) { nodes_[n] = kept; }
  bool place(int n, const Vec3& param) {
    nodes_[n] = param;
    return true;
  }

  static constexpr Vec3 kUp{0, 0, 1};

  // Whether all nodes share one z, as their corners (planar_quad_corners) assume.
  static bool in_one_plane(const std::vector<Vec3>& nodes) {
    return std::all_of(nodes.begin(), nodes.end(), [&](const Vec3& p) { return p.z == nodes.front().z; });
  }

 private:
  std::vector<Vec3>& nodes_;
};

// Quad q's corners (quality.h) at its nodes' current places and normals.
template <typename Nodes>
QuadCorners corners_of(const Quad& q, const Nodes& nodes) {
  return quad_corners({nodes.position(q[0]), nodes.position(q[1]), nodes.position(q[2]), nodes.position(q[3])},
                      {nodes.unit_normal(q[0]), nodes.unit_normal(q[1]), nodes.unit_normal(q[2]),
                       nodes.unit_normal(q[3])});
}
QuadCorners corners_of(const Quad& q, const PlanarNodes& nodes) {
  return planar_quad_corners({nodes.position(q[0]), nodes.position(q[1]), nodes.position(q[2]), nodes.position(q[3])});
}

// Positions and normals (any length) read where they are, each unit normal computed
// as a corner needs it: what the fold count before and after the untangling reads,
// without the copy of every normal that SurfaceNodes makes for the smoother.
struct NormalsInPlace {
  const std::vector<Vec3>& positions;
  const std::vector<Vec3>& normals;
  const Vec3& position(int n) const { return positions[n]; }
  Vec3 unit_normal(int n) const { return unit(normals[n]); }
};

// The corners of a quad inverted where the user sees them: a scaled Jacobian against
// the surface normals (each quad's own where the normal is singular) below
// -kInvertedBelow.
int inverted_corners(const QuadCorners& c) {
  int inverted = 0;
  for (double j : c.jacobian) inverted += j < -kInvertedBelow ? 1 : 0;
  return inverted;
}

// One pass over every quad's corners: the nodes, not among the `fixed` first, that
// decide a corner under `threshold` as the smoother judges corners (a corner's angle
// is decided by its own node and its two neighbours in the quad), and the corners
// inverted (inverted_corners).
struct CornerScan {
  std::vector<bool> deciding;  // bits: a byte a node added to the peak memory of large meshes
  long long inverted = 0;
};
template <typename Nodes>
CornerScan scan_corners(const std::vector<Quad>& quads, int fixed, const Nodes& nodes, double threshold) {
  CornerScan scan{std::vector<bool>(nodes.size(), false), 0};
  for (const Quad& q : quads) {
    poll_cancellation(4);
    const QuadCorners c = corners_of(q, nodes);
    scan.inverted += inverted_corners(c);
    // A collapsed quad's angles can all be sound (is_collapsed): its nodes move too.
    for (int j = 0; j < 4; ++j) {
      if (!c.collapsed && !(judged_corner(c, j) < threshold)) continue;
      for (int k : decided_by(j)) scan.deciding[q[k]] = true;  // the nodes deciding corner j
    }
  }
  std::fill(scan.deciding.begin(), scan.deciding.begin() + std::min<std::size_t>(fixed, nodes.size()), false);
  return scan;
}

// Moves the interior nodes of `quads` held by Nodes (SurfaceNodes or PlanarNodes).
template <typename Nodes>
class Smoother {
 public:
  Smoother(const std::vector<Quad>& quads, int fixed, Nodes& nodes)
      : quads_(quads), fixed_(fixed), nodes_(nodes), quads_of_(slotted_quads_around_nodes(nodes.size(), quads)) {}

  SmoothingResult run(const SmoothingOptions& options) {
    return run(options, scan_corners(quads_, fixed_, nodes_, options.good_enough).deciding);
  }

  // Only the nodes marked in `movable` move from now on.
  void restrict_to(std::vector<bool> movable) { movable_ = std::move(movable); }

  // `active`: the nodes deciding a corner under good_enough (scan_corners), moved
  // first; then only nodes with a neighbour that moved (or that moved themselves):
  // most of a mesh (its mapped grids) is left as the templates placed it.
  SmoothingResult run(const SmoothingOptions& options, std::vector<bool> active) {
    SmoothingResult result;
    const int count = static_cast<int>(nodes_.size());
    std::vector<bool> next(count, false);
    for (int pass = 0; pass < options.passes; ++pass) {
      long long moves = 0;
      for (int n = fixed_; n < count; ++n) {
        poll_cancellation(1);
        if (!active[n] || nodes_.singular(n)) continue;  // a node on a pole stays there
        if (!movable_.empty() && !movable_[n]) continue;
        poll_cancellation(32);  // a visit: the Laplacian, perhaps an ascent
        // First the mean of the neighbours; then, where a corner stays poor, the
        // steepest ascent of the worst corner from wherever the Laplacian left the
        // node. With the ascent only where the Laplacian failed, the Laplacian's
        // small gains kept a sliver corner from it for all eight passes, leaving the
        // corner far lower than the ascent takes it.
        LocalQuality here = local_quality(n);
        bool moved = move_to_neighbours_mean(n, here);
        // Where the worst is fair but some corner is under good_enough, the sum's
        // steepest ascent instead, the worst held: it raises the means a little (with
        // every node, not only those under good_enough, a little more, at twice the
        // smoothing time, and several times the meshing's on a cone).
        if (here.worst < options.search_below) {
          moved = ascend_worst_corner(n, here) || moved;
        } else if (here.worst < options.good_enough) {
          moved = ascend_corner_sum(n, here) || moved;
        }
        // Where a corner is still inverted, also the compass search: across a fold
        // the finite differences mislead the ascent. On the mildly non-convex
        // generated boundaries it leaves fewer inverted quads than the ascent alone.
        // So too around a collapsed quad (is_collapsed, next to a tiny CAD edge): its
        // corners may be fine, and nothing but the corner areas say which way to go.
        if (here.worst < 0 || here.collapsed > 0) moved = compass_search(n, here) || moved;
        if (!moved) continue;
        ++moves;
        next[n] = true;
        for_each_neighbour(n, [&](NodeId other) {
          active[other] = true;  // later in this pass
          next[other] = true;
        });
      }
      result.moves += moves;
      ++result.passes;
      if (moves == 0) break;
      active.swap(next);
      std::fill(next.begin(), next.end(), false);
    }
    return result;
  }

 private:

  // Calls visit(corners, i) for each quad around node n, i being n's place in it,
  // always in the same order.
  template <typename Visit>
  void for_each_quad_around(int n, const Visit& visit) const {
    quads_of_.for_each(n, [&](int k) {
      const Quad& q = quads_[k];
      visit(corners_of(q, nodes_), corner_of(q, n));
    });
  }

  LocalQuality local_quality(int n) const {
    LocalQuality local;
    for_each_quad_around(n, [&](const QuadCorners& c, int i) {
      for (int j : decided_by(i)) {
        local.worst = std::min(local.worst, judged_corner(c, j));
        local.sum += kCornerWeight * judged_corner(c, j);
      }
      local.sum += quad_value(c);
      local.collapsed += c.collapsed ? 1 : 0;
      local.edge_ratio = std::min(local.edge_ratio, c.edge_ratio);
    });
    return local;
  }

  // The corners node n decides (judged_corner), always in the same order, three a
  // quad, into `values`; and, when given, into `opposite` the corner of each quad
  // that node n does not decide (the one opposite it), constant while n moves.
  void corner_values(int n, std::vector<double>& values, std::vector<double>* opposite = nullptr) const {
    values.clear();
    if (opposite) opposite->clear();
    for_each_quad_around(n, [&](const QuadCorners& c, int i) {
      for (int j : decided_by(i)) values.push_back(judged_corner(c, j));
      if (opposite) opposite->push_back(judged_corner(c, (i + 2) % 4));
    });
  }

  // Node n placed at `param` for a measurement, then put back. False where the
  // surface cannot take it.
  bool corner_values_at(int n, const Vec3& param, std::vector<double>& values) {
    const typename Nodes::State kept = nodes_.state(n);
    if (!nodes_.place(n, param)) return false;
    corner_values(n, values);
    nodes_.restore(n, kept);
    return true;
  }

  // Node n's own directions in the mesh coordinates: towards its first neighbour and
  // a quarter turn from it. Searching along these rather than the coordinate axes
  // makes the smoothing of a region the same however its plane is turned (up to
  // rounding).
  struct LocalFrame {
    Vec3 first, second;
  };
  LocalFrame local_frame(int n) const {
    const int first = quads_of_.first(n);
    if (first < 0) return {{1, 0, 0}, {0, 1, 0}};
    const Quad& q = quads_[first];
    Vec3 d = nodes_.param(q[(corner_of(q, n) + 1) % 4]) - nodes_.param(n);
    d.z = 0;
    d = unit(d);
    if (norm(d) == 0) d = {1, 0, 0};
    return {d, {-d.y, d.x, 0.0}};
  }

  // The corners node n decides (values_) and their gradients along the frame's two
  // directions (gradient_first_, gradient_second_), by finite differences over h.
  // False where the surface cannot take the displaced node.
  bool corner_gradients(int n, double h, const LocalFrame& frame) {
    const Vec3 start = nodes_.param(n);
    corner_values(n, values_, &opposite_);
    if (!corner_values_at(n, start + h * frame.first, gradient_first_) ||
        !corner_values_at(n, start + h * frame.second, gradient_second_) ||
        gradient_first_.size() != values_.size() || gradient_second_.size() != values_.size()) {
      return false;
    }
    for (std::size_t i = 0; i < values_.size(); ++i) {
      gradient_first_[i] = (gradient_first_[i] - values_[i]) / h;
      gradient_second_[i] = (gradient_second_[i] - values_[i]) / h;
    }
    return true;
  }

  // Tries node n from `start` along `direction` (mesh coordinates, unit), from `step`
  // halving down to `smallest`; true once try_move keeps one.
  bool line_search(int n, const Vec3& start, const Vec3& direction, double step, double smallest,
                   LocalQuality& best) {
    for (; step > smallest; step *= 0.5) {
      if (try_move(n, start + step * direction, best)) return true;
    }
    return false;
  }

  // A steepest ascent at node n: up to `iterations` steps, each from the corners'
  // values and gradients (corner_gradients) to the direction and first step length
  // that choose(shortest edge around n) gives (nothing: stop), then halved until
  // try_move keeps the move.
  struct AscentStep {
    double first = 0, second = 0;  // unit direction in the node's frame
    double length = 0;              // first step, in mesh coordinates
    // No step shorter than this is tried (besides kSmallestStep of the shortest edge).
    double shortest_step = 0;
  };
  template <typename Choose>
  bool ascend(int n, LocalQuality& best, int iterations, const Choose& choose) {
    const double shortest = shortest_edge_around(n);
    if (!(shortest > 0) || !std::isfinite(shortest)) return false;
    const LocalFrame frame = local_frame(n);
    bool moved = false;
    for (int iteration = 0; iteration < iterations; ++iteration) {
      if (!corner_gradients(n, shortest * kGradientStep, frame)) break;
      const std::optional<AscentStep> step = choose(shortest);
      if (!step) break;
      const Vec3 direction = step->first * frame.first + step->second * frame.second;
      const double smallest = std::max(shortest * kSmallestStep, step->shortest_step);
      if (!line_search(n, nodes_.param(n), direction, step->length, smallest, best)) break;
      moved = true;
    }
    return moved;
  }

  // Raises the worst corner around node n by steepest ascent of the minimum
  // (max_min_ascent.h): the step predicted to where a corner not yet at the minimum
  // would join it. Three to six surface evaluations per step where the compass
  // search (below) spends 32 or more.
  bool ascend_worst_corner(int n, LocalQuality& best) {
    return ascend(n, best, kAscentIterations, [&](double shortest) -> std::optional<AscentStep> {
      const double worst = *std::min_element(values_.begin(), values_.end());
      gradients_.clear();
      for (std::size_t i = 0; i < values_.size(); ++i) {
        if (values_[i] <= worst + kActiveBand) gradients_.push_back({gradient_first_[i], gradient_second_[i], 0.0});
      }
      const Ascent ascent = max_min_ascent(gradients_);  // in the frame's directions
      if (!(ascent.rate > 0)) return std::nullopt;
      // Where a corner above the band, falling faster, would meet the minimum.
      double length = kLargestStep * shortest;
      for (std::size_t i = 0; i < values_.size(); ++i) {
        if (values_[i] <= worst + kActiveBand) continue;
        const double rate = gradient_first_[i] * ascent.direction.x + gradient_second_[i] * ascent.direction.y;
        if (rate < ascent.rate) length = std::min(length, (values_[i] - worst) / (ascent.rate - rate));
      }
      return AscentStep{ascent.direction.x, ascent.direction.y, length};
    });
  }

  // Raises the quads' sum around node n (quad_value) by steepest ascent, at most
  // kSumAscentIterations steps, each kept only as try_move allows (the worst corner
  // held), along the sum's gradient projected so that no corner at the worst falls.
  bool ascend_corner_sum(int n, LocalQuality& best) {
    return ascend(n, best, kSumAscentIterations, [&](double shortest) -> std::optional<AscentStep> {
      // The gradient of the quads' values (quad_value): each quad's lowest corner's,
      // none where that is the corner n does not decide (opposite_, corner_gradients).
      double along_first = 0, along_second = 0;
      for (std::size_t i = 0; i < values_.size(); ++i) {
        along_first += kCornerWeight * gradient_first_[i];
        along_second += kCornerWeight * gradient_second_[i];
      }
      for (std::size_t k = 0; k < opposite_.size(); ++k) {
        std::size_t lowest = 3 * k;
        for (std::size_t i = 3 * k + 1; i < 3 * k + 3; ++i) {
          if (values_[i] < values_[lowest]) lowest = i;
        }
        if (opposite_[k] < values_[lowest]) continue;
        along_first += gradient_first_[lowest];
        along_second += gradient_second_[lowest];
      }
      // The worst corner must hold: the sum's gradient without its part that would
      // lower a corner at the worst (to first order).
      const double worst = *std::min_element(values_.begin(), values_.end());
      for (std::size_t i = 0; i < values_.size(); ++i) {
        if (values_[i] > worst + kActiveBand) continue;
        const double g1 = gradient_first_[i], g2 = gradient_second_[i], gg = g1 * g1 + g2 * g2;
        const double along = along_first * g1 + along_second * g2;
        if (along >= 0 || !(gg > 0)) continue;
        along_first -= along / gg * g1;
        along_second -= along / gg * g2;
      }
      for (std::size_t i = 0; i < values_.size(); ++i) {
        if (values_[i] > worst + kActiveBand) continue;
        if (along_first * gradient_first_[i] + along_second * gradient_second_[i] < -1e-12) return std::nullopt;
      }
      const double rate = std::hypot(along_first, along_second);  // the sum's gain per unit step
      if (!(rate > 0)) return std::nullopt;
      // Steps whose predicted gain is under kSumGain would not be kept (to first
      // order), so none is tried. With the sum's plain gradient nearly all of these
      // ascents failed (it lowered a corner at the worst), spending most of the
      // smoothing's node placements; projected and cut short so, they spend far fewer
      // and keep more moves, and the means of CAD parts rise a little.
      const double first_step = kLargestStep * shortest;
      if (first_step * rate < kSumGain) return std::nullopt;
      return AscentStep{along_first / rate, along_second / rate, first_step, kSumGain / rate};
    });
  }

  // Tries node n at `param`; keeps it if the corners around improve on `before`
  // (which is then updated), else restores the node.
  bool try_move(int n, const Vec3& param, LocalQuality& before) {
    const typename Nodes::State kept = nodes_.state(n);
    if (!nodes_.place(n, param)) return false;
    const LocalQuality after = local_quality(n);
    if (after.improves_on(before)) {
      before = after;
      return true;
    }
    nodes_.restore(n, kept);
    return false;
  }

  bool move_to_neighbours_mean(int n, LocalQuality& before) {
    Vec3 mean;
    int count = 0;
    for_each_neighbour(n, [&](NodeId other) {
      mean += nodes_.param(other);
      ++count;
    });
    if (count == 0) return false;
    mean = (1.0 / count) * mean;
    const Vec3 start = nodes_.param(n);
    for (double t : {1.0, 0.5, 0.25}) {
      if (try_move(n, start + t * (mean - start), before)) return true;
    }
    return false;
  }

  // Eight directions, steps halving from a quarter of the shortest edge around the
  // node down to 1/64 of it, at most kStepsPerSize moves per step size; around a
  // collapsed quad, whose shortest edge is the one that collapsed (a millionth of the
  // others), from a quarter of the longest down to 1/4096 of it.
  bool compass_search(int n, LocalQuality& best) {
    double shortest = INFINITY, longest = 0;
    for_each_neighbour(n, [&](NodeId other) {
      const double d = distance(nodes_.param(n), nodes_.param(other));
      shortest = std::min(shortest, d);
      longest = std::max(longest, d);
    });
    if (!(shortest > 0) || !std::isfinite(shortest)) return false;
    const double from = best.collapsed > 0 ? 0.25 * longest : 0.25 * shortest;
    const double down_to = best.collapsed > 0 ? std::max(shortest / 64, longest / 4096) : shortest / 64;
    bool moved = false;
    for (double step = from; step > down_to; step *= 0.5) {
      for (int moves = 0, improved = 1; improved && moves < kStepsPerSize; ++moves) {
        improved = 0;
        const Vec3 start = nodes_.param(n);
        for (int d = 0; d < 8 && !improved; ++d) improved = try_move(n, start + step * kCompass[d], best);
        moved = moved || improved != 0;
      }
    }
    return moved;
  }

  // In the mesh coordinates.
  double shortest_edge_around(int n) const {
    double shortest = INFINITY;
    for_each_neighbour(n, [&](NodeId other) {
      shortest = std::min(shortest, distance(nodes_.param(n), nodes_.param(other)));
    });
    return shortest;
  }

  // Node n's place in quad q (which holds it).
  static int corner_of(const Quad& q, NodeId n) {
    return static_cast<int>(std::find(q.begin(), q.end(), n) - q.begin());
  }

  // Calls visit(neighbour) for each edge neighbour of node n, in the same order every
  // time: the corner after n in each quad around it, so an interior node's
  // neighbours once each. (A list of them would cost 20 bytes a node more, much memory
  // on large meshes.)
  template <typename Visit>
  void for_each_neighbour(int n, const Visit& visit) const {
    quads_of_.for_each(n, [&](int k) {
      const Quad& q = quads_[k];
      visit(q[(corner_of(q, n) + 1) % 4]);
    });
  }

  const std::vector<Quad>& quads_;
  int fixed_;
  Nodes& nodes_;
  SlottedLists quads_of_;  // the quads around each node
  std::vector<bool> movable_;  // empty: every node from fixed_ on
  // The ascents' buffers, kept to spare an allocation per node.
  std::vector<double> values_, gradient_first_, gradient_second_, opposite_;
  std::vector<Vec3> gradients_;
};

}  // namespace

namespace {

// +1 when the quads run counter-clockwise in their mesh coordinates (most of their
// area), -1 when clockwise, 0 when that cannot be told.
double orientation_in_coordinates(const std::vector<Quad>& quads, const std::vector<Vec3>& param) {
  double area = 0;
  for (const Quad& q : quads) {
    poll_cancellation(4);
    const Vec3 d1 = param[q[2]] - param[q[0]], d2 = param[q[3]] - param[q[1]];
    area += d1.x * d2.y - d1.y * d2.x;
  }
  return area > 0 ? 1.0 : area < 0 ? -1.0 : 0.0;
}

}  // namespace

namespace {

// Inverted corners (inverted_corners), and collapsed quads (is_collapsed).
struct SurfaceFolds {
  int inverted = 0, collapsed = 0;
};
SurfaceFolds folds_on_surface(const std::vector<Quad>& quads, const std::vector<Vec3>& position,
                              const std::vector<Vec3>& normal) {
  SurfaceFolds folds;
  const NormalsInPlace nodes{position, normal};
  for (const Quad& q : quads) {
    poll_cancellation(4);
    const QuadCorners c = corners_of(q, nodes);
    folds.inverted += inverted_corners(c);
    folds.collapsed += c.collapsed ? 1 : 0;
  }
  return folds;
}

// Unfolds what the surface shows inverted (area_untangling.h), in the mesh coordinates;
// kept only if fewer corners are inverted on the surface after it and no more quads
// are collapsed (a corner folded in
// (u, v) alone, at a cusp, is no reason to move nodes). Returns the moves kept.
long long unfold_inverted_corners(const std::vector<Quad>& quads, int fixed, std::vector<Vec3>& param,
                                  std::vector<Vec3>& position, std::vector<Vec3>& normal, const PlaceNode& place) {
  const SurfaceFolds before = folds_on_surface(quads, position, normal);
  const double orientation = orientation_in_coordinates(quads, param);
  if (before.inverted == 0 || orientation == 0) return 0;
  const std::vector<Vec3> kept_param = param, kept_position = position, kept_normal = normal;
  const auto place_node = [&](int n, const Vec3& p) {
    Vec3 moved_position, moved_normal;
    if (norm(normal[n]) == 0 || !place(n, p, moved_position, moved_normal) || norm(moved_normal) == 0) return false;
    position[n] = moved_position;
    normal[n] = moved_normal;
    return true;
  };
  const AreaUntanglingResult result = untangle_corner_areas(quads, fixed, param, orientation, place_node);
  if (result.moves > 0) {
    const SurfaceFolds after = folds_on_surface(quads, position, normal);
    if (after.inverted < before.inverted && after.collapsed <= before.collapsed) return result.moves;
  }
  param = kept_param;
  position = kept_position;
  normal = kept_normal;
  return 0;
}

}  // namespace

SmoothingResult smooth_mesh(const std::vector<Quad>& quads, int fixed, std::vector<Vec3>& param,
                            std::vector<Vec3>& position, std::vector<Vec3>& normal, const PlaceNode& place,
                            const SmoothingOptions& options) {
  if (fixed >= static_cast<int>(param.size())) return {};
  // Folded corners first: the smoother below cannot unfold them.
  const long long untangling_moves = unfold_inverted_corners(quads, fixed, param, position, normal, place);
  SurfaceNodes nodes(param, position, normal, place);
  SmoothingResult result = Smoother<SurfaceNodes>(quads, fixed, nodes).run(options);
  result.untangling_moves = untangling_moves;
  return result;
}

SmoothingResult smooth_mesh_near(const std::vector<Quad>& quads, int fixed, std::vector<Vec3>& param,
                                 std::vector<Vec3>& position, std::vector<Vec3>& normal, const PlaceNode& place,
                                 std::vector<bool> region, const SmoothingOptions& options) {
  if (fixed >= static_cast<int>(param.size())) return {};
  region.resize(param.size(), false);
  std::fill(region.begin(), region.begin() + fixed, false);
  // Folds unfolded among the quads touching the region alone, by its nodes alone.
  std::vector<Quad> touching;
  for (const Quad& q : quads) {
    poll_cancellation(4);
    if (std::any_of(q.begin(), q.end(), [&](NodeId n) { return region[n]; })) touching.push_back(q);
  }
  const PlaceNode in_region = [&](int n, const Vec3& p, Vec3& at, Vec3& out_normal) {
    return region[n] && place(n, p, at, out_normal);
  };
  const long long untangling_moves = unfold_inverted_corners(touching, fixed, param, position, normal, in_region);
  SurfaceNodes nodes(param, position, normal, place);
  Smoother<SurfaceNodes> smoother(quads, fixed, nodes);
  smoother.restrict_to(region);
  SmoothingResult result = smoother.run(options, std::move(region));
  result.untangling_moves = untangling_moves;
  return result;
}

namespace {

// Nodes in a plane's frame (x, y, 0): their own mesh coordinates, normal +z,
// cleaned (doublets.h) and smoothed; `quads` are renumbered as doublets go.
SmoothingResult smooth_in_frame(std::vector<Quad>& quads, int fixed, std::vector<Vec3>& nodes, int& merged,
                                const SmoothingOptions& options) {
  // Most meshes have neither doublets nor folds: smoothed in the one node array.
  // Otherwise the general route below (with copies) merges or unfolds them first.
  merged = 0;
  if (fixed >= static_cast<int>(nodes.size())) return {};
  PlanarNodes planar(nodes);
  if (PlanarNodes::in_one_plane(nodes) && !has_doublet(quads, fixed, nodes.size())) {
    CornerScan scan = scan_corners(quads, fixed, planar, options.good_enough);
    if (scan.inverted == 0) return Smoother<PlanarNodes>(quads, fixed, planar).run(options, std::move(scan.deciding));
  }
  const Vec3 up = PlanarNodes::kUp;
  std::vector<Vec3> param = nodes, normal(nodes.size(), up);
  merged = remove_doublets(quads, fixed, param, nodes, normal);
  const PlaceNode in_plane = [&](int, const Vec3& p, Vec3& position, Vec3& n) {
    position = p;
    n = up;
    return true;
  };
  return smooth_mesh(quads, fixed, param, nodes, normal, in_plane, options);
}

}  // namespace

SmoothingResult smooth_planar_mesh(QuadMesh& mesh, int fixed, int& merged, const SmoothingOptions& options) {
  return smooth_in_frame(mesh.quads, fixed, mesh.nodes, merged, options);
}

SmoothingResult smooth_mesh_in_plane(QuadMesh& mesh, int fixed, const Vec3& normal, int& merged,
                                     const SmoothingOptions& options) {
  merged = 0;
  if (fixed <= 0 || fixed >= static_cast<int>(mesh.nodes.size())) return {};
  // A right-handed frame (e1, e2, normal) at the first boundary node; the nodes are
  // taken into it in place (a copy costs much memory and time on large meshes, most
  // of it the kernel handing out its pages) and the boundary's saved apart.
  const MeanPlane plane = MeanPlane::with_normal(mesh.nodes[0], normal);
  const std::vector<Vec3> boundary(mesh.nodes.begin(), mesh.nodes.begin() + fixed);
  for (Vec3& p : mesh.nodes) {
    const Vec3 in_plane = plane.local(p);
    p = {in_plane.x, in_plane.y, 0};
  }
  const SmoothingResult result = smooth_in_frame(mesh.quads, fixed, mesh.nodes, merged, options);
  // The boundary nodes keep their coordinates bit for bit; the others come back.
  std::copy(boundary.begin(), boundary.end(), mesh.nodes.begin());
  for (std::size_t i = fixed; i < mesh.nodes.size(); ++i) {
    mesh.nodes[i] = plane.point_at(mesh.nodes[i].x, mesh.nodes[i].y, 0);
  }
  return result;
}

namespace {

// A curved loop's mesh in its mean plane's coordinates, doublets merged (once, for
// both surfaces below): param (x, y, 0), position (the nodes where they are) and
// quads as smooth_mesh takes them.
struct CurvedLoopMesh {
  std::vector<Vec3> param, position;
  std::vector<Quad> quads;
};

CurvedLoopMesh in_mean_plane(const QuadMesh& mesh, int fixed, const MeanPlane& plane) {
  CurvedLoopMesh out{{}, mesh.nodes, mesh.quads};
  for (const Vec3& p : mesh.nodes) {
    const Vec3 local = plane.local(p);
    out.param.push_back({local.x, local.y, 0});
  }
  std::vector<Vec3> unused_normals(mesh.nodes.size());  // doublets judged in their quads' own planes
  remove_doublets(out.quads, fixed, out.param, out.position, unused_normals);
  return out;
}

// That mesh smoothed with its interior nodes placed by `place`, moved onto the
// surface first when `relift` (else they start where they are: on the surface it
// stands for); the boundary's corners are signed by their quads' own normals (normal
// zero). nullopt where a node cannot be placed.
std::optional<QuadMesh> smoothed_on(const QuadMesh& mesh, int fixed, CurvedLoopMesh start, const PlaceNode& place,
                                    bool relift) {
  std::vector<Vec3> normal(start.param.size());
  for (std::size_t i = fixed; i < start.param.size(); ++i) {
    Vec3 at;
    if (!place(static_cast<int>(i), start.param[i], at, normal[i])) return std::nullopt;
    if (relift) start.position[i] = at;
  }
  smooth_mesh(start.quads, fixed, start.param, start.position, normal, place);
  QuadMesh smoothed = mesh;
  smoothed.nodes = std::move(start.position);
  smoothed.quads = std::move(start.quads);
  return smoothed;
}

// A curved loop's mesh smoothed: on the templates' own surface, fitted around each
// node (fitted_surface.h); where that leaves an inverted quad (the templates' surface
// folds there: a few of the curved generated boundaries kept one, some with a corner
// far below zero), also on the mean value membrane through the loop
// (mean_value_surface.h). The mesh with the highest worst corner in its quads' own
// planes is kept, the unsmoothed one included: smooth_mesh keeps the worst corner as
// it judges corners (against the surface normals and in each quad's plane), which is
// not quite that. Left as meshed where the loop's projection on its mean plane
// crosses itself.
void smooth_curved_region(QuadMesh& mesh, int fixed) {
  const std::vector<Vec3> loop(mesh.nodes.begin(), mesh.nodes.begin() + fixed);
  const std::optional<MeanPlane> plane = MeanPlane::of_loop(loop);
  if (!plane) return;
  const CurvedLoopMesh start = in_mean_plane(mesh, fixed, *plane);
  FittedSurface fitted(*plane, fixed);
  fitted.fit_nodes(start.position, start.quads);

  const QuadMesh meshed = mesh;
  QualitySummary best = summarize_quality(mesh, std::nullopt);
  const auto keep_if_better = [&](std::optional<QuadMesh> smoothed) {
    if (!smoothed) return;
    const QualitySummary q = summarize_quality(*smoothed, std::nullopt);
    if (q.scaled_jacobian.min >= best.scaled_jacobian.min) best = q, mesh = std::move(*smoothed);
  };
  keep_if_better(smoothed_on(meshed, fixed, start,
                             [&](int n, const Vec3& p, Vec3& at, Vec3& normal) { return fitted.place(n, p, at, normal); },
                             false));
  if (best.inverted == 0) return;
  const MeanValueSurface membrane(*plane, loop);
  keep_if_better(smoothed_on(meshed, fixed, start,
                             [&](int, const Vec3& p, Vec3& at, Vec3& normal) { return membrane.place(p, at, normal); },
                             true));
}

}  // namespace

void smooth_region(QuadMesh& mesh, int boundary_points, const std::optional<Vec3>& plane_normal) {
  if (plane_normal) {
    split_reflex_corner_quads(mesh, boundary_points, *plane_normal);
    int merged = 0;
    smooth_mesh_in_plane(mesh, boundary_points, *plane_normal, merged);
  } else {
    smooth_curved_region(mesh, boundary_points);
  }
  const std::string problem = check_disk_mesh(mesh, boundary_points);
  if (!problem.empty()) throw std::logic_error("the smoothed mesh is invalid: " + problem);
}

}  // namespace tquad
