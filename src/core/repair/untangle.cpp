#include "core/repair/untangle.h"
#include "core/cancellation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "core/mesh/node_adjacency.h"

namespace tquad {

namespace {

constexpr double kBadCorner = 1e-6;  // scaled Jacobian at or below: degenerate or inverted

// The compass search's eight directions, (cos, sin) of d * pi / 4, computed once
// rather than for every try, where they cost a noticeable share of a whole run.
struct CompassDirections {
  std::array<double, 8> cos, sin;
  CompassDirections() {
    for (int d = 0; d < 8; ++d) {
      const double angle = d * M_PI / 4;
      cos[d] = std::cos(angle);
      sin[d] = std::sin(angle);
    }
  }
};
const CompassDirections kCompassDirections;

class Untangler {
 public:
  Untangler(QuadMesh& mesh, int boundary_points, const std::optional<Vec3>& plane_normal)
      : mesh_(mesh),
        boundary_points_(boundary_points),
        adjacency_(mesh.nodes.size(), mesh.quads),
        neighbours_(adjacency_.neighbours),
        quads_of_(adjacency_.quads_of) {
    normals_.resize(mesh.nodes.size());
    for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
      poll_cancellation(4);
      normals_[n] = plane_normal ? *plane_normal : estimated_normal(static_cast<NodeId>(n));
    }
  }

  bool is_bad(int quad_index) const {
    const Quad& q = mesh_.quads[quad_index];
    for (int i = 0; i < 4; ++i) {
      const NodeId prev = q[(i + 3) % 4], here = q[i], next = q[(i + 1) % 4];
      // A corner whose node and both neighbours are on the boundary cannot be moved.
      if (here < boundary_points_ && prev < boundary_points_ && next < boundary_points_) continue;
      const Vec3 a = mesh_.nodes[next] - mesh_.nodes[here], b = mesh_.nodes[prev] - mesh_.nodes[here];
      const double lengths = norm(a) * norm(b);
      if (lengths == 0 || dot(cross(a, b), normals_[here]) / lengths <= kBadCorner) return true;
    }
    return false;
  }

  std::vector<int> bad_quads() const {
    std::vector<int> bad;
    for (std::size_t k = 0; k < mesh_.quads.size(); ++k) {
      poll_cancellation(4);
      if (is_bad(static_cast<int>(k))) bad.push_back(static_cast<int>(k));
    }
    return bad;
  }

  UntangleResult run() {
    UntangleResult result;
    std::vector<int> bad = bad_quads();
    result.bad_before = static_cast<long long>(bad.size());
    if (bad.empty()) return result;

    const std::vector<Vec3> placed = mesh_.nodes;
    std::vector<NodeId> zone = smooth_laplacian(bad);
    std::size_t remaining = bad_quads().size();
    if (remaining > 0) {
      // Laplacian smoothing only guarantees validity on convex regions; on others it
      // can drag nodes across a concave side. Start again from the template's
      // positions with the local max-min repair and keep the better outcome.
      std::vector<Vec3> smoothed = mesh_.nodes;
      mesh_.nodes = placed;
      std::vector<NodeId> optimized = maximize_worst_corners(bad_quads(), remaining);
      const std::size_t after = bad_quads().size();
      if (after <= remaining) {
        remaining = after;
        zone = optimized;
      } else {
        mesh_.nodes.swap(smoothed);
      }
    }
    result.bad_after = static_cast<long long>(remaining);
    result.moved_nodes = static_cast<long long>(zone.size());
    return result;
  }

