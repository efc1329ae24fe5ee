#include "core/decomposition/face_decomposition.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>

#include "core/decomposition/coarse_triangulation.h"
#include "core/input_error.h"
#include "core/geometry/planar_predicates.h"
#include "core/geometry/planar_self_intersection.h"

namespace tquad {

namespace {

constexpr double kDegree = M_PI / 180.0;
// A CAD vertex that turns this much is a corner the patches keep (the corner rule of
// face_corners.h, a little stricter because the turn here is the discrete one).
constexpr double kSharpVertexTurn = 30.0 * kDegree;
// Any boundary point turning this much is a corner, CAD vertex or not.
constexpr double kSharpPointTurn = 60.0 * kDegree;
// A piece of boundary between coarse vertices turns at most this much in all: a
// cut's end then meets the piece at most ~30 degrees off its chord.
constexpr double kMaxPieceTurn = 60.0 * kDegree;
// Two triangles become one four-sided patch when every corner of the union lies in
// [25, 155] degrees.
constexpr double kPairAngleMin = 25.0 * kDegree;
// ... or in [10, 170] degrees when one of them has a one-segment boundary piece.
constexpr double kUrgentPairAngleMin = 10.0 * kDegree;
// A cut that leaves the boundary at less than this makes a sliver patch against a
// curved piece: the piece is split (when it can be) so the cut can start elsewhere.
constexpr double kMinCutAngle = 15.0 * kDegree;
// A pair whose corners all lie within 30 degrees of square (sines of 0.866 or more)
// is a patch worth keeping whole (DecompositionOptions::keep_square_pairs).
constexpr double kSquarePair = 0.866;

int wrap(int i, int n) { return ((i % n) + n) % n; }

// Unsigned angle between two vectors of the chart's plane (radians, in [0, pi]).
double planar_angle_between(const Vec3& u, const Vec3& v) { return std::abs(signed_angle(u, v)); }

// Signed turn of the loop at point i (radians, > 0 to the left).
double turn_at(const std::vector<Vec3>& p, int i) {
  const int n = static_cast<int>(p.size());
  return signed_angle(p[i] - p[wrap(i - 1, n)], p[wrap(i + 1, n)] - p[i]);
}

// Points first+1 .. last-1 (forward, cyclic) of a loop of n points.
// (first == last: the whole loop but that point.)
int inner_count(int first, int last, int n) { return first == last ? n - 1 : wrap(last - first, n) - 1; }

// The coarse vertices of one loop (sorted point indices).
class LoopCoarsening {
 public:
  // `reflex_turn`: DecompositionOptions::reflex_point_turn.
  LoopCoarsening(const DomainLoop& loop, double reflex_turn) : points_(loop.points) {
    const int n = size();
    turns_.resize(n);
    for (int i = 0; i < n; ++i) turns_[i] = turn_at(points_, i);
    for (int i = 0; i < n; ++i) {
      const bool vertex = !loop.vertex.empty() && loop.vertex[i];
      if ((vertex && std::abs(turns_[i]) >= kSharpVertexTurn) || std::abs(turns_[i]) >= kSharpPointTurn ||
          turns_[i] <= -reflex_turn) {
        coarse_.insert(i);
      }
    }
    if (coarse_.empty()) coarse_.insert(sharpest_point());
    split_by_turning();
    while (static_cast<int>(coarse_.size()) < std::min(3, n)) split_longest();
  }

  const std::set<int>& coarse() const { return coarse_; }
  bool is_coarse(int point) const { return coarse_.count(point) > 0; }
  void add(int point) { coarse_.insert(point); }
  double turn(int point) const { return turns_[point]; }

  // (first, last) of each piece between consecutive coarse vertices, in loop order.
  std::vector<std::pair<int, int>> pieces() const {
    std::vector<std::pair<int, int>> out;
    for (auto it = coarse_.begin(); it != coarse_.end(); ++it) {
      const auto next = std::next(it);
      out.push_back({*it, next == coarse_.end() ? *coarse_.begin() : *next});
    }
    return out;
  }

  // Adds the middle point of the piece when both halves keep at least `segments`
  // segments; false otherwise.
  bool split(int first, int last, int segments = 1) {
    const int inner = inner_count(first, last, size());
    if (inner < 2 * segments - 1) return false;
    coarse_.insert(wrap(first + (inner + 1) / 2, size()));
    return true;
  }

  // Adds the middle point of the piece holding segment `segment` (from point segment
  // to segment + 1); false when that piece has a single segment.
  bool split_piece_at(int segment) {
    int first = *coarse_.rbegin(), last = *coarse_.begin();  // the wrapping piece
    const auto after = coarse_.upper_bound(segment);
    if (after != coarse_.end() && after != coarse_.begin()) {
      last = *after;
      first = *std::prev(after);
    }
    return split(first, last);
  }

 private:
  int size() const { return static_cast<int>(points_.size()); }

  int sharpest_point() const {
    int best = 0;
    for (int i = 1; i < size(); ++i) if (std::abs(turns_[i]) > std::abs(turns_[best])) best = i;
    return best;
  }

