// bench_surface: mesh_shape on one large curved B-spline face, and what putting the
// interior nodes on the surface costs compared with one surface evaluation.
//
//   bench_surface                      # about 1,000,000 quads, 3 runs
//   bench_surface --quads 200000 --runs 5 --json
//   bench_surface --size 0.1
//
// The face is built in memory: a cubic B-spline interpolating a 7 x 7 grid over
// [0,100] x [0,60] with z = 10 sin(pi x / 100) sin(pi y / 60) (a smooth bump that is
// zero on the border, so the four natural boundary edges are straight). The edge size
// is sqrt(area / quads) with the area from BRepGProp, since a mapped mesh has about
// area / size^2 quads.
//
// Single-threaded (ShapeMeshOptions::threads = 1). Per run: the wall time of
// mesh_shape and its split from ShapeMeshResult: template_seconds (core templates in
// (u, v)), placement_seconds (interior nodes onto the surface), and the rest ("other":
// edge discretization, parity, boundary loop, inverted-quad check, assembly).
// Then BRepAdaptor_Surface::Value alone is timed on as many (u, v) points as the mesh
// has interior nodes, on a grid over BRepTools::UVBounds, visited in row order (as a
// mapped mesh creates its nodes) and in a shuffled order (no locality); the ratio
// placement per node / one evaluation is the project's target (<= 2). D1 (point and
// derivatives) is timed too: the inverted-quad check evaluates it once per quad.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>

#include "occ/shape_mesher.h"

namespace tquad {
namespace {

struct BenchOptions {
  long long quads = 1'000'000;  // target quad count (sets the size)
  double size = 0;              // > 0: use this edge size instead
  int runs = 3;
  bool json = false;
};

void usage(const char* argv0) {
  std::fprintf(stderr,
               "usage: %s [--quads N | --size H] [--runs N] [--json]\n"
               "  Meshes one B-spline face over [0,100] x [0,60] (z bump up to 10) with about\n"
               "  N quads (default 1000000), single-threaded, N runs (default 3).\n",
               argv0);
}

bool parse_long(const char* text, long long& out) {
  char* end = nullptr;
  const long long value = std::strtoll(text, &end, 10);
  if (end == text || *end != '\0' || value < 1 || value > 1'000'000'000LL) return false;
  out = value;
  return true;
}

std::optional<BenchOptions> parse_args(int argc, char** argv) {
  BenchOptions o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    bool ok = true;
    if (arg == "--json") {
      o.json = true;
    } else if (arg == "--quads" && has_value) {
      ok = parse_long(argv[++i], o.quads);
    } else if (arg == "--runs" && has_value) {
      long long runs = 0;
      ok = parse_long(argv[++i], runs) && runs <= 1000;
      o.runs = static_cast<int>(runs);
    } else if (arg == "--size" && has_value) {
      char* end = nullptr;
      o.size = std::strtod(argv[++i], &end);
      ok = end != argv[i] && *end == '\0' && o.size > 0;
    } else if (arg == "-h" || arg == "--help") {
      usage(argv[0]);
      return std::nullopt;
    } else {
      ok = false;
    }
    if (!ok) {
      std::fprintf(stderr, "bad argument: %s\n", arg.c_str());
      usage(argv[0]);
      return std::nullopt;
    }
  }
  return o;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The bump face: interpolation through a 7 x 7 grid, bounded by its natural edges.
TopoDS_Face bump_face() {
  constexpr int n = 7;
  constexpr double width = 100, height = 60, amplitude = 10;
  const double pi = std::acos(-1.0);
  TColgp_Array2OfPnt grid(1, n, 1, n);
  for (int i = 1; i <= n; ++i) {
    for (int j = 1; j <= n; ++j) {
      const double x = width * (i - 1) / (n - 1), y = height * (j - 1) / (n - 1);
      grid.SetValue(i, j, gp_Pnt(x, y, amplitude * std::sin(pi * x / width) * std::sin(pi * y / height)));
    }
  }
  GeomAPI_PointsToBSplineSurface fit;
  fit.Interpolate(grid);
  if (!fit.IsDone()) throw std::runtime_error("B-spline interpolation failed");
  BRepBuilderAPI_MakeFace make(fit.Surface(), 1e-7);
  if (!make.IsDone()) throw std::runtime_error("BRepBuilderAPI_MakeFace failed");
  return make.Face();
}

// Nodes on the mesh boundary: the ends of edges used by exactly one quad.
long long boundary_node_count(const ShapeMesh& mesh) {
  std::vector<std::pair<NodeId, NodeId>> edges;
  edges.reserve(mesh.quads.size() * 4);
  for (const Quad& q : mesh.quads) {
    for (int k = 0; k < 4; ++k) edges.emplace_back(std::minmax(q[k], q[(k + 1) % 4]));
  }
  std::sort(edges.begin(), edges.end());
  std::vector<char> on_boundary(mesh.nodes.size(), 0);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) on_boundary[edges[i].first] = on_boundary[edges[i].second] = 1;
    i = j;
  }
  long long count = 0;
  for (char b : on_boundary) count += b;
  return count;
}

struct MeshRun {
  double total = 0, templates = 0, placement = 0;
  double other() const { return total - templates - placement; }
};

struct EvalTiming {
  std::vector<double> times;  // seconds per pass over all points
  double per_eval() const { return median(times); }
};

struct Result {
  double area = 0, size = 0;
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  long long quads = 0, nodes = 0, boundary_nodes = 0, interior_nodes = 0;
  std::string tree;
  long long inverted = 0, projected_faces = 0;
  std::vector<MeshRun> runs;
  long long eval_points = 0;
  EvalTiming row_order, shuffled, d1_row_order;
  double checksum = 0;  // keeps the evaluations from being optimized away

