#include "core/repair/flat_corner_turns.h"
#include "core/cancellation.h"

#include <algorithm>
#include <utility>

#include "core/mesh/quads_around_nodes.h"
#include "core/mesh/quality.h"

namespace tquad {

namespace {

// The scaled Jacobian of `quad` at its node n, each corner signed by its node's normal.
double corner_at(const Quad& quad, NodeId n, const std::vector<Vec3>& position, const std::vector<Vec3>& normal) {
  const int k = static_cast<int>(std::find(quad.begin(), quad.end(), n) - quad.begin());
  return quad_corners(quad, position, normal).jacobian[k];
}

// Which way a chain runs from the lone node a of its quad (a, b, c, d): toward d
// (turning the edge c-d) or toward b (turning the edge b-c).
enum class Toward { d, b };

class FlatCornerTurner {
 public:
  FlatCornerTurner(std::vector<Quad>& quads, int fixed, const std::vector<Vec3>& position,
                   const std::vector<Vec3>& normal)
      : quads_(quads), fixed_(fixed), position_(position), normal_(normal), around_(quads, position.size()) {}

  // The shorter of the chains from a flat lone node a in either direction; 0 turns
  // where neither ends well.
  int mend(NodeId a) {
    if (!flat_and_alone(a)) return 0;
    int best = 0;
    Toward best_way = Toward::d;
    for (Toward way : {Toward::d, Toward::b}) {
      const int turns = chain(a, way);
      undo(turns);
      if (turns > 0 && (best == 0 || turns < best)) {
        best = turns;
        best_way = way;
      }
    }
    if (best > 0) {
      chain(a, best_way);
      log_.clear();
    }
    return best;
  }

 private:
  bool flat_and_alone(NodeId a) const {
    return around_.of(a).size() == 1 && corner_at(quads_[around_.of(a)[0]], a, position_, normal_) < kFlatCornerBelow;
  }

  // The quad other than q with the directed edge from -> to, and where `from` is in it.
  std::pair<int, int> across(int q, NodeId from, NodeId to) const {
    for (int r : around_.of(from)) {
      if (r == q) continue;
      for (int i = 0; i < 4; ++i) {
        if (quads_[r][i] == from && quads_[r][(i + 1) % 4] == to) return {r, i};
      }
    }
    return {-1, 0};
  }

  void replace(int q, const Quad& quad) {
    log_.emplace_back(q, quads_[q]);
    set(q, quad);
  }
  void set(int q, const Quad& quad) { around_.set(q, quad); }
  // Undoes the last `turns` turns (two replaced quads each).
  void undo(int turns) {
    for (int i = 0; i < 2 * turns; ++i) {
      set(log_.back().first, log_.back().second);
      log_.pop_back();
    }
  }

  // Turns from the flat lone node a on, `way` along the boundary; returns the number
  // of turns made when the chain ended well, else undoes them and returns 0.
  int chain(NodeId a, Toward way) {
    int turns = 0;
    for (NodeId lone = a; turns < kMaxChain;) {
      const int q = around_.of(lone)[0];
      const Quad quad = quads_[q];
      const int k = static_cast<int>(std::find(quad.begin(), quad.end(), lone) - quad.begin());
      const NodeId b = quad[(k + 1) % 4], c = quad[(k + 2) % 4], d = quad[(k + 3) % 4];
      // The node giving up a quad along the boundary, the one giving up a quad inside
      // (c), and the two new quads.
      const NodeId giver = way == Toward::d ? d : b;
      const auto [r, at] = way == Toward::d ? across(q, d, c) : across(q, c, b);
      if (r < 0 || c < fixed_ || around_.of(c).size() < 4) break;
      const NodeId far1 = quads_[r][(at + 2) % 4], far2 = quads_[r][(at + 3) % 4];
      const Quad first = way == Toward::d ? Quad{lone, b, c, far1} : Quad{lone, b, far1, far2};
      const Quad second = way == Toward::d ? Quad{lone, far1, far2, d} : Quad{lone, far2, c, d};
      if (!distinct(first) || !distinct(second)) break;
      replace(q, first);
      replace(r, second);
      ++turns;
      if (giver >= fixed_) {  // an inner node (a hole's edge is boundary too): keep three
        if (around_.of(giver).size() >= 3) return turns;
        break;
      }
      if (!flat_and_alone(giver)) return turns;  // it kept two quads, or a real corner
      lone = giver;
    }
    undo(turns);
    return 0;
  }

  static bool distinct(const Quad& q) {
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) if (q[i] == q[j]) return false;
    }
    return true;
  }

  std::vector<Quad>& quads_;
  const int fixed_;
  const std::vector<Vec3>& position_;
  const std::vector<Vec3>& normal_;
  QuadsAroundNodes around_;                         // each node's quads, kept up to date
  std::vector<std::pair<int, Quad>> log_;           // replaced quads, for undo
};

}  // namespace

bool has_flat_lone_corner(const std::vector<Quad>& quads, int fixed, const std::vector<Vec3>& position,
                          const std::vector<Vec3>& normal) {
  std::vector<int> lone_in(fixed, -1);  // the quad of a node alone in one, -2 if in more
  for (std::size_t q = 0; q < quads.size(); ++q) {
    poll_cancellation(4);
    for (NodeId n : quads[q]) {
      if (n < fixed) lone_in[n] = lone_in[n] == -1 ? static_cast<int>(q) : -2;
    }
  }
  for (NodeId n = 0; n < fixed; ++n) {
    if (lone_in[n] >= 0 && corner_at(quads[lone_in[n]], n, position, normal) < kFlatCornerBelow) return true;
  }
  return false;
}

int turn_flat_boundary_corners(std::vector<Quad>& quads, int fixed, const std::vector<Vec3>& position,
                               const std::vector<Vec3>& normal) {
  if (!has_flat_lone_corner(quads, fixed, position, normal)) return 0;  // most meshes
  FlatCornerTurner turner(quads, fixed, position, normal);
  int total = 0;
  for (NodeId a = 0; a < fixed; ++a) total += turner.mend(a);
  return total;
}

}  // namespace tquad
