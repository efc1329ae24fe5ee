#include "occ/face/surface_smoothing.h"
#include "core/cancellation.h"

#include <BRepAdaptor_Surface.hxx>

#include <algorithm>

#include "core/geometry/box3.h"
#include "core/repair/doublets.h"
#include "core/repair/flat_corner_turns.h"
#include "core/repair/sharp_corner_flips.h"
#include "core/repair/smoothing.h"
#include "occ/model/occ_vec.h"

namespace tquad {

namespace {

// A copy of `mesh` without its per-quad and per-node arrays (quads, interior nodes,
// and what check_on_surface measures), which the caller fills: copying them whole
// took most of the smoothing's time on faces where few nodes move.
// The arrays are moved out for the copy and back, so `source` ends as it was.
FaceMeshResult without_nodes_and_quads(FaceMeshResult& source) {
  std::vector<Quad> quads = std::move(source.quads);
  std::vector<Vec3> interior = std::move(source.interior), param = std::move(source.param),
                    normal = std::move(source.normal);
  std::vector<double> scaled_jacobian = std::move(source.scaled_jacobian);
  FaceMeshResult copy = source;
  source.quads = std::move(quads);
  source.interior = std::move(interior);
  source.param = std::move(param);
  source.normal = std::move(normal);
  source.scaled_jacobian = std::move(scaled_jacobian);
  return copy;
}

// A mesh with its layout changed around boundary corners (flat corners turned, sharp
// ones flipped) replaces the best so far only for a clear gain: a
// worst corner better by kTurnGain (or, below that, doubled), or as good and a better
// mean. A turn changes the layout around the node; elsewhere it can raise the worst
// corner a little and lower the mean more, while the flat corners it is made for gain
// far more (a near-straight corner's scaled Jacobian raised several times over).
constexpr double kTurnGain = 0.05;
bool turned_is_better(const FaceMeshResult& turned, const FaceMeshResult& incumbent) {
  if (turned.bad != incumbent.bad || turned.inverted != incumbent.inverted || turned.collapsed != incumbent.collapsed) {
    return better_face_mesh(turned, incumbent);
  }
  const double gain = turned.worst_corner - incumbent.worst_corner;
  if (gain > 0 && gain >= std::min(kTurnGain, incumbent.worst_corner)) return true;
  return turned.worst_corner >= incumbent.worst_corner &&
         mean_scaled_jacobian(turned) > mean_scaled_jacobian(incumbent);
}

// A changed layout's smoothing moves the nodes of its changed quads and this many
// rings of nodes around them: 3 rings gave a better worst quad than 2, and 5 little
// or nothing more than 3, at about the same smoothing time.
constexpr int kChangeRings = 3;

// The surface normals (of any length: a B-spline face's derivatives' cross product
// can be hundreds long) at unit length, zero where singular, as the layout
// changes' corner measures want them.
std::vector<Vec3> unit_normals(const std::vector<Vec3>& normal) {
  std::vector<Vec3> unit;
  unit.reserve(normal.size());
  for (const Vec3& n : normal) {
    poll_cancellation();
    const double length = norm(n);
    unit.push_back(length > 0 ? (1.0 / length) * n : Vec3{});
  }
  return unit;
}

// The nodes of the quads of `changed` that differ from `before`'s (the layout
// changes replace quads in place: the same count, the others as they were), and
// `rings` rings of nodes around them.
std::vector<bool> around_changed_quads(const std::vector<Quad>& before, const std::vector<Quad>& changed,
                                       std::size_t nodes, int rings) {
  std::vector<bool> around(nodes, false);
  for (std::size_t q = 0; q < changed.size(); ++q) {
    poll_cancellation();
    if (q < before.size() && changed[q] == before[q]) continue;
    for (NodeId n : changed[q]) around[n] = true;
  }
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<bool> grown = around;
    for (const Quad& q : changed) {
      poll_cancellation(2);
      if (std::none_of(q.begin(), q.end(), [&](NodeId n) { return around[n]; })) continue;
      for (NodeId n : q) grown[n] = true;
    }
    around.swap(grown);
  }
  return around;
}

}  // namespace