 private:
  // The nodes of the bad quads plus `rings` layers of neighbours, interior only.
  struct Zone {
    std::vector<char> member;
    std::vector<NodeId> nodes;
  };
  Zone zone_around(const std::vector<int>& bad) const {
    Zone z{std::vector<char>(mesh_.nodes.size(), 0), {}};
    for (int k : bad) for (NodeId n : mesh_.quads[k]) add_to(z, n);
    return z;
  }
  void add_to(Zone& z, NodeId n) const {
    if (n >= boundary_points_ && !z.member[n]) { z.member[n] = 1; z.nodes.push_back(n); }
  }
  void grow_ring(Zone& z) const {
    const std::size_t count = z.nodes.size();
    for (std::size_t i = 0; i < count; ++i) {
      poll_cancellation();
      const NodeId n = z.nodes[i];
      for (int k = neighbours_.offsets[n]; k < neighbours_.offsets[n + 1]; ++k) add_to(z, neighbours_.items[k]);
    }
  }

  // Laplacian smoothing in a zone grown two rings per round until no bad quad is
  // left; once it covers the whole mesh, the sweeps per round double (Gauss-Seidel
  // converges slowly on long grids) until rounds bring no progress.
  std::vector<NodeId> smooth_laplacian(std::vector<int> bad) {
    Zone z = zone_around(bad);
    const long long interior = static_cast<long long>(mesh_.nodes.size()) - boundary_points_;
    int sweeps = 8, stalled = 0;
    std::size_t fewest = bad.size();
    for (int round = 0; round < 40 && !bad.empty() && stalled < 4; ++round) {
      grow_ring(z);
      grow_ring(z);
      const bool everything = static_cast<long long>(z.nodes.size()) >= interior;
      for (int s = 0; s < sweeps; ++s) laplacian_sweep(z.nodes);
      if (everything) sweeps = std::min(sweeps * 2, 1024);
      bad = bad_quads();
      for (int k : bad) for (NodeId n : mesh_.quads[k]) add_to(z, n);
      if (bad.size() < fewest) { fewest = bad.size(); stalled = 0; } else if (everything) { ++stalled; }
    }
    return z.nodes;
  }

  // Local max-min repair: each node of the zone (the bad quads and two rings around)
  // moves, in its tangent plane, to raise the worst scaled Jacobian of the corners
  // its position decides, by a compass search whose step starts at a quarter of its
  // shortest edge. Its outcome is kept only if it ends with at most `to_beat` bad
  // quads (the Laplacian's), so it stops once it cannot get there even at its best
  // rate so far: a hopeless candidate otherwise spent long on thousands of bad quads
  // without ever nearing the Laplacian's count.
  std::vector<NodeId> maximize_worst_corners(std::vector<int> bad, std::size_t to_beat) {
    constexpr int kPasses = 30;
    Zone z = zone_around(bad);
    grow_ring(z);
    grow_ring(z);
    std::size_t fewest = bad.size();
    long long best_gain = 0;  // most bad quads repaired by one pass so far
    Settling settling(mesh_.nodes.size());
    for (int pass = 0, stalled = 0; pass < kPasses && !bad.empty() && stalled < 3; ++pass) {
      for (NodeId n : z.nodes) {
        poll_cancellation(16);
        if (settling.settled(n, *this)) continue;
        const Vec3 before = mesh_.nodes[n];
        improve_node(n);
        settling.visited(n, !(mesh_.nodes[n] == before));
      }
      const long long before = static_cast<long long>(bad.size());
      bad = bad_quads();
      for (int k : bad) for (NodeId n : mesh_.quads[k]) add_to(z, n);
      if (bad.size() < fewest) { fewest = bad.size(); stalled = 0; } else { ++stalled; }
      best_gain = std::max(best_gain, before - static_cast<long long>(bad.size()));
      const long long passes_left = kPasses - pass - 1;
      if (static_cast<long long>(bad.size()) > static_cast<long long>(to_beat) + best_gain * passes_left) break;
    }
    return z.nodes;
  }

