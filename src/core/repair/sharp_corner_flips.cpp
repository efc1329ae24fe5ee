#include "core/repair/sharp_corner_flips.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "core/repair/flat_corner_turns.h"
#include "core/mesh/quads_around_nodes.h"
#include "core/mesh/quality.h"

namespace tquad {

namespace {

// `quad` turned so that node n comes first.
Quad starting_at(Quad quad, NodeId n) {
  std::rotate(quad.begin(), std::find(quad.begin(), quad.end(), n), quad.end());
  return quad;
}

// The two quads' worst corner, each corner signed by its node's normal.
double worst_of(const Quad& a, const Quad& b, const std::vector<Vec3>& position, const std::vector<Vec3>& normal) {
  double worst = 1;
  for (const Quad& quad : {a, b}) {
    for (double c : quad_corners(quad, position, normal).jacobian) worst = std::min(worst, c);
  }
  return worst;
}

class SharpCornerFlipper {
 public:
  SharpCornerFlipper(std::vector<Quad>& quads, int fixed, const std::vector<Vec3>& position,
                     const std::vector<Vec3>& normal, FlipDiagonal diagonal)
      : fixed_(fixed), position_(position), normal_(normal), diagonal_(diagonal),
        around_(quads, position.size()) {}

  bool flip(NodeId corner) {
    if (around_.of(corner).size() != 2) return false;
    int q1 = around_.of(corner)[0], q2 = around_.of(corner)[1];
    Quad first = starting_at(around_.quad(q1), corner), second = starting_at(around_.quad(q2), corner);
    // The shared edge runs corner -> d in `second` and d -> corner in `first`
    // (both counter-clockwise): the hexagon is corner, b, c, d, e, f.
    if (first[3] != second[1]) {
      std::swap(q1, q2);
      std::swap(first, second);
    }
    if (first[3] != second[1]) return false;
    const NodeId d = first[3];
    if (d < fixed_ || around_.of(d).size() < 4) return false;
    if (!lopsided_and_sharp(first, second)) return false;
    const std::array<NodeId, 6> hexagon{corner, first[1], first[2], d, second[2], second[3]};
    for (int i = 0; i < 6; ++i) {
      for (int j = i + 1; j < 6; ++j) if (hexagon[i] == hexagon[j]) return false;
    }
    // The diagonals from b (to e) and from c (to f), the better first.
    std::vector<std::pair<double, std::pair<Quad, Quad>>> cuts;
    for (int from : {1, 2}) {
      if (joined(hexagon[from], hexagon[from + 3])) continue;  // an edge already: the mesh would fold over it
      const Quad a{hexagon[from], hexagon[from + 1], hexagon[from + 2], hexagon[from + 3]};
      const Quad b{hexagon[(from + 3) % 6], hexagon[(from + 4) % 6], hexagon[(from + 5) % 6], hexagon[from]};
      cuts.push_back({worst_of(a, b, position_, normal_), {a, b}});
    }
    std::stable_sort(cuts.begin(), cuts.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    const std::size_t pick = diagonal_ == FlipDiagonal::better_now ? 0 : 1;
    if (pick >= cuts.size()) return false;
    around_.set(q1, cuts[pick].second.first);
    around_.set(q2, cuts[pick].second.second);
    return true;
  }

 private:
  // The corner is at most kSharpCornerUpTo (its two quads' angles there summed) and
  // one of its two quads' corners there is under kFlatCornerBelow.
  bool lopsided_and_sharp(const Quad& first, const Quad& second) const {
    const NodeId corner = first[0];
    const Vec3& at = position_[corner];
    const double angle = angle_between(position_[first[1]] - at, position_[first[3]] - at) +
                         angle_between(position_[second[1]] - at, position_[second[3]] - at);
    if (!(angle <= kSharpCornerUpTo)) return false;
    return std::min(corner_of(first), corner_of(second)) < kFlatCornerBelow;
  }

  // The scaled Jacobian of `quad` at its first node.
  double corner_of(const Quad& quad) const { return quad_corners(quad, position_, normal_).jacobian[0]; }

  // Whether nodes p and q are an edge of some quad.
  bool joined(NodeId p, NodeId q) const {
    for (int r : around_.of(p)) {
      const Quad& quad = around_.quad(r);
      for (int i = 0; i < 4; ++i) {
        if (quad[i] == p && (quad[(i + 1) % 4] == q || quad[(i + 3) % 4] == q)) return true;
      }
    }
    return false;
  }

  const int fixed_;
  const std::vector<Vec3>& position_;
  const std::vector<Vec3>& normal_;
  const FlipDiagonal diagonal_;
  QuadsAroundNodes around_;  // each node's quads, kept up to date
};

}  // namespace

int flip_lopsided_sharp_corners(std::vector<Quad>& quads, int fixed, const std::vector<Vec3>& position,
                                const std::vector<Vec3>& normal, FlipDiagonal diagonal) {
  SharpCornerFlipper flipper(quads, fixed, position, normal, diagonal);
  int flips = 0;
  for (NodeId n = 0; n < fixed; ++n) flips += flipper.flip(n) ? 1 : 0;
  return flips;
}

}  // namespace tquad