  // Splits each piece into equal shares of its turning of at most kMaxPieceTurn.
  void split_by_turning() {
    for (const auto& [first, last] : pieces()) {
      const int inner = inner_count(first, last, size());
      double total = 0;
      for (int k = 1; k <= inner; ++k) total += std::abs(turns_[wrap(first + k, size())]);
      // Shares of at least 2 segments: a one-segment piece on a three-sided patch
      // makes the templates add a corner on a straight side.
      const int shares = std::min(static_cast<int>(std::ceil(total / kMaxPieceTurn - 1e-9)), (inner + 1) / 2);
      if (shares <= 1) continue;
      double running = 0;
      int next_share = 1, previous = 0;
      for (int k = 1; k <= inner && next_share < shares; ++k) {
        const int i = wrap(first + k, size());
        running += std::abs(turns_[i]);
        if (running >= next_share * total / shares - 1e-12 && k - previous >= 2 && inner + 1 - k >= 2) {
          coarse_.insert(i);
          previous = k;
          ++next_share;
        }
      }
    }
  }

  void split_longest() {
    int best_first = 0, best_last = 0, most = -1;
    for (const auto& [first, last] : pieces()) {
      const int inner = inner_count(first, last, size());
      if (inner > most) { most = inner; best_first = first; best_last = last; }
    }
    // check_domain refused loops of fewer than 3 points.
    if (!split(best_first, best_last)) throw std::logic_error("a loop of 3 or more points has no piece to split");
  }

  const std::vector<Vec3>& points_;
  std::vector<double> turns_;
  std::set<int> coarse_;
};

// The coarse polygon: its vertices (loop, point) in loop order, and the reverse map.
struct CoarsePolygon {
  std::vector<std::vector<int>> points;  // per loop, point indices
  std::vector<std::pair<int, int>> of_id;  // coarse id -> (loop, position in points[loop])

  explicit CoarsePolygon(const std::vector<std::set<int>>& coarse) {
    for (std::size_t l = 0; l < coarse.size(); ++l) {
      points.emplace_back(coarse[l].begin(), coarse[l].end());
      for (std::size_t k = 0; k < points[l].size(); ++k) of_id.push_back({static_cast<int>(l), static_cast<int>(k)});
    }
  }
  int loop(int id) const { return of_id[id].first; }
  int point(int id) const { return points[of_id[id].first][of_id[id].second]; }
  // y follows x on their loop: the side x -> y is a boundary piece.
  bool is_piece(int x, int y) const {
    if (loop(x) != loop(y)) return false;
    const int n = static_cast<int>(points[loop(x)].size());
    return of_id[y].second == (of_id[x].second + 1) % n;
  }
};

}  // namespace

std::vector<std::pair<int, int>> cut_obstacles(const PlanarDomain& d, int lx, int px, int ly, int py) {
  const auto point = [&](int l, int i) -> const Vec3& { return d.loops[l].points[i]; };
  const Vec3 &a = point(lx, px), &b = point(ly, py);
  std::vector<std::pair<int, int>> out;
  for (int l = 0; l < d.loop_count(); ++l) {
    const int n = static_cast<int>(d.loops[l].points.size());
    for (int s = 0; s < n; ++s) {
      const int s1 = (s + 1) % n;
      const bool touches_x = l == lx && (s == px || s1 == px);
      const bool touches_y = l == ly && (s == py || s1 == py);
      if (touches_x || touches_y) continue;
      if (segments_meet(a, b, point(l, s), point(l, s1))) out.push_back({l, s});
    }
  }
  if (!out.empty()) return out;
  for (const auto& [l, p, from, to] : {std::tuple{lx, px, a, b}, std::tuple{ly, py, b, a}}) {
    const int n = static_cast<int>(d.loops[l].points.size());
    if (!inside_corner(point(l, wrap(p - 1, n)), from, point(l, wrap(p + 1, n)), to)) {
      out.push_back({l, p});
      out.push_back({l, wrap(p - 1, n)});
    }
  }
  return out;
}

namespace {

// Patches of coarse corners (counter-clockwise) made of the coarse triangles, and the
// diagonals (lower id first) of the pairs merged outside the corner window because
// their triangles were slivers.
struct Pairing {
  std::vector<std::vector<int>> patches;
  std::set<std::pair<int, int>> rescued_diagonals;
  // DecompositionOptions::keep_square_pairs: the diagonals of the pairs kept whole.
  std::set<std::pair<int, int>> square_diagonals;
};

class Decomposer {
 public:
  Decomposer(const PlanarDomain& domain, const DecompositionOptions& options)
      : d_(domain), options_(options) {
    for (const DomainLoop& loop : d_.loops) coarsening_.emplace_back(loop, options.reflex_point_turn * kDegree);
    join_thin_junctions();
    split_by_feature_size();
    if (options.cross_thin_bands) band_crossings_ = cross_thin_bands();
    if (options.extend_reflex_corners) reflex_extensions_ = extend_reflex_corners();
    if (options.clear_corner_ears) corner_splits_ = clear_corner_ears();
  }