  // Which nodes a visit of improve_node would leave in place: those whose last visit
  // did, no node of their quads having moved since (the visit depends on nothing
  // else). Skipping them changes nothing. It pays where repairs stall, and many
  // nodes are visited again unchanged; where most nodes move in every pass the look
  // at their quads costs little.
  class Settling {
   public:
    explicit Settling(std::size_t nodes) : moved_at_(nodes, -1), settled_at_(nodes, -1) {}
    bool settled(NodeId n, const Untangler& u) const {
      const long long since = settled_at_[n];
      if (since < 0) return false;
      for (int k = u.quads_of_.offsets[n]; k < u.quads_of_.offsets[n + 1]; ++k) {
        for (NodeId m : u.mesh_.quads[u.quads_of_.items[k]]) {
          if (moved_at_[m] > since) return false;
        }
      }
      return true;
    }
    void visited(NodeId n, bool moved) {
      if (moved) moved_at_[n] = ++moves_;
      settled_at_[n] = moved ? -1 : moves_;
    }

   private:
    std::vector<long long> moved_at_;    // the move count when each node last moved
    std::vector<long long> settled_at_;  // the move count at its last visit that left it in place
    long long moves_ = 0;
  };

  // Scaled Jacobian at corner i of quad q, signed by the corner node's normal.
  double corner_quality(const Quad& q, int i) const {
    const NodeId here = q[i];
    const Vec3 a = mesh_.nodes[q[(i + 1) % 4]] - mesh_.nodes[here];
    const Vec3 b = mesh_.nodes[q[(i + 3) % 4]] - mesh_.nodes[here];
    const double lengths = norm(a) * norm(b);
    return lengths > 0 ? dot(cross(a, b), normals_[here]) / lengths : -1.0;
  }

  // Worst corner whose angle depends on node n: at n and at its two neighbours in
  // each quad around it; or, as soon as one is at or below `stop_at`, that one. A try
  // that cannot beat the best so far is rejected at its first such corner, which is
  // looked at first in the next try (`first`: its quad in n's list and corner). With
  // n's place in each quad found once, the untangling does well under half the work
  // for the same meshes.
  struct CornerNear {
    int quad = 0, corner = 0;
  };
  double worst_corner_near(NodeId n, double stop_at, CornerNear& first) const {
    const int begin = quads_of_.offsets[n], count = quads_of_.offsets[n + 1] - begin;
    // Quad k of n's list, and n's corners there: its own, the next and the previous.
    const auto quad_and_corners = [&](int k) {
      const Quad& q = mesh_.quads[quads_of_.items[begin + k]];
      const int i = static_cast<int>(std::find(q.begin(), q.end(), n) - q.begin());
      return std::pair<const Quad&, std::array<int, 3>>(q, {i, (i + 1) % 4, (i + 3) % 4});
    };
    double worst = 1.0;
    if (first.quad >= 0 && first.quad < count) {
      const auto [q, corners] = quad_and_corners(first.quad);
      worst = std::min(worst, corner_quality(q, corners[first.corner]));
      if (worst <= stop_at) return worst;
    }
    for (int k = 0; k < count; ++k) {
      const auto [q, corners] = quad_and_corners(k);
      for (int j = 0; j < 3; ++j) {
        if (k == first.quad && j == first.corner) continue;
        worst = std::min(worst, corner_quality(q, corners[j]));
        if (worst <= stop_at) {
          first = {k, j};
          return worst;
        }
      }
    }
    return worst;
  }
  double worst_corner_near(NodeId n) const {
    CornerNear none{-1, -1};
    return worst_corner_near(n, -INFINITY, none);
  }

