#include "occ/face_with_hole.h"

#include <BRepAdaptor_Surface.hxx>

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/input_error.h"

namespace tquad {

namespace {

Vec3 to_vec3(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

double uv_distance(const Vec3& a, const Vec3& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Index of the loop node nearest (in (u, v)) to p, other than `skip`.
int nearest(const std::vector<Vec3>& loop, const Vec3& p, int skip) {
  int best = -1;
  for (int i = 0; i < static_cast<int>(loop.size()); ++i) {
    if (i == skip) continue;
    if (best < 0 || uv_distance(loop[i], p) < uv_distance(loop[best], p)) best = i;
  }
  return best;
}

// One way of cutting the face: bridge 1 joins outer node o1 to rim node i1, bridge 2
// joins o2 to i2, with b1 and b2 edges.
struct Bridges {
  int o1, i1, o2, i2, b1, b2;
};

// The two halves of the face, as loops of face-local node indices (outer nodes, then
// rim nodes, then the bridges' inner nodes), with their (u, v) and corner positions.
struct Half {
  std::vector<int> local;
  std::vector<Vec3> uv;
  std::vector<int> corners;
};

class HoleSplitter {
 public:
  HoleSplitter(const TopoDS_Face& face, const FaceBoundary& b, const std::vector<Vec3>& nodes, double size)
      : face_(face), b_(b), nodes_(nodes), size_(size), outer_(b.uv), rim_(b.holes[0].uv),
        rim_nodes_(b.holes[0].nodes) {
    // A hole's rim runs the other way round from the outer wire.
    if ((signed_uv_area(outer_) > 0) == (signed_uv_area(rim_) > 0)) {
      std::reverse(rim_.begin(), rim_.end());
      std::reverse(rim_nodes_.begin(), rim_nodes_.end());
    }
  }

  FaceMeshResult best_mesh(const MeshOptions& options) {
    const int n_rim = static_cast<int>(rim_.size());
    const int tries = std::min(8, n_rim);
    std::optional<FaceMeshResult> best;
    std::string last_problem = "no bridge could be placed";
    for (int t = 0; t < tries; ++t) {
      Bridges br;
      br.i1 = t * n_rim / tries;
      br.i2 = (br.i1 + n_rim / 2) % n_rim;
      br.o1 = nearest(outer_, rim_[br.i1], -1);
      br.o2 = nearest(outer_, rim_[br.i2], br.o1);
      br.b1 = bridge_edges(br.o1, br.i1);
      br.b2 = bridge_edges(br.o2, br.i2);
      try {
        FaceMeshResult r = mesh_with(br, options);
        if (!best || r.inverted < best->inverted ||
            (r.inverted == best->inverted && r.worst_corner > best->worst_corner)) {
          best = std::move(r);
        }
      } catch (const InputError& e) {
        last_problem = e.what();
      }
    }
    if (!best) throw InputError("no cut from the hole to the outer wire gives two valid regions (" + last_problem + ")");
    return std::move(*best);
  }

 private:
  int bridge_edges(int o, int i) const {
    const double length = distance(nodes_[b_.nodes[o]], nodes_[rim_nodes_[i]]);
    return std::max(1, static_cast<int>(std::lround(length / size_)));
  }

  int outer_count() const { return static_cast<int>(outer_.size()); }
  int rim_count() const { return static_cast<int>(rim_.size()); }

  // Local index of outer node k, rim node k, and bridge inner nodes.
  int outer_local(int k) const { return k; }
  int rim_local(int k) const { return outer_count() + k; }

  // Half from outer node `from_o` forward to `to_o`, across the bridge to rim node
  // `to_i`, forward along the rim to `back_i`, and across the other bridge home.
  // `across` / `home` list the bridges' inner nodes (local indices and (u, v)) in the
  // direction outer -> rim.
  Half half(int from_o, int to_o, int to_i, int back_i, const std::vector<int>& across_local,
            const std::vector<Vec3>& across_uv, const std::vector<int>& home_local,
            const std::vector<Vec3>& home_uv) const {
    Half h;
    h.corners.push_back(0);
    for (int k = from_o;; k = (k + 1) % outer_count()) {
      h.local.push_back(outer_local(k));
      h.uv.push_back(outer_[k]);
      if (k == to_o) break;
    }
    h.corners.push_back(static_cast<int>(h.local.size()) - 1);
    h.local.insert(h.local.end(), across_local.begin(), across_local.end());
    h.uv.insert(h.uv.end(), across_uv.begin(), across_uv.end());
    h.corners.push_back(static_cast<int>(h.local.size()));
    for (int k = to_i;; k = (k + 1) % rim_count()) {
      h.local.push_back(rim_local(k));
      h.uv.push_back(rim_[k]);
      if (k == back_i) break;
    }
    h.corners.push_back(static_cast<int>(h.local.size()) - 1);
    for (int k = static_cast<int>(home_local.size()) - 1; k >= 0; --k) {  // rim -> outer
      h.local.push_back(home_local[k]);
      h.uv.push_back(home_uv[k]);
    }
    return h;
  }

  static int forward_edges(int from, int to, int count) { return ((to - from) % count + count) % count; }

  FaceMeshResult mesh_with(Bridges br, const MeshOptions& options) {
    if (br.o1 == br.o2 || br.i1 == br.i2) throw InputError("bridges meet");
    // Each half needs an even total; the face's total is even, so fixing one half's
    // parity with bridge 2 fixes the other's.
    const int half_a = forward_edges(br.o1, br.o2, outer_count()) + br.b2 +
                       forward_edges(br.i2, br.i1, rim_count()) + br.b1;
    if (half_a % 2 != 0) ++br.b2;

    FaceMeshResult out;
    out.boundary_nodes = b_.nodes;
    out.boundary_nodes.insert(out.boundary_nodes.end(), rim_nodes_.begin(), rim_nodes_.end());
    std::vector<Vec3> param(outer_);
    param.insert(param.end(), rim_.begin(), rim_.end());
    const BRepAdaptor_Surface surface(face_);

    // Bridge inner nodes, from the outer wire to the rim, straight in (u, v).
    auto make_bridge = [&](int o, int i, int edges, std::vector<int>& local, std::vector<Vec3>& uv) {
      for (int k = 1; k < edges; ++k) {
        const double t = static_cast<double>(k) / edges;
        const Vec3 p = (1 - t) * outer_[o] + t * rim_[i];
        local.push_back(static_cast<int>(param.size()));
        uv.push_back(p);
        param.push_back(p);
        out.interior.push_back(to_vec3(surface.Value(p.x, p.y)));
      }
    };
    std::vector<int> bridge1_local, bridge2_local;
    std::vector<Vec3> bridge1_uv, bridge2_uv;
    make_bridge(br.o1, br.i1, br.b1, bridge1_local, bridge1_uv);
    make_bridge(br.o2, br.i2, br.b2, bridge2_local, bridge2_uv);

    const Half a = half(br.o1, br.o2, br.i2, br.i1, bridge2_local, bridge2_uv, bridge1_local, bridge1_uv);
    const Half c = half(br.o2, br.o1, br.i1, br.i2, bridge1_local, bridge1_uv, bridge2_local, bridge2_uv);
    const bool reverse = !runs_counter_clockwise(b_, face_);
    std::string trees;
    for (const Half* h : {&a, &c}) {
      const QuadMesh m = mesh_boundary(BoundaryLoop{h->uv, h->corners}, options);
      // The half's own interior nodes follow everything placed so far.
      std::vector<int> to_local(h->local);
      for (std::size_t k = h->uv.size(); k < m.nodes.size(); ++k) {
        to_local.push_back(static_cast<int>(param.size()));
        param.push_back(m.nodes[k]);
        out.interior.push_back(to_vec3(surface.Value(m.nodes[k].x, m.nodes[k].y)));
      }
      for (Quad q : m.quads) {
        for (NodeId& n : q) n = to_local[n];
        if (reverse) std::swap(q[1], q[3]);
        out.quads.push_back(q);
      }
      trees += (trees.empty() ? "" : ",") + m.template_tree;
    }
    out.template_tree = "H2[" + trees + "]";

    std::vector<Vec3> xyz;
    for (NodeId id : out.boundary_nodes) xyz.push_back(nodes_[id]);
    xyz.insert(xyz.end(), out.interior.begin(), out.interior.end());
    check_on_surface(face_, param, std::nullopt, xyz, out);
    return out;
  }

  const TopoDS_Face& face_;
  const FaceBoundary& b_;
  const std::vector<Vec3>& nodes_;
  double size_;
  std::vector<Vec3> outer_, rim_;
  std::vector<NodeId> rim_nodes_;
};

}  // namespace

FaceMeshResult mesh_face_with_hole(const TopoDS_Face& face, int face_index, const FaceBoundary& boundary,
                                   const std::vector<Vec3>& nodes, double edge_size,
                                   const MeshOptions& options) {
  try {
    return HoleSplitter(face, boundary, nodes, edge_size).best_mesh(options);
  } catch (const InputError& e) {
    throw InputError("face " + std::to_string(face_index) + " (with a hole): " + e.what());
  }
}

}  // namespace tquad