  // Triangulates, clears blocked and sliver cuts by adding coarse vertices, and
  // builds the patches. Ends within kRounds: after that, or when nothing more can be
  // added, every boundary point becomes a coarse vertex, and if even that
  // triangulation has a cut outside the domain the boundary is refused.
  FaceDecomposition run() {
    constexpr int kRounds = 12;
    FaceDecomposition out;
    out.corner_splits = corner_splits_;
    out.neighbour_splits = neighbour_splits_;
    out.band_crossings = band_crossings_;
    out.reflex_extensions = reflex_extensions_;
    std::vector<std::set<int>> coarse;
    for (const LoopCoarsening& c : coarsening_) coarse.push_back(c.coarse());
    for (int round = 0;; ++round) {
      const bool last_resort = all_points(coarse);
      const CoarsePolygon polygon(coarse);
      std::vector<CoarseTriangle> triangles;
      try {
        // An ear whose two sides are one-segment pieces is a triangle of 4 edges: one
        // quad with a straight angle. Cut it only when nothing else is left.
        triangles = triangulate_polygon_with_holes(coarse_loops(polygon), [&](int a, int b, int c) {
          return polygon.is_piece(a, b) && polygon.is_piece(b, c) && piece_segments(polygon, a) == 1 &&
                 piece_segments(polygon, b) == 1;
        });
      } catch (const TriangulationFailure& e) {
        if (last_resort) throw InputError(std::string("the boundary cannot be cut into patches: ") + e.what());
        coarse = every_point();
        continue;
      }
      // (loop, segment) met by a cut: must be cleared.
      std::vector<std::pair<int, int>> blocked;
      for (const CoarseTriangle& t : triangles) {
        for (int i = 0; i < 3; ++i) {
          const int x = t[i], y = t[(i + 1) % 3];
          // Each diagonal is met once in each direction: checked once.
          if (x < y && !polygon.is_piece(x, y) && !polygon.is_piece(y, x)) blocked_segments(polygon, x, y, blocked);
        }
      }
      if (last_resort) {
        if (!blocked.empty()) throw InputError("the boundary cannot be cut into patches: a cut leaves the domain");
        const Pairing pairing = pair_triangles(polygon, triangles);
        out.square_pair_slivers = square_pair_slivers_;
        build(polygon, pairing, out);
        return out;
      }
      bool added = false;
      for (const auto& [loop, segment] : blocked) added = coarsening_[loop].split_piece_at(segment) || added;
      if (blocked.empty()) {
        // A diagonal that a pair merged only for its slivers (Pairing) is left out:
        // splitting a piece there brings the slivers back.
        const Pairing pairing = pair_triangles(polygon, triangles);
        if (round < kRounds) {
          const std::vector<std::pair<int, int>> slivers = sliver_segments(polygon, triangles, skipped_diagonals(pairing));
          if (options_.keep_square_pairs) {
            square_pair_slivers_ +=
                static_cast<int>(sliver_segments(polygon, triangles, pairing.rescued_diagonals).size() - slivers.size());
          }
          for (const auto& [loop, segment] : slivers) added = coarsening_[loop].split_piece_at(segment) || added;
        }
        if (!added) {
          out.square_pair_slivers = square_pair_slivers_;
          build(polygon, pairing, out);
          return out;
        }
      }
      coarse.clear();
      for (const LoopCoarsening& c : coarsening_) coarse.push_back(c.coarse());
      if (!added || round >= kRounds) coarse = every_point();
    }
  }

 private:
  const Vec3& point(int loop, int i) const { return d_.loops[loop].points[i]; }

  // DecompositionOptions::clear_corner_ears; returns the pieces split.
  int clear_corner_ears() {
    constexpr double kCornerTurn = 60.0 * kDegree;
    constexpr int kPasses = 8;
    int splits = 0;
    for (int pass = 0; pass < kPasses; ++pass) {
      bool changed = false;
      for (int l = 0; l < d_.loop_count(); ++l) {
        const std::vector<std::pair<int, int>> pieces = coarsening_[l].pieces();
        const int count = static_cast<int>(pieces.size());
        for (int k = 0; k < count && !changed; ++k) {
          const int before = pieces[wrap(k - 1, count)].first, corner = pieces[k].first, after = pieces[k].second;
          const Vec3 &p = point(l, before), &q = point(l, corner), &r = point(l, after);
          if (signed_angle(q - p, r - q) < kCornerTurn && turn_at(d_.loops[l].points, corner) < kCornerTurn) continue;
          if (orient2d(p, q, r) <= 0 || !other_loop_in_circle(l, p, q, r)) continue;
          // The longer piece first; the other when the longer cannot be split.
          const bool longer_before = distance(p, q) >= distance(q, r);
          const bool split = longer_before ? coarsening_[l].split(before, corner, 2) || coarsening_[l].split(corner, after, 2)
                                           : coarsening_[l].split(corner, after, 2) || coarsening_[l].split(before, corner, 2);
          splits += split ? 1 : 0;
          changed = split || changed;
        }
      }
      if (!changed) break;
    }
    return splits;
  }

  // Whether a point of a loop other than `loop` lies strictly inside the circle
  // through p, q and r (counter-clockwise).
  bool other_loop_in_circle(int loop, const Vec3& p, const Vec3& q, const Vec3& r) const {
    const double ax = p.x - q.x, ay = p.y - q.y, bx = r.x - q.x, by = r.y - q.y;
    const double twice_area = 2 * (ax * by - ay * bx);
    const double ux = (by * (ax * ax + ay * ay) - ay * (bx * bx + by * by)) / twice_area;
    const double uy = (ax * (bx * bx + by * by) - bx * (ax * ax + ay * ay)) / twice_area;
    const Vec3 centre{q.x + ux, q.y + uy, 0};
    const double radius = std::hypot(ux, uy);
    for (int m = 0; m < d_.loop_count(); ++m) {
      if (m == loop) continue;
      for (int i = 0; i < loop_size(m); ++i) {
        if (distance(centre, point(m, i)) < radius * (1 - 1e-9)) return true;
      }
    }
    return false;
  }

