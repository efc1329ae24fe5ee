#include "core/flat_corner_turns.h"

#include <algorithm>
#include <array>
#include <optional>

#include "core/node_adjacency.h"
#include "core/quality.h"

namespace tquad {

namespace {

// Passes over the mesh; each turns quads no other turn of the pass touched.
constexpr int kPasses = 4;

struct Turn {
  int first, second;          // the two quads replaced
  Quad new_first, new_second;  // and their replacements
  double worst;               // the replacements' worst corner where they are now
};

class FlatCornerTurner {
 public:
  FlatCornerTurner(std::vector<Quad>& quads, int fixed, const std::vector<Vec3>& position,
                   const std::vector<Vec3>& normal)
      : quads_(quads), fixed_(fixed), position_(position), normal_(normal) {}

  int pass() {
    const CompressedLists around = quads_around_nodes(position_.size(), quads_);
    std::vector<char> touched(quads_.size(), 0);
    gained_.assign(position_.size(), 0);
    int turns = 0;
    for (int a = 0; a < fixed_; ++a) {
      if (quads_at(around, a) != 1) continue;
      const int q = around.items[around.offsets[a]];
      if (touched[q]) continue;
      const std::optional<Turn> turn = best_turn(around, a, q, touched);
      if (!turn) continue;
      for (NodeId n : quads_[turn->first]) --gained_[n];
      for (NodeId n : quads_[turn->second]) --gained_[n];
      quads_[turn->first] = turn->new_first;
      quads_[turn->second] = turn->new_second;
      for (NodeId n : turn->new_first) ++gained_[n];
      for (NodeId n : turn->new_second) ++gained_[n];
      touched[turn->first] = touched[turn->second] = 1;
      ++turns;
    }
    return turns;
  }

 private:
  double worst_corner(const Quad& quad) const {
    std::array<Vec3, 4> p, n;
    for (int i = 0; i < 4; ++i) {
      p[i] = position_[quad[i]];
      n[i] = normal_[quad[i]];
    }
    const QuadCorners corners = quad_corners(p, n);
    return corners.collapsed ? -1.0 : *std::min_element(corners.jacobian.begin(), corners.jacobian.end());
  }

  // Node n's quads now: the pass's lists, and what its turns so far gave or took.
  int quads_at(const CompressedLists& around, NodeId n) const {
    return around.offsets[n + 1] - around.offsets[n] + gained_[n];
  }

  // The scaled Jacobian of `quad` at its node n, each corner signed by its node's normal.
  double corner_at(const Quad& quad, NodeId n) const {
    std::array<Vec3, 4> p, nn;
    for (int i = 0; i < 4; ++i) {
      p[i] = position_[quad[i]];
      nn[i] = normal_[quad[i]];
    }
    const int k = static_cast<int>(std::find(quad.begin(), quad.end(), n) - quad.begin());
    return quad_corners(p, nn).jacobian[k];
  }

  // Whether node n may give up one of its quads, `keeping` the one it stays in: an
  // inner node keeps three (two would make it a doublet), a boundary node two, or one
  // where its corner there (between its two boundary neighbours: the boundary's own
  // angle) is not flat, as at a corner of the face.
  bool may_lose_one(const CompressedLists& around, NodeId n, const Quad& keeping) const {
    const int count = quads_at(around, n);
    if (n >= fixed_) return count >= 4;
    return count >= 3 || (count == 2 && corner_at(keeping, n) >= kFlatCornerBelow);
  }

  // The quad other than q with the directed edge from -> to (q has it the other way).
  int across(const CompressedLists& around, int q, NodeId from, NodeId to, int& at) const {
    for (int k = around.offsets[from]; k < around.offsets[from + 1]; ++k) {
      const int r = around.items[k];
      if (r == q) continue;
      for (int i = 0; i < 4; ++i) {
        if (quads_[r][i] == from && quads_[r][(i + 1) % 4] == to) {
          at = i;
          return r;
        }
      }
    }
    return -1;
  }

  // q = (a, b, c, d) from a. Across c-d lies r = (d, c, x, y): the hexagon a b c x y d
  // cut along a-x instead gives (a, b, c, x) and (a, x, y, d); c and d lose a quad.
  // Across b-c lies s = (c, b, u, v): the hexagon a b u v c d cut along a-v gives
  // (a, b, u, v) and (a, v, c, d); b and c lose a quad.
  std::optional<Turn> best_turn(const CompressedLists& around, NodeId a, int q, const std::vector<char>& touched) const {
    const Quad& quad = quads_[q];
    const int k = static_cast<int>(std::find(quad.begin(), quad.end(), a) - quad.begin());
    const NodeId b = quad[(k + 1) % 4], c = quad[(k + 2) % 4], d = quad[(k + 3) % 4];
    if (corner_at(quad, a) >= kFlatCornerBelow) return std::nullopt;
    std::optional<Turn> best;
    const auto consider = [&](int r, const Quad& first, const Quad& second) {
      if (r < 0 || touched[r]) return;
      for (const Quad& made : {first, second}) {
        for (int i = 0; i < 4; ++i) {
          for (int j = i + 1; j < 4; ++j) if (made[i] == made[j]) return;
        }
      }
      const double after = std::min(worst_corner(first), worst_corner(second));
      if (!best || after > best->worst) {
        best = Turn{q, r, first, second, after};
      }
    };
    int at = 0;
    if (const int r = across(around, q, d, c, at); r >= 0) {
      const NodeId x = quads_[r][(at + 2) % 4], y = quads_[r][(at + 3) % 4];
      const Quad first{a, b, c, x}, second{a, x, y, d};
      if (may_lose_one(around, c, first) && may_lose_one(around, d, second)) consider(r, first, second);
    }
    if (const int s = across(around, q, c, b, at); s >= 0) {
      const NodeId u = quads_[s][(at + 2) % 4], v = quads_[s][(at + 3) % 4];
      const Quad first{a, b, u, v}, second{a, v, c, d};
      if (may_lose_one(around, b, first) && may_lose_one(around, c, second)) consider(s, first, second);
    }
    return best;
  }

  std::vector<Quad>& quads_;
  const int fixed_;
  const std::vector<Vec3>& position_;
  const std::vector<Vec3>& normal_;
  std::vector<int> gained_;  // per node, quads gained (lost: negative) in this pass
};

}  // namespace

int turn_flat_boundary_corners(std::vector<Quad>& quads, int fixed, const std::vector<Vec3>& position,
                               const std::vector<Vec3>& normal) {
  FlatCornerTurner turner(quads, fixed, position, normal);
  int total = 0;
  for (int pass = 0; pass < kPasses; ++pass) {
    const int turns = turner.pass();
    total += turns;
    if (turns == 0) break;
  }
  return total;
}

}  // namespace tquad