  void improve_node(NodeId n) {
    double shortest = INFINITY;
    for (int k = neighbours_.offsets[n]; k < neighbours_.offsets[n + 1]; ++k) {
      shortest = std::min(shortest, distance(mesh_.nodes[n], mesh_.nodes[neighbours_.items[k]]));
    }
    const Vec3& normal = normals_[n];
    const Vec3 helper = std::abs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    Vec3 e1 = cross(normal, helper);
    e1 = (1.0 / norm(e1)) * e1;
    const Vec3 e2 = cross(normal, e1);
    double best = worst_corner_near(n);
    CornerNear first;
    for (double step = 0.25 * shortest; step > 1e-3 * shortest; step *= 0.5) {
      bool moved = true;
      for (int tries = 0; moved && tries < 4; ++tries) {
        moved = false;
        const Vec3 start = mesh_.nodes[n];
        Vec3 best_position = start;
        for (int d = 0; d < 8; ++d) {
          mesh_.nodes[n] = start + step * (kCompassDirections.cos[d] * e1 + kCompassDirections.sin[d] * e2);
          const double value = worst_corner_near(n, best + 1e-12, first);
          if (value > best + 1e-12) { best = value; best_position = mesh_.nodes[n]; moved = true; }
        }
        mesh_.nodes[n] = best_position;
      }
    }
  }

  Vec3 estimated_normal(NodeId n) const {
    Vec3 sum;
    for (int i = quads_of_.offsets[n]; i < quads_of_.offsets[n + 1]; ++i) {
      const Quad& q = mesh_.quads[quads_of_.items[i]];
      const Vec3 d = cross(mesh_.nodes[q[2]] - mesh_.nodes[q[0]], mesh_.nodes[q[3]] - mesh_.nodes[q[1]]);
      const double length = norm(d);
      if (length > 0) sum += (1.0 / length) * d;
    }
    const double length = norm(sum);
    return length > 0 ? (1.0 / length) * sum : Vec3{0, 0, 1};
  }

  // One Gauss-Seidel Laplacian sweep; the move is projected on the node's tangent plane.
  void laplacian_sweep(const std::vector<NodeId>& nodes) {
    for (NodeId n : nodes) {
      poll_cancellation(2);
      Vec3 mean;
      const int first = neighbours_.offsets[n], last = neighbours_.offsets[n + 1];
      for (int k = first; k < last; ++k) mean += mesh_.nodes[neighbours_.items[k]];
      mean = (1.0 / (last - first)) * mean;
      Vec3 move = mean - mesh_.nodes[n];
      move = move - dot(move, normals_[n]) * normals_[n];
      mesh_.nodes[n] += move;
    }
  }

  QuadMesh& mesh_;
  int boundary_points_;
  NodeAdjacency adjacency_;
  const CompressedLists& neighbours_;
  const CompressedLists& quads_of_;
  std::vector<Vec3> normals_;
};

// A cheap first look, without adjacency: any corner at or below kBadCorner, signed by
// the plane normal or, for a curved region, by the quad's own diagonal normal.
bool has_bad_corner(const QuadMesh& mesh, const std::optional<Vec3>& plane_normal) {
  for (const Quad& q : mesh.quads) {
    poll_cancellation(4);
    const Vec3 p[4] = {mesh.nodes[q[0]], mesh.nodes[q[1]], mesh.nodes[q[2]], mesh.nodes[q[3]]};
    const Vec3 normal = plane_normal ? *plane_normal : cross(p[2] - p[0], p[3] - p[1]);
    const Vec3 e[4] = {p[1] - p[0], p[2] - p[1], p[3] - p[2], p[0] - p[3]};
    for (int i = 0; i < 4; ++i) {
      // Corner i between e[i] (outgoing) and -e[i-1] (incoming, reversed).
      const Vec3& out = e[i];
      const Vec3& in = e[(i + 3) % 4];
      const double signed_area = -dot(cross(out, in), normal);
      const double scale = dot(out, out) * dot(in, in) * dot(normal, normal);
      if (signed_area <= 0 || signed_area * signed_area <= kBadCorner * kBadCorner * scale) return true;
    }
  }
  return false;
}

}  // namespace

UntangleResult untangle_mesh(QuadMesh& mesh, int boundary_points, const std::optional<Vec3>& plane_normal) {
  if (!has_bad_corner(mesh, plane_normal)) return {};
  return Untangler(mesh, boundary_points, plane_normal).run();
}

}  // namespace tquad