  // A reflex corner much nearer to a boundary point in front of it than to its own
  // neighbours is a thin junction (a thin flange meeting a plate, far narrower than
  // the segments along it): that point becomes a coarse vertex, so that the
  // triangulation can cut straight across and the flange stays one band of quads
  // instead of a fan of slivers into the middle of its long side.
  void join_thin_junctions() {
    constexpr double kThinJunction = 0.5;  // cut / shortest boundary segment at its ends
    for (int l = 0; l < d_.loop_count(); ++l) {
      const int n = loop_size(l);
      for (const int c : std::vector<int>(coarsening_[l].coarse().begin(), coarsening_[l].coarse().end())) {
        if (coarsening_[l].turn(c) > -kSharpVertexTurn) continue;
        const auto [before, after] = neighbours_of(l, c);
        int best_loop = -1, best_point = -1;
        double best = INFINITY;
        for (int m = 0; m < d_.loop_count(); ++m) {
          for (int i = 0; i < loop_size(m); ++i) {
            if (m == l && wrap(i - before, n) <= wrap(after - before, n)) continue;
            const double gap = distance(point(l, c), point(m, i));
            if (gap < best) { best = gap; best_loop = m; best_point = i; }
          }
        }
        if (best_loop < 0 || coarsening_[best_loop].is_coarse(best_point)) continue;
        if (best >= kThinJunction * std::min(shortest_segment_at(l, c), shortest_segment_at(best_loop, best_point))) continue;
        if (!cut_obstacles(d_, l, c, best_loop, best_point).empty()) continue;
        coarsening_[best_loop].add(best_point);
      }
    }
  }

  // DecompositionOptions::cross_thin_bands; returns the points made coarse. Passes
  // until none is added: a point made coarse is crossed from in turn.
  int cross_thin_bands() {
    constexpr double kThinBand = 1.0;           // gap / shortest boundary segment at both ends
    constexpr double kAcross = 30.0 * kDegree;  // off each side's inward normal, at most
    constexpr int kPasses = 4;
    int added = 0;
    for (int pass = 0; pass < kPasses; ++pass) {
      bool changed = false;
      for (int l = 0; l < d_.loop_count(); ++l) {
        for (const int c : std::vector<int>(coarsening_[l].coarse().begin(), coarsening_[l].coarse().end())) {
          int best_loop = -1, best_point = -1;
          double best = INFINITY;
          for (int m = 0; m < d_.loop_count(); ++m) {
            for (int i = 0; i < loop_size(m); ++i) {
              const Vec3 across = point(m, i) - point(l, c);
              const double gap = norm(across);
              if (gap >= best || (m == l && i == c) || !faces(l, c, across, kAcross)) continue;
              best = gap;
              best_loop = m;
              best_point = i;
            }
          }
          if (best_loop < 0 || coarsening_[best_loop].is_coarse(best_point)) continue;
          if (best >= kThinBand * std::min(shortest_segment_at(l, c), shortest_segment_at(best_loop, best_point))) continue;
          if (!faces(best_loop, best_point, point(l, c) - point(best_loop, best_point), kAcross)) {
            continue;  // not a band: the other side does not face back
          }
          if (!cut_obstacles(d_, l, c, best_loop, best_point).empty()) continue;
          coarsening_[best_loop].add(best_point);
          ++added;
          changed = true;
        }
      }
      if (!changed) break;
    }
    return added;
  }

  // DecompositionOptions::extend_reflex_corners; returns the points made coarse.
  int extend_reflex_corners() {
    constexpr double kMostLean = 20.0 * kDegree;  // between the continued side and the cut
    int added = 0;
    for (int l = 0; l < d_.loop_count(); ++l) {
      const int n = loop_size(l);
      for (const int c : std::vector<int>(coarsening_[l].coarse().begin(), coarsening_[l].coarse().end())) {
        if (coarsening_[l].turn(c) > -kSharpVertexTurn) continue;
        const Vec3& corner = point(l, c);
        for (const Vec3& side : {corner - point(l, wrap(c - 1, n)), corner - point(l, (c + 1) % n)}) {
          const std::optional<std::pair<int, int>> end = side_continued(l, c, side, kMostLean);
          if (!end || !cut_obstacles(d_, l, c, end->first, end->second).empty()) continue;
          if (coarsening_[end->first].is_coarse(end->second)) continue;
          coarsening_[end->first].add(end->second);
          ++added;
        }
      }
    }
    return added;
  }

  // The boundary point (loop, point) nearest to where the ray from point c of loop l
  // along `direction` first meets the boundary, when the way to it leans by at most
  // `most_lean` from the ray and it is not one of c's neighbours.
  std::optional<std::pair<int, int>> side_continued(int l, int c, const Vec3& direction, double most_lean) const {
    const Vec3& from = point(l, c);
    const double length = norm(direction);
    if (!(length > 0)) return std::nullopt;
    const Vec3 ray = (1.0 / length) * direction;
    double nearest = INFINITY;
    std::pair<int, int> hit{-1, -1};
    Vec3 at;
    for (int m = 0; m < d_.loop_count(); ++m) {
      const int size = loop_size(m);
      for (int s = 0; s < size; ++s) {
        const int s1 = (s + 1) % size;
        if (m == l && (s == c || s1 == c)) continue;
        const Vec3 &a = point(m, s), &b = point(m, s1);
        const Vec3 ab = b - a, ao = a - from;
        const double denominator = ray.x * ab.y - ray.y * ab.x;
        if (denominator == 0) continue;  // parallel
        const double t = (ao.x * ab.y - ao.y * ab.x) / denominator;   // along the ray
        const double u = (ao.x * ray.y - ao.y * ray.x) / denominator;  // along the segment
        if (!(t > 0) || u < 0 || u > 1 || t >= nearest) continue;
        nearest = t;
        hit = {m, u < 0.5 ? s : s1};
        at = a + u * ab;
      }
    }
    if (hit.first < 0) return std::nullopt;
    const int n = loop_size(l);
    if (hit.first == l && (hit.second == wrap(c - 1, n) || hit.second == (c + 1) % n)) return std::nullopt;
    const Vec3 cut = point(hit.first, hit.second) - from;
    if (planar_angle_between(cut, at - from) > most_lean) return std::nullopt;
    return hit;
  }

