#include "core/decomposition/corner_search.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "core/mesh/quality.h"
#include "core/repair/smoothing.h"

namespace tquad {

namespace {

constexpr double kCandidateTurn = 5.0 * M_PI / 180.0;

// Turn of the loop at point i (radians, >= 0): the angle between the incoming and the
// outgoing segment.
double turn_at(const std::vector<Vec3>& p, int i) {
  const int n = static_cast<int>(p.size());
  const Vec3 a = p[i] - p[(i + n - 1) % n], b = p[(i + 1) % n] - p[i];
  const double la = norm(a), lb = norm(b);
  if (!(la > 0) || !(lb > 0)) return 0;
  return std::acos(std::clamp(dot(a, b) / (la * lb), -1.0, 1.0));
}

// The sets a loop's search meshes: its given corners and sharpest points ranked
// (ranked_corner_sets), the first `limit`.
std::vector<std::vector<int>> candidate_sets(const BoundaryLoop& loop, const std::vector<int>& given, int limit) {
  const int n = static_cast<int>(loop.points.size());
  std::vector<CornerCandidate> candidates;
  for (int i = 0; i < n; ++i) {
    const double turn = turn_at(loop.points, i);
    if (turn >= kCandidateTurn || std::find(given.begin(), given.end(), i) != given.end()) {
      candidates.push_back({i, turn});
    }
  }
  // The given corners always stay candidates, then the sharpest points.
  std::stable_sort(candidates.begin(), candidates.end(), [&](const CornerCandidate& x, const CornerCandidate& y) {
    const bool gx = std::find(given.begin(), given.end(), x.position) != given.end();
    const bool gy = std::find(given.begin(), given.end(), y.position) != given.end();
    return gx != gy ? gx : x.turn > y.turn;
  });
  if (candidates.size() > static_cast<std::size_t>(kBoundarySearchCandidates)) {
    candidates.resize(kBoundarySearchCandidates);
  }
  return ranked_corner_sets(std::move(candidates), {given}, limit);
}

// Inverted quads, then the worst and mean scaled Jacobian: the order of the search.
struct Score {
  long long inverted = 0;
  double worst = -2, mean = -2;
  bool better_than(const Score& o) const {
    if (inverted != o.inverted) return inverted < o.inverted;
    if (std::abs(worst - o.worst) > 1e-9) return worst > o.worst;
    return mean > o.mean;
  }
};

Score score_of(const QuadMesh& mesh, const std::optional<Vec3>& plane_normal) {
  const QualitySummary q = summarize_quality(mesh, plane_normal);
  return {q.inverted, q.scaled_jacobian.min, q.scaled_jacobian.avg};
}

// The first `limit` candidate sets (candidate_sets) meshed in turn, each kept that
// beats the best so far, from `best` (the given corners' mesh and its score). Returns
// how many sets were tried.
struct Searched {
  QuadMesh mesh;
  std::vector<int> corners;
  Score score;
};
int search_corner_sets(const BoundaryLoop& loop, const std::vector<int>& given, const MeshOptions& options,
                       const std::optional<Vec3>& plane_normal, int limit, Searched& best) {
  int tried = 0;
  for (const std::vector<int>& corners : candidate_sets(loop, given, limit)) {
    ++tried;
    try {
      QuadMesh mesh = mesh_boundary(BoundaryLoop{loop.points, corners}, options);
      const Score s = score_of(mesh, plane_normal);
      if (s.better_than(best.score)) best = {std::move(mesh), corners, s};
    } catch (const InputError&) {
      // counts the templates cannot mesh with these curves: one candidate fewer
    }
  }
  return tried;
}

}  // namespace

std::vector<std::vector<int>> ranked_corner_sets(std::vector<CornerCandidate> candidates,
                                                 const std::vector<std::vector<int>>& excluded, int limit) {
  if (candidates.size() > 16) candidates.resize(16);
  std::sort(candidates.begin(), candidates.end(),
            [](const CornerCandidate& x, const CornerCandidate& y) { return x.position < y.position; });
  struct Scored {
    double score;
    std::vector<int> corners;
  };
  std::vector<Scored> sets;
  const int m = static_cast<int>(candidates.size());
  for (unsigned mask = 1; mask < (1u << m); ++mask) {
    const int count = __builtin_popcount(mask);
    if (count < 2 || count > 4) continue;
    const double target_turn = 2 * M_PI / count;  // a regular polygon's turn at each corner
    Scored s{0, {}};
    for (int k = 0; k < m; ++k) {
      if (!(mask & (1u << k))) continue;
      s.corners.push_back(candidates[k].position);
      s.score += std::abs(candidates[k].turn - target_turn);
    }
    if (std::find(excluded.begin(), excluded.end(), s.corners) != excluded.end()) continue;
    sets.push_back(std::move(s));
  }
  std::stable_sort(sets.begin(), sets.end(), [](const Scored& x, const Scored& y) { return x.score < y.score; });
  if (sets.size() > static_cast<std::size_t>(std::max(limit, 0))) sets.resize(std::max(limit, 0));
  std::vector<std::vector<int>> out;
  for (Scored& s : sets) out.push_back(std::move(s.corners));
  return out;
}

CornerSearchResult mesh_boundary_best_corners(const BoundaryLoop& loop, const MeshOptions& options,
                                              const std::optional<Vec3>& plane_normal, bool smooth,
                                              const QuadMesh* given_smoothed) {
  const std::vector<int> given = validate_boundary(loop);
  const int n = static_cast<int>(loop.points.size());
  CornerSearchResult natural{mesh_boundary(loop, options), given, {}};
  Score natural_score = score_of(natural.mesh, plane_normal);
  Searched searched{natural.mesh, given, natural_score};
  const int tried = search_corner_sets(loop, given, options, plane_normal, kBoundarySearchSets, searched);
  CornerSearchResult best{std::move(searched.mesh), std::move(searched.corners), {}};
  Score best_score = searched.score;
  const bool replaced = best.corners != given;
  if (smooth) {
    // The given corners' mesh smoothed, unless the caller has it already.
    const auto smooth_given = [&](QuadMesh& mesh) {
      if (given_smoothed) {
        mesh = *given_smoothed;
      } else {
        smooth_region(mesh, n, plane_normal);
      }
    };
    if (replaced) {
      smooth_region(best.mesh, n, plane_normal);
      smooth_given(natural.mesh);
      natural_score = score_of(natural.mesh, plane_normal);
    } else {
      smooth_given(best.mesh);
    }
    best_score = score_of(best.mesh, plane_normal);
    if (!replaced) natural_score = best_score;
  }
  CornerSearch search;
  search.tried = tried;
  search.natural_worst = natural_score.worst;
  search.natural_mean = natural_score.mean;
  search.changed = replaced && best_score.better_than(natural_score);
  // Without a replacement `best` is the given corners' mesh, the one smoothed.
  const bool keep_best = search.changed || !replaced;
  CornerSearchResult& kept = keep_best ? best : natural;
  const Score& kept_score = keep_best ? best_score : natural_score;
  search.chosen_worst = kept_score.worst;
  search.chosen_mean = kept_score.mean;
  kept.search = search;
  return std::move(kept);
}

QuadMesh mesh_patch_best_corners(const BoundaryLoop& loop, const MeshOptions& options, const QuadMesh& given) {
  const Vec3 up{0, 0, 1};
  Searched best{given, loop.corners, score_of(given, up)};
  if (best.score.inverted == 0 && best.score.worst >= kPatchSearchBelow) return given;
  search_corner_sets(loop, validate_boundary(loop), options, up, kPatchSearchSets, best);
  return std::move(best.mesh);
}

}  // namespace tquad