void smooth_face_mesh(const TopoDS_Face& face, bool has_seam, const std::vector<Vec3>& nodes, FaceMeshResult& mesh,
                      const SmoothingOptions& options, LayoutChanges changes) {
  if ((mesh.used_projection && has_seam) || mesh.interior.empty()) return;
  // Every corner already at good_enough: smooth_mesh would move no node (it starts
  // from the nodes with a corner under it), and there is no doublet (a doublet's
  // node has a corner of 180 degrees or more). Without this return, large mapped
  // faces with every corner good spent time here for nothing.
  if (mesh.worst_corner >= options.good_enough && mesh.collapsed == 0) return;
  const std::size_t fixed = mesh.boundary_nodes.size();
  if (mesh.param.size() != fixed + mesh.interior.size()) return;  // not measured on the surface
  const BRepAdaptor_Surface surface(face);
  const bool reversed = face.Orientation() == TopAbs_REVERSED;
  const auto to_uv = [&](const Vec3& p) { return mesh.polar ? polar_to_uv(*mesh.polar, p) : p; };

  std::vector<Vec3> position;
  position.reserve(mesh.param.size());
  for (NodeId id : mesh.boundary_nodes) position.push_back(nodes[id]);
  position.insert(position.end(), mesh.interior.begin(), mesh.interior.end());
  if (mesh.normal.size() != mesh.param.size()) {  // not those check_on_surface measured
    mesh.normal.clear();
    for (const Vec3& p : mesh.param) {
      poll_cancellation(16);
      mesh.normal.push_back(outer_normal(surface, reversed, to_uv(p)));
    }
  }
  // A node stays inside the box of its face's boundary nodes in the mesh coordinates
  // (the interior of a loop lies within the loop's box): beyond the face a B-spline
  // surface is extrapolated, so a node there lies off the surface the face is cut
  // from, which no corner measure sees (its normal is the extrapolation's).
  const Box3 box = bounding_box(mesh.param.begin(), mesh.param.begin() + static_cast<std::ptrdiff_t>(fixed));
  const Vec3 margin = 1e-6 * box.extent();
  const auto in_boundary_box = [&](const Vec3& p) {
    return p.x >= box.low.x - margin.x && p.x <= box.high.x + margin.x && p.y >= box.low.y - margin.y &&
           p.y <= box.high.y + margin.y;
  };
  const PlaceNode place = [&](int, const Vec3& p, Vec3& at, Vec3& n) {
    if (!in_boundary_box(p)) return false;
    const Vec3 uv = to_uv(p);
    n = outer_normal(surface, reversed, uv, at);
    return norm(n) > 0;
  };
  // Doublets merged where the merged quad is no worse; where some are not, also with
  // every doublet merged and its reflex corner left to the smoothing; and each of
  // these again with the layout changed around boundary corners where the mesh has
  // such corners: flat ones turned (core/repair/flat_corner_turns.h), or lopsided sharp ones
  // flipped (core/repair/sharp_corner_flips.h), each on its own. The best kept. `mesh`
  // stays as it is until the end: each try starts from it.
  std::vector<std::vector<Quad>> layouts{mesh.quads};
  const std::vector<Vec3> unit = unit_normals(mesh.normal);
  // `quads` with its flat lone corners turned, when it has any.
  const auto add_turned = [&](const std::vector<Quad>& quads) {
    if (!has_flat_lone_corner(quads, static_cast<int>(fixed), position, unit)) return;
    std::vector<Quad> turned = quads;
    if (turn_flat_boundary_corners(turned, static_cast<int>(fixed), position, unit) > 0) {
      layouts.push_back(std::move(turned));
    }
  };
  if (changes == LayoutChanges::tried) {
    add_turned(mesh.quads);
    for (FlipDiagonal diagonal : {FlipDiagonal::better_now, FlipDiagonal::other}) {
      std::vector<Quad> flipped = mesh.quads;
      if (flip_lopsided_sharp_corners(flipped, static_cast<int>(fixed), position, unit, diagonal) > 0) {
        layouts.push_back(flipped);
        add_turned(flipped);  // a flip may leave a neighbour alone on a straight boundary
      }
    }
  }
  // A changed layout starts from the nodes where the unchanged one's smoothing left
  // them, when that merged no doublet (the same nodes then), and is smoothed from
  // around its changed quads on (smooth_mesh_near); else it is smoothed whole.
  struct SmoothedNodes {
    std::vector<Vec3> param, position, normal;
  };
  std::optional<SmoothedNodes> unchanged;
  std::optional<FaceMeshResult> best;
  // With every doublet merged (the second round), only the unchanged layout and the
  // changed one kept in the first round, if any, are tried again: trying them all
  // again doubled the smoothing time of decomposed faces.
  std::size_t kept_layout = 0;
  for (bool even_if_worse : {false, true}) {
    int refused_any = 0;
    unchanged.reset();
    for (std::size_t layout = 0; layout < layouts.size(); ++layout) {
      if (even_if_worse && layout > 0 && layout != kept_layout) continue;
      const bool changed = layout > 0;
      const bool near = changed && unchanged;
      std::vector<Vec3> param = near ? unchanged->param : mesh.param;
      std::vector<Vec3> moved = near ? unchanged->position : position;
      std::vector<Vec3> normals = near ? unchanged->normal : mesh.normal;
      std::vector<Quad> quads = layouts[layout];
      int refused = 0;
      const int merged =
          remove_doublets(quads, static_cast<int>(fixed), param, moved, normals, even_if_worse, &refused);
      refused_any = std::max(refused_any, refused);
      const long long moves =
          near && merged == 0
              ? smooth_mesh_near(quads, static_cast<int>(fixed), param, moved, normals, place,
                                 around_changed_quads(layouts[0], quads, param.size(), kChangeRings), options)
                    .moves
              : smooth_mesh(quads, static_cast<int>(fixed), param, moved, normals, place, options).moves;
      if (!changed && merged == 0 && layouts.size() > 1) unchanged = SmoothedNodes{param, moved, normals};
      if (changed || merged > 0 || moves > 0) {
        FaceMeshResult smoothed = without_nodes_and_quads(mesh);
        smoothed.quads = std::move(quads);
        smoothed.interior.assign(moved.begin() + fixed, moved.end());
        check_on_surface(face, surface, param, mesh.polar, moved, std::move(normals), smoothed);
        const FaceMeshResult& incumbent = best ? *best : mesh;
        if (changed ? turned_is_better(smoothed, incumbent) : !better_face_mesh(incumbent, smoothed)) {
          best = std::move(smoothed);
          if (!even_if_worse) kept_layout = layout;
        }
      }
    }
    if (refused_any == 0) break;  // every doublet merged: the second try would be the same
  }
  if (best) mesh = std::move(*best);
}

}  // namespace tquad