  // Whether `direction` from point i of loop l is within `angle` of the inward normal
  // of one of the two boundary segments there (the domain lies to the left of its
  // loops): at a corner, straight in front of either side.
  bool faces(int l, int i, const Vec3& direction, double angle) const {
    const int n = loop_size(l);
    for (const Vec3& along : {point(l, i) - point(l, wrap(i - 1, n)), point(l, (i + 1) % n) - point(l, i)}) {
      if (planar_angle_between(Vec3{-along.y, along.x, 0}, direction) <= angle) return true;
    }
    return false;
  }

  // The coarse vertices before and after point c of loop l.
  std::pair<int, int> neighbours_of(int l, int c) const {
    const std::set<int>& coarse = coarsening_[l].coarse();
    auto it = coarse.find(c);
    const int after = std::next(it) == coarse.end() ? *coarse.begin() : *std::next(it);
    const int before = it == coarse.begin() ? *coarse.rbegin() : *std::prev(it);
    return {before, after};
  }

  double shortest_segment_at(int l, int i) const {
    const int n = loop_size(l);
    return std::min(distance(point(l, wrap(i - 1, n)), point(l, i)), distance(point(l, i), point(l, (i + 1) % n)));
  }

  // Pieces much longer than the gap in front of them (the distance from their middle
  // to the rest of the boundary, their neighbouring pieces left out) are split, so the
  // coarse vertices are spaced like the domain's local feature size and the
  // triangulation has no long slivers (a plate's long side next to a row of holes).
  void split_by_feature_size() {
    constexpr double kLongerThanGap = 2.0;
    // DecompositionOptions::neighbours_across_corners: within this of the piece's
    // inward normal at its middle (a 60-degree corner's neighbour stays out).
    constexpr double kInFront = 30.0 * kDegree;
    for (int pass = 0; pass < 8; ++pass) {
      bool changed = false;
      for (int l = 0; l < d_.loop_count(); ++l) {
        const int n = loop_size(l);
        const std::vector<std::pair<int, int>> pieces = coarsening_[l].pieces();
        const int count = static_cast<int>(pieces.size());
        for (int k = 0; k < count; ++k) {
          const auto [first, last] = pieces[k];
          const int inner = inner_count(first, last, n);
          if (inner < 1) continue;
          const Vec3& middle = point(l, wrap(first + (inner + 1) / 2, n));
          const double chord = distance(point(l, first), point(l, last));
          const Vec3 along = point(l, last) - point(l, first);
          const Vec3 inward{-along.y, along.x, 0};  // the domain lies to the left of its loops
          // Points of this piece and its two neighbours are not "in front" of it.
          const int skip_from = pieces[wrap(k - 1, count)].first, skip_to = pieces[(k + 1) % count].second;
          const int skipped = inner_count(skip_from, skip_to, n) + 2;  // a loop has 3+ coarse vertices
          double gap = INFINITY, neighbour_gap = INFINITY;
          for (int m = 0; m < d_.loop_count(); ++m) {
            for (int i = 0; i < loop_size(m); ++i) {
              if (m == l && wrap(i - skip_from, n) < skipped) {
                // A neighbour's point straight in front (across a sharp corner) counts
                // when asked; never one of this piece's own.
                if (!options_.neighbours_across_corners || wrap(i - first, n) <= inner + 1) continue;
                if (planar_angle_between(inward, point(m, i) - middle) > kInFront) continue;
                neighbour_gap = std::min(neighbour_gap, distance(middle, point(m, i)));
                continue;
              }
              gap = std::min(gap, distance(middle, point(m, i)));
            }
          }
          if (chord > kLongerThanGap * std::min(gap, neighbour_gap) && coarsening_[l].split(first, last, 2)) {
            changed = true;
            if (chord <= kLongerThanGap * gap) ++neighbour_splits_;
          }
        }
      }
      if (!changed) break;
    }
  }
  int loop_size(int loop) const { return static_cast<int>(d_.loops[loop].points.size()); }

  std::vector<std::vector<Vec3>> coarse_loops(const CoarsePolygon& polygon) const {
    std::vector<std::vector<Vec3>> loops;
    for (std::size_t l = 0; l < polygon.points.size(); ++l) {
      loops.emplace_back();
      for (int i : polygon.points[l]) loops.back().push_back(point(static_cast<int>(l), i));
    }
    return loops;
  }

  bool all_points(const std::vector<std::set<int>>& coarse) const {
    for (int l = 0; l < d_.loop_count(); ++l) if (static_cast<int>(coarse[l].size()) != loop_size(l)) return false;
    return true;
  }

  std::vector<std::set<int>> every_point() const {
    std::vector<std::set<int>> coarse(d_.loops.size());
    for (int l = 0; l < d_.loop_count(); ++l) for (int i = 0; i < loop_size(l); ++i) coarse[l].insert(i);
    return coarse;
  }