  double med(double MeshRun::*field) const {
    std::vector<double> v;
    for (const MeshRun& r : runs) v.push_back(r.*field);
    return median(v);
  }
  double med_other() const {
    std::vector<double> v;
    for (const MeshRun& r : runs) v.push_back(r.other());
    return median(v);
  }
  double placement_per_node() const { return med(&MeshRun::placement) / interior_nodes; }
};

// Times `passes` passes of evaluate(u, v) over the points; returns the seconds per
// evaluation of each pass. evaluate returns a number summed into the checksum.
template <typename Evaluate>
std::vector<double> time_evaluations(const std::vector<std::pair<double, double>>& points, int passes,
                                     double& checksum, const Evaluate& evaluate) {
  std::vector<double> per_eval;
  for (int p = 0; p < passes; ++p) {
    double sum = 0;
    const auto start = std::chrono::steady_clock::now();
    for (const auto& [u, v] : points) sum += evaluate(u, v);
    per_eval.push_back(seconds_since(start) / static_cast<double>(points.size()));
    checksum += sum;
  }
  return per_eval;
}

Result run(const BenchOptions& o) {
  Result r;
  const TopoDS_Face face = bump_face();
  GProp_GProps props;
  BRepGProp::SurfaceProperties(face, props);
  r.area = props.Mass();
  r.size = o.size > 0 ? o.size : std::sqrt(r.area / static_cast<double>(o.quads));

  ShapeMeshOptions options;
  options.size = r.size;
  options.threads = 1;
  for (int i = 0; i < o.runs; ++i) {
    const auto start = std::chrono::steady_clock::now();
    ShapeMeshResult result = mesh_shape(face, options);
    MeshRun m;
    m.total = seconds_since(start);
    m.templates = result.template_seconds;
    m.placement = result.placement_seconds;
    r.runs.push_back(m);
    if (i == 0) {
      const ShapeMesh& mesh = result.mesh;
      r.quads = static_cast<long long>(mesh.quads.size());
      r.nodes = static_cast<long long>(mesh.nodes.size());
      r.boundary_nodes = boundary_node_count(mesh);
      r.interior_nodes = r.nodes - r.boundary_nodes;
      r.tree = mesh.faces.empty() ? "" : mesh.faces[0].template_tree;
      r.inverted = result.inverted;
      r.projected_faces = result.projected_faces;
    }
  }  // the mesh is freed before the next run
  if (r.interior_nodes <= 0) throw std::runtime_error("the mesh has no interior node");

  // A grid of about interior_nodes points strictly inside the parameter bounds, with
  // the face's aspect, in row order; then the same points shuffled (fixed seed).
  BRepTools::UVBounds(face, r.u0, r.u1, r.v0, r.v1);
  const double aspect = 100.0 / 60.0;  // columns per row as in the mesh (the face's 3D aspect)
  const long long nu = std::max(1LL, std::llround(std::sqrt(r.interior_nodes * aspect)));
  const long long nv = std::max(1LL, (r.interior_nodes + nu - 1) / nu);
  std::vector<std::pair<double, double>> points;
  points.reserve(static_cast<std::size_t>(r.interior_nodes));
  for (long long j = 0; j < nv && static_cast<long long>(points.size()) < r.interior_nodes; ++j) {
    for (long long i = 0; i < nu && static_cast<long long>(points.size()) < r.interior_nodes; ++i) {
      points.emplace_back(r.u0 + (r.u1 - r.u0) * (i + 0.5) / nu, r.v0 + (r.v1 - r.v0) * (j + 0.5) / nv);
    }
  }
  r.eval_points = static_cast<long long>(points.size());
  // One adaptor for all passes, as face_mesher makes one per face.
  const BRepAdaptor_Surface surface(face);
  const auto value = [&surface](double u, double v) {
    const gp_Pnt q = surface.Value(u, v);
    return q.X() + q.Y() + q.Z();
  };
  // D1 (point and first derivatives): what the inverted-quad check after placement
  // evaluates once per quad, inside "other".
  const auto d1 = [&surface](double u, double v) {
    gp_Pnt q;
    gp_Vec du, dv;
    surface.D1(u, v, q, du, dv);
    return q.X() + du.X() + dv.Y();
  };
  r.row_order.times = time_evaluations(points, o.runs, r.checksum, value);
  r.d1_row_order.times = time_evaluations(points, o.runs, r.checksum, d1);
  std::mt19937_64 random(12345);
  std::shuffle(points.begin(), points.end(), random);
  r.shuffled.times = time_evaluations(points, o.runs, r.checksum, value);
  return r;
}

void print_table(const BenchOptions& o, const Result& r) {
  const double total = r.med(&MeshRun::total), templates = r.med(&MeshRun::templates),
               placement = r.med(&MeshRun::placement), other = r.med_other();
  const double per_node = r.placement_per_node();
  std::printf("TemplateQuad bench_surface: one B-spline face 100 x 60 (bump 10), %d runs, 1 thread, "
              "medians\n", o.runs);
  std::printf("  %-30s %.2f mm^2; size %.6g (target %lld quads)\n", "surface area", r.area, r.size, o.quads);
  std::printf("  %-30s %s\n", "template tree", r.tree.c_str());
  std::printf("  %-30s %lld\n", "quads", r.quads);
  std::printf("  %-30s %lld (%lld boundary, %lld interior)\n", "nodes", r.nodes, r.boundary_nodes,
              r.interior_nodes);
  std::printf("  %-30s %lld inverted, %lld faces by 3D projection\n", "checks", r.inverted, r.projected_faces);
  std::printf("  %-30s", "mesh_shape wall times");
  for (const MeshRun& m : r.runs) std::printf(" %.3f", m.total);
  std::printf(" s\n");
  std::printf("  %-30s %.3f s\n", "total", total);
  std::printf("  %-30s %.3f s (%.1f%%)\n", "  templates", templates, 100 * templates / total);
  std::printf("  %-30s %.3f s (%.1f%%)\n", "  placement", placement, 100 * placement / total);
  std::printf("  %-30s %.3f s (%.1f%%)\n", "  other", other, 100 * other / total);
  std::printf("  %-30s %.3f M quads/s\n", "whole face", r.quads / total / 1e6);
  std::printf("  %-30s %.1f ns\n", "placement per interior node", per_node * 1e9);
  std::printf("  %-30s %.1f ns row order, %.1f ns shuffled (%lld points, u [%g, %g], v [%g, %g])\n",
              "one Value(u, v)", r.row_order.per_eval() * 1e9, r.shuffled.per_eval() * 1e9, r.eval_points,
              r.u0, r.u1, r.v0, r.v1);
  std::printf("  %-30s %.2f x row order, %.2f x shuffled (target <= 2)\n", "placement / evaluation",
              per_node / r.row_order.per_eval(), per_node / r.shuffled.per_eval());
  std::printf("  %-30s %.1f ns row order; x quads = %.3f s (the inverted check's share of other)\n",
              "one D1(u, v)", r.d1_row_order.per_eval() * 1e9, r.d1_row_order.per_eval() * r.quads);
}

void print_json(const BenchOptions& o, const Result& r) {
  const double total = r.med(&MeshRun::total);
  const double per_node = r.placement_per_node();
  std::printf("{\"runs\":%d,\"threads\":1,\"area\":%.6f,\"size\":%.9g,\"target_quads\":%lld,"
              "\"template_tree\":\"%s\",\"quads\":%lld,\"nodes\":%lld,\"boundary_nodes\":%lld,"
              "\"interior_nodes\":%lld,\"inverted\":%lld,\"projected_faces\":%lld,\"total_s\":[",
              o.runs, r.area, r.size, o.quads, r.tree.c_str(), r.quads, r.nodes, r.boundary_nodes,
              r.interior_nodes, r.inverted, r.projected_faces);
  for (std::size_t i = 0; i < r.runs.size(); ++i) std::printf("%s%.6f", i ? "," : "", r.runs[i].total);
  std::printf("],\"total_median_s\":%.6f,\"template_s\":%.6f,\"placement_s\":%.6f,\"other_s\":%.6f,"
              "\"quads_per_s\":%.1f,\"placement_per_node_ns\":%.3f,\"eval_points\":%lld,"
              "\"eval_row_order_ns\":%.3f,\"eval_shuffled_ns\":%.3f,"
              "\"placement_over_eval_row_order\":%.4f,\"placement_over_eval_shuffled\":%.4f,"
              "\"target_ratio\":2,\"d1_row_order_ns\":%.3f}\n",
              total, r.med(&MeshRun::templates), r.med(&MeshRun::placement), r.med_other(), r.quads / total,
              per_node * 1e9, r.eval_points, r.row_order.per_eval() * 1e9, r.shuffled.per_eval() * 1e9,
              per_node / r.row_order.per_eval(), per_node / r.shuffled.per_eval(),
              r.d1_row_order.per_eval() * 1e9);
}

}  // namespace
}  // namespace tquad

int main(int argc, char** argv) {
  const auto options = tquad::parse_args(argc, argv);
  if (!options) return 2;
  // OpenCASCADE's messages would mix into the table or the JSON line.
  Message::DefaultMessenger()->ChangePrinters().Clear();
  try {
    const tquad::Result result = tquad::run(*options);
    if (options->json) {
      tquad::print_json(*options, result);
    } else {
      tquad::print_table(*options, result);
    }
    // Printed last on stderr so the compiler keeps the timed evaluations.
    if (!std::isfinite(result.checksum)) std::fprintf(stderr, "checksum %g\n", result.checksum);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_surface: %s\n", e.what());
    return 1;
  }
  return 0;
}