  // Appends to `blocked` the boundary segments that the straight cut between coarse
  // vertices x and y meets away from its own ends (or, when it leaves the domain at
  // an end, the segments there).
  void blocked_segments(const CoarsePolygon& polygon, int x, int y, std::vector<std::pair<int, int>>& blocked) const {
    const std::vector<std::pair<int, int>> obstacles =
        cut_obstacles(d_, polygon.loop(x), polygon.point(x), polygon.loop(y), polygon.point(y));
    blocked.insert(blocked.end(), obstacles.begin(), obstacles.end());
  }

  // The boundary segments (loop, segment) at the ends of the triangles' diagonals
  // (but `skipped`) that a diagonal leaves at less than kMinCutAngle.
  std::vector<std::pair<int, int>> sliver_segments(const CoarsePolygon& polygon, const std::vector<CoarseTriangle>& triangles,
                                                   const std::set<std::pair<int, int>>& skipped) const {
    std::vector<std::pair<int, int>> sliver;
    for (const CoarseTriangle& t : triangles) {
      for (int i = 0; i < 3; ++i) {
        const int x = t[i], y = t[(i + 1) % 3];
        // Each diagonal is a side of two triangles, once in each direction: checked once.
        if (x > y || polygon.is_piece(x, y) || polygon.is_piece(y, x) || skipped.count({x, y})) continue;
        const int lx = polygon.loop(x), ly = polygon.loop(y);
        const int px = polygon.point(x), py = polygon.point(y);
        const Vec3 &a = point(lx, px), &b = point(ly, py);
        for (const auto& [l, p, from, to] : {std::tuple{lx, px, a, b}, std::tuple{ly, py, b, a}}) {
          const int n = loop_size(l);
          const Vec3 &prev = point(l, wrap(p - 1, n)), &next = point(l, wrap(p + 1, n));
          if (planar_angle_between(next - from, to - from) < kMinCutAngle) sliver.push_back({l, p});
          if (planar_angle_between(prev - from, to - from) < kMinCutAngle) sliver.push_back({l, wrap(p - 1, n)});
        }
      }
    }
    return sliver;
  }

  // The diagonals whose slivers are left as they are: those of the pairs merged only
  // for their slivers (splitting a piece there brings the slivers back) and of the
  // square pairs (no cut lies there).
  static std::set<std::pair<int, int>> skipped_diagonals(const Pairing& pairing) {
    std::set<std::pair<int, int>> skipped = pairing.rescued_diagonals;
    skipped.insert(pairing.square_diagonals.begin(), pairing.square_diagonals.end());
    return skipped;
  }

  // Segments of the boundary piece that starts at coarse vertex x.
  int piece_segments(const CoarsePolygon& polygon, int x) const {
    const int l = polygon.loop(x), n = loop_size(l);
    const std::vector<int>& pts = polygon.points[l];
    const int k = polygon.of_id[x].second;
    const int s = wrap(pts[(k + 1) % pts.size()] - pts[k], n);
    return s == 0 ? n : s;
  }

  // Direction in which the side x -> y leaves x: along the boundary for a piece, along
  // the chord for a cut.
  Vec3 leaving(const CoarsePolygon& polygon, int x, int y) const {
    const int l = polygon.loop(x), p = polygon.point(x);
    if (polygon.is_piece(x, y)) return point(l, (p + 1) % loop_size(l)) - point(l, p);
    return point(polygon.loop(y), polygon.point(y)) - point(l, p);
  }
  // Direction in which the side x -> y arrives at y, reversed (from y back along it).
  Vec3 arriving_back(const CoarsePolygon& polygon, int x, int y) const {
    const int l = polygon.loop(y), p = polygon.point(y);
    if (polygon.is_piece(x, y)) return point(l, wrap(p - 1, loop_size(l))) - point(l, p);
    return point(polygon.loop(x), polygon.point(x)) - point(l, p);
  }

  // Smallest sine of the corners of the patch with these coarse corners (counter-
  // clockwise), measured on the real sides; -1 when a corner is outside [lo, pi - lo].
  double corner_quality(const CoarsePolygon& polygon, const std::vector<int>& corners, double lo) const {
    const int k = static_cast<int>(corners.size());
    double worst = 1;
    for (int i = 0; i < k; ++i) {
      const int prev = corners[wrap(i - 1, k)], here = corners[i], next = corners[(i + 1) % k];
      const Vec3 out = leaving(polygon, here, next), back = arriving_back(polygon, prev, here);
      double angle = signed_angle(out, back);
      if (angle < 0) angle += 2 * M_PI;
      if (angle < lo || angle > M_PI - lo) return -1;
      worst = std::min(worst, std::sin(angle));
    }
    return worst;
  }

  // Triangles paired across cuts into four-sided patches where the pair is worth it,
  // the others left as they are.
  Pairing pair_triangles(const CoarsePolygon& polygon, const std::vector<CoarseTriangle>& triangles) const {
    // Triangles across each diagonal, and the pairs worth merging, best first.
    std::map<std::pair<int, int>, std::vector<int>> across;
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
      for (int i = 0; i < 3; ++i) {
        const int x = triangles[t][i], y = triangles[t][(i + 1) % 3];
        if (!polygon.is_piece(x, y)) across[{std::min(x, y), std::max(x, y)}].push_back(t);
      }
    }
    // A triangle with a one-segment boundary piece would have to be meshed with a
    // corner added on a straight side (a 180-degree quad corner): it is paired first,
    // within a wider angle window, so that the piece becomes a side of a four-sided
    // patch (which takes a one-edge side as it is).
    std::vector<char> needs_pair(triangles.size(), 0);
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      for (int i = 0; i < 3; ++i) {
        const int x = triangles[t][i], y = triangles[t][(i + 1) % 3];
        if (polygon.is_piece(x, y) && piece_segments(polygon, x) == 1) needs_pair[t] = 1;
      }
    }
    struct Pair { bool urgent, rescued; double quality; int t1, t2; std::vector<int> corners; std::pair<int, int> diagonal; };
    std::vector<Pair> pairs;
    for (const auto& [edge, users] : across) {
      if (users.size() != 2) continue;
      const CoarseTriangle &t1 = triangles[users[0]], &t2 = triangles[users[1]];
      int i1 = 0;
      while (!(std::min(t1[i1], t1[(i1 + 1) % 3]) == edge.first && std::max(t1[i1], t1[(i1 + 1) % 3]) == edge.second)) ++i1;
      const int a = t1[i1], b = t1[(i1 + 1) % 3], c = t1[(i1 + 2) % 3];
      int d = -1;
      for (int v : t2) if (v != a && v != b) d = v;
      const std::vector<int> corners{a, d, b, c};
      const bool urgent = needs_pair[users[0]] || needs_pair[users[1]];
      double q = corner_quality(polygon, corners, urgent ? kUrgentPairAngleMin : kPairAngleMin);
      bool rescued = false;
      if (q <= 0 && options_.merge_sliver_pairs) {
        // Outside the window, the quadrilateral is still the better patch when its
        // worst corner beats the worst corner of one of its triangles, which a
        // triangle's mesh keeps: two slivers across a thin junction (0.6 degrees)
        // make one band with corners of 19 and 161 degrees.
        const double merged = corner_quality(polygon, corners, 0.0);
        const double alone = std::min(corner_quality(polygon, {t1[0], t1[1], t1[2]}, 0.0),
                                      corner_quality(polygon, {t2[0], t2[1], t2[2]}, 0.0));
        rescued = merged > alone;
        if (rescued) q = merged;
      }
      if (q > 0) pairs.push_back({urgent, rescued, q, users[0], users[1], corners, edge});
    }
    std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) {
      return x.urgent != y.urgent ? x.urgent : x.quality > y.quality;
    });
    std::vector<char> used(triangles.size(), 0);
    Pairing out;
    for (const Pair& p : pairs) {
      if (used[p.t1] || used[p.t2]) continue;
      used[p.t1] = used[p.t2] = 1;
      out.patches.push_back(p.corners);
      if (p.rescued) out.rescued_diagonals.insert(p.diagonal);
      if (options_.keep_square_pairs && p.quality >= kSquarePair) out.square_diagonals.insert(p.diagonal);
    }
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      if (!used[t]) out.patches.push_back({triangles[t][0], triangles[t][1], triangles[t][2]});
    }
    return out;
  }

  void build(const CoarsePolygon& polygon, const Pairing& pairing, FaceDecomposition& out) const {
    const std::vector<std::vector<int>>& patches = pairing.patches;
    out.sliver_pairs = static_cast<int>(pairing.rescued_diagonals.size());
    // Pieces: one per coarse side on a loop.
    std::map<std::pair<int, int>, int> piece_of;
    for (std::size_t l = 0; l < polygon.points.size(); ++l) {
      const std::vector<int>& pts = polygon.points[l];
      for (std::size_t k = 0; k < pts.size(); ++k) {
        piece_of[{static_cast<int>(l), static_cast<int>(k)}] = static_cast<int>(out.pieces.size());
        out.pieces.push_back({static_cast<int>(l), pts[k], pts[(k + 1) % pts.size()]});
      }
    }
    // Sides: pieces, or cuts numbered in order of first use.
    std::map<std::pair<int, int>, int> cut_of;
    for (const std::vector<int>& corners : patches) {
      DomainPatch patch;
      const int k = static_cast<int>(corners.size());
      for (int i = 0; i < k; ++i) {
        const int x = corners[i], y = corners[(i + 1) % k];
        PatchSide side;
        if (polygon.is_piece(x, y)) {
          side.index = piece_of.at(polygon.of_id[x]);
        } else {
          side.is_cut = true;
          const auto key = std::make_pair(std::min(x, y), std::max(x, y));
          auto it = cut_of.find(key);
          if (it == cut_of.end()) {
            const int from = d_.offset(polygon.loop(key.first)) + polygon.point(key.first);
            const int to = d_.offset(polygon.loop(key.second)) + polygon.point(key.second);
            const double length = distance(point(polygon.loop(key.first), polygon.point(key.first)),
                                           point(polygon.loop(key.second), polygon.point(key.second)));
            it = cut_of.emplace(key, static_cast<int>(out.cuts.size())).first;
            out.cuts.push_back({from, to, length});
          }
          side.index = it->second;
          side.reversed = x != key.first;
        }
        patch.sides.push_back(side);
      }
      out.patches.push_back(std::move(patch));
    }
  }

  int corner_splits_ = 0;
  const PlanarDomain& d_;
  const DecompositionOptions options_;
  int neighbour_splits_ = 0;
  int band_crossings_ = 0;
  int reflex_extensions_ = 0;
  int square_pair_slivers_ = 0;
  std::vector<LoopCoarsening> coarsening_;
};

// Even-odd rule: whether p lies inside the closed polygon.
bool inside_loop(const std::vector<Vec3>& loop, const Vec3& p) {
  bool in = false;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const Vec3 &a = loop[i], &b = loop[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

std::string loop_name(int l) { return l == 0 ? "the outer loop" : "hole " + std::to_string(l); }

// A domain the decomposition can work on: finite points, no zero-length segment,
// loops oriented as PlanarDomain says, and no two boundary segments meeting (a loop
// crossing itself, a hole crossing or touching another loop).
}  // namespace

void check_planar_domain(const PlanarDomain& domain) {
  if (domain.loops.empty()) throw InputError("the domain has no loop");
  std::vector<PlanarSegment> segments;
  std::vector<std::pair<int, int>> where;  // (loop, segment)
  for (int l = 0; l < domain.loop_count(); ++l) {
    const std::vector<Vec3>& p = domain.loops[l].points;
    const int n = static_cast<int>(p.size());
    if (n < 3) throw InputError(loop_name(l) + " has fewer than 3 points");
    if (!domain.loops[l].vertex.empty() && static_cast<int>(domain.loops[l].vertex.size()) != n) {
      throw InputError(loop_name(l) + " has " + std::to_string(domain.loops[l].vertex.size()) +
                       " vertex flags for " + std::to_string(n) + " points");
    }
    for (int i = 0; i < n; ++i) {
      if (!std::isfinite(p[i].x) || !std::isfinite(p[i].y)) {
        throw InputError(loop_name(l) + ": point " + std::to_string(i) + " is not a finite number");
      }
      if (same_xy(p[i], p[(i + 1) % n])) {
        throw InputError(loop_name(l) + ": points " + std::to_string(i) + " and " + std::to_string((i + 1) % n) +
                         " coincide");
      }
      segments.push_back({p[i], p[(i + 1) % n]});
      where.push_back({l, i});
    }
    const double area = twice_signed_area(p);
    if (l == 0 ? area <= 0 : area >= 0) {
      throw InputError(loop_name(l) + (l == 0 ? " must run counter-clockwise" : " must run clockwise"));
    }
  }
  const auto crossing = find_segment_crossing(segments, [&](int i, int j) {
    if (where[i].first != where[j].first) return false;
    const int n = static_cast<int>(domain.loops[where[i].first].points.size());
    const int a = where[i].second, b = where[j].second;
    return b == a + 1 || (a == 0 && b == n - 1);
  });
  if (crossing) {
    const auto [l1, s1] = where[crossing->first];
    const auto [l2, s2] = where[crossing->second];
    throw InputError(loop_name(l1) + " segment " + std::to_string(s1) + " meets " +
                     (l1 == l2 ? "its" : loop_name(l2)) + " segment " + std::to_string(s2) +
                     ": the boundary crosses or touches itself");
  }
  // With no crossing, a hole lies wholly inside or outside each other loop.
  for (int l = 1; l < domain.loop_count(); ++l) {
    const Vec3& p = domain.loops[l].points[0];
    if (!inside_loop(domain.loops[0].points, p)) throw InputError(loop_name(l) + " lies outside the outer loop");
    for (int m = 1; m < domain.loop_count(); ++m) {
      if (m != l && inside_loop(domain.loops[m].points, p)) throw InputError(loop_name(l) + " lies inside " + loop_name(m));
    }
  }
}

int piece_segments(const PlanarDomain& domain, const BoundaryPiece& piece) {
  const int n = static_cast<int>(domain.loops[piece.loop].points.size());
  const int s = wrap(piece.last - piece.first, n);
  return s == 0 ? n : s;
}

std::vector<int> side_nodes(const PlanarDomain& domain, const FaceDecomposition& decomposition,
                            const PatchSide& side, const std::vector<std::vector<int>>& cut_nodes) {
  if (side.is_cut) {
    std::vector<int> nodes = cut_nodes[side.index];
    if (side.reversed) std::reverse(nodes.begin(), nodes.end());
    return nodes;
  }
  const BoundaryPiece& piece = decomposition.pieces[side.index];
  const int n = static_cast<int>(domain.loops[piece.loop].points.size());
  const int offset = domain.offset(piece.loop);
  std::vector<int> nodes;
  for (int k = 0; k <= piece_segments(domain, piece); ++k) nodes.push_back(offset + (piece.first + k) % n);
  return nodes;
}

// Each option worth a second mesh, and what the decomposition counts where it acted.
struct VariantOption {
  bool DecompositionOptions::*option;
  int FaceDecomposition::*acted;
};
constexpr VariantOption kVariantOptions[] = {
    {&DecompositionOptions::merge_sliver_pairs, &FaceDecomposition::sliver_pairs},
    {&DecompositionOptions::neighbours_across_corners, &FaceDecomposition::neighbour_splits},
    {&DecompositionOptions::cross_thin_bands, &FaceDecomposition::band_crossings},
    {&DecompositionOptions::extend_reflex_corners, &FaceDecomposition::reflex_extensions},
    {&DecompositionOptions::keep_square_pairs, &FaceDecomposition::square_pair_slivers},
};

std::vector<DecompositionOptions> decomposition_variants(const DecompositionOptions& used, const FaceDecomposition* made) {
  std::vector<DecompositionOptions> variants;
  // Options can act together (a square pair along a reflex corner's extension): with
  // two or more of them, also the decomposition with none, so that the one before any
  // of them stays a candidate.
  DecompositionOptions none = used;
  for (const auto& [option, acted] : kVariantOptions) {
    if (!(used.*option) || (made && made->*acted == 0)) continue;
    variants.emplace_back(used).*option = false;
    none.*option = false;
  }
  if (variants.size() >= 2) variants.push_back(none);
  return variants;
}

FaceDecomposition decompose_domain(const PlanarDomain& domain, const DecompositionOptions& options) {
  check_planar_domain(domain);
  return Decomposer(domain, options).run();
}

}  // namespace tquad
