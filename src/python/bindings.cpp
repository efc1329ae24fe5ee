// tquad._core: the pybind11 binding of the mesher. The Python package `tquad`
// (tquad/__init__.py) is the public face; this module is private to it.
#include <atomic>
#include <cmath>
#include <map>
#include <optional>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>

#include "core/boundary_region.h"
#include "core/input_error.h"
#include "core/templates/mesher.h"
#include "core/mesh_option_schema.h"
#include "core/mesh/mesh_validation.h"
#include "core/geometry/planar_self_intersection.h"
#include "core/mesh/quality.h"
#include "core/repair/smoothing.h"
#include "io/shape_mesh_check.h"
#include "core/mesh/shape_mesh.h"
#include "occ/shape_mesher.h"
#include "occ/sweep/sweep.h"
#include "occ/read/isolated_reader.h"
#include "occ/read/shape_reader.h"

namespace py = pybind11;

namespace tquad {
namespace {

py::dict stats_dict(const QualityStats& s) {
  py::dict d;
  d["min"] = s.min;
  d["avg"] = s.avg;
  d["max"] = s.max;
  d["std"] = s.std;
  return d;
}

py::dict quality_dict(const QualitySummary& q) {
  py::dict d;
  d["lee_lo"] = stats_dict(q.lee_lo);
  d["scaled_jacobian"] = stats_dict(q.scaled_jacobian);
  d["inverted"] = q.inverted;
  d["degenerate"] = q.degenerate;
  d["collapsed"] = q.collapsed;
  py::list histogram;
  for (long long count : q.jacobian_histogram) histogram.append(count);
  d["jacobian_histogram"] = histogram;
  return d;
}

py::array_t<double> numpy_copy(const std::vector<double>& values) {
  py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

// One refused face as the Python module documents it (tquad/__init__.py, Mesh).
py::dict refused_face_dict(const RefusedFace& f) {
  py::dict d;
  d["face"] = f.face;
  d["code"] = refusal_code_name(f.code);
  d["reason"] = f.reason;
  d["vertices"] = f.vertices;
  return d;
}

// Rows of four node indices (quads, or their edge middles) as an M x 4 int32 array.
py::array_t<std::int32_t> index_rows(const std::vector<Quad>& rows) {
  py::array_t<std::int32_t> array({static_cast<py::ssize_t>(rows.size()), py::ssize_t{4}});
  auto a = array.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    for (int k = 0; k < 4; ++k) a(i, k) = rows[static_cast<std::size_t>(i)][k];
  }
  return array;
}

// Nodes as an N x 3 float64 array (copied once).
py::array_t<double> node_array(const std::vector<Vec3>& points) {
  py::array_t<double> nodes({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  auto n = nodes.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n.shape(0); ++i) {
    n(i, 0) = points[i].x;
    n(i, 1) = points[i].y;
    n(i, 2) = points[i].z;
  }
  return nodes;
}

// The mesh as plain Python data: numpy arrays for nodes and quads (copied once).
py::dict mesh_dict(const ShapeMesh& mesh, const QualitySummary& quality) {
  const py::array_t<double> nodes = node_array(mesh.nodes);
  py::list faces, refused;
  for (const FaceMesh& f : mesh.faces) {
    py::dict d;
    d["face"] = f.face;
    d["template_tree"] = f.template_tree;
    if (!f.route.empty()) d["route"] = f.route;
    d["first_quad"] = f.first_quad;
    d["quad_count"] = f.quad_count;
    if (f.corner_search) {
      const CornerSearch& c = *f.corner_search;
      py::dict search;
      search["tried"] = c.tried;
      search["reason"] = c.after_inverted ? "inverted" : "asked";
      search["changed"] = c.changed;
      search["natural_min"] = c.natural_worst;
      search["natural_mean"] = c.natural_mean;
      search["chosen_min"] = c.chosen_worst;
      search["chosen_mean"] = c.chosen_mean;
      d["corner_search"] = search;
    }
    faces.append(d);
  }
  for (const RefusedFace& f : mesh.refused_faces) refused.append(refused_face_dict(f));
  py::dict out;
  out["nodes"] = nodes;
  out["quads"] = index_rows(mesh.quads);
  out["faces"] = faces;
  out["refused_faces"] = refused;
  out["quality"] = quality_dict(quality);
  out["scaled_jacobian"] = numpy_copy(mesh.scaled_jacobian);
  out["lee_lo"] = numpy_copy(mesh.lee_lo);
  if (mesh.second_order()) out["mid_nodes"] = index_rows(mesh.mid_nodes);
  return out;
}

MeshOptions template_options(int t4_ratio, int t5_cut_edges, long long max_quads) {
  MeshOptions options;
  options.t4_ratio = t4_ratio;
  options.t5_cut_edges = t5_cut_edges;
  options.max_quads = max_quads;
  return options;
}

py::dict mesh_boundary_binding(const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
                               const std::vector<int>& corners, int t4_ratio, int t5_cut_edges,
                               long long max_quads, bool smooth, bool best_corners) {
  if (points.ndim() != 2 || (points.shape(1) != 2 && points.shape(1) != 3)) {
    throw InputError("points must be an N x 3 (or N x 2) array of coordinates");
  }
  BoundaryLoop loop;
  auto p = points.unchecked<2>();
  for (py::ssize_t i = 0; i < p.shape(0); ++i) {
    loop.points.push_back({p(i, 0), p(i, 1), p.shape(1) == 3 ? p(i, 2) : 0.0});
  }
  loop.corners = corners;
  ShapeMesh shape;
  QualitySummary quality;
  {
    py::gil_scoped_release release;
    Vec3 normal;
    const bool planar = planar_normal(loop.points, normal);
    const std::optional<Vec3> plane = planar ? std::optional<Vec3>(normal) : std::nullopt;
    const MeshOptions options = template_options(t4_ratio, t5_cut_edges, max_quads);
    // The same route and final check as the CLI's.
    BoundaryRegionMesh region = mesh_boundary_region(loop, options, plane, smooth, best_corners);
    quality = region.summary;
    shape = boundary_shape_mesh(std::move(region));
  }
  py::dict out = mesh_dict(shape, quality);
  return out;
}

bool looks_like_brep_text(const std::string& s) {
  return s.find("CASCADE Topology") != std::string::npos || s.rfind("DBRep_DrawableShape", 0) == 0;
}

// The shape of BREP text (FreeCAD's exportBrepToString) or of a file, read in a child
// process: a damaged input must not take the interpreter (FreeCAD) down.
ReadShape read_text_or_file(const std::string& brep_text_or_path, const ReadLimits& limits) {
  return looks_like_brep_text(brep_text_or_path) ? read_brep_text_isolated(brep_text_or_path, limits)
                                                 : read_shape_isolated(brep_text_or_path, limits);
}

// The numbers mesh_shape and sweep_shape take as the command does: InputError
// (ValueError) naming the keyword. A read_timeout of 0 is the default, scaled to the
// input's size (isolated_reader.h).
void check_sizes_and_timeout(double size, double min_size, double read_timeout) {
  if (!(size >= 0) || !std::isfinite(size)) {
    throw InputError("size must be a finite positive number (or 0 for the default), not " + std::to_string(size));
  }
  if (!(min_size >= 0) || !std::isfinite(min_size)) {
    throw InputError("min_size must be a finite number of 0 (no floor) or more, not " + std::to_string(min_size));
  }
  if (read_timeout != 0 && !(read_timeout >= kMinReadSeconds && read_timeout <= kMaxReadSeconds)) {
    throw InputError("read_timeout must be between 0.001 and 1e6 seconds, not " + std::to_string(read_timeout));
  }
}

py::dict mesh_shape_binding(const std::string& brep_text_or_path, double size, const std::vector<int>& faces,
                            const std::map<int, std::vector<int>>& corners, bool keep_going,
                            bool allow_inverted, int threads, int t4_ratio, int t5_cut_edges,
                            long long max_quads, bool smooth, const py::object& progress,
                            double read_timeout, bool best_corners, double min_size, int order, bool sew,
                            const std::vector<std::string>& sizes, int curvature_segments, double growth_rate) {
  ShapeMeshOptions options;
  options.sew = sew;
  for (const std::string& entry : sizes) options.local_sizes.push_back(parse_local_size(entry));
  check_growth_rate(growth_rate);
  options.growth_rate = growth_rate;
  options.curvature_segments = curvature_segments;
  options.order = order;  // checked by mesh_shape (1 or 2)
  options.smooth = smooth;
  options.best_corners = best_corners;
  // The Python progress callable runs with the GIL, one call at a time; returning
  // True, or raising, cancels. Its exception is re-raised once meshing has stopped.
  std::atomic<bool> cancel{false};
  std::optional<py::error_already_set> callback_error;
  options.cancel = &cancel;
  if (!progress.is_none()) {
    options.progress = [&](const MeshProgress& p) {
      py::gil_scoped_acquire gil;
      if (cancel) return;
      try {
        const py::object answer = progress(p.stage, p.done, p.total);
        if (!answer.is_none() && py::bool_(answer)) cancel = true;  // Python's truth
      } catch (py::error_already_set& e) {
        callback_error = std::move(e);
        cancel = true;
      }
    };
  }
  options.size = size;
  options.min_size = min_size;
  options.faces = faces;
  options.corners = corners;
  options.keep_going = keep_going;
  options.allow_inverted = allow_inverted;
  options.threads = threads;
  options.templates = template_options(t4_ratio, t5_cut_edges, max_quads);
  check_sizes_and_timeout(size, min_size, read_timeout);
  ReadLimits limits;
  limits.seconds = read_timeout;
  ShapeMeshResult result;
  QualitySummary quality;
  std::vector<std::string> read_warnings;
  {
    py::gil_scoped_release release;
    const ReadShape read = read_text_or_file(brep_text_or_path, limits);
    read_warnings = read.warnings;
    const TopoDS_Shape& shape = read.shape;
    for (int f : read.invalid_faces) options.damaged_faces[f] = kInvalidFaceReason;
    try {
      result = mesh_shape(shape, options);
    } catch (const MeshCancelled&) {
      if (!callback_error) throw;
    }
    if (callback_error) {
      py::gil_scoped_acquire gil;
      callback_error->restore();
      throw py::error_already_set();
    }
    // The check every writer of the CLI runs before a byte is written; a mesh failing
    // it is the mesher's fault (RuntimeError), not the input's.
    try {
      check_shape_mesh(result.mesh);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(std::string("internal failure: ") + e.what());
    }
    quality = measure_mesh_quality(result.mesh, std::nullopt);
  }
  py::dict out = mesh_dict(result.mesh, quality);
  out["edge_size"] = result.size;
  out["shape_diagonal"] = result.diagonal;
  py::list changes;
  for (const IntervalChange& c : result.changes) {
    py::dict d;
    d["edge"] = c.edge;
    d["from"] = c.from;
    d["to"] = c.to;
    changes.append(d);
  }
  out["changed_edges"] = changes;
  py::list unsewn;
  for (const UnsewnEdgePair& p : result.unsewn_edges) unsewn.append(py::make_tuple(p.first, p.second));
  out["unsewn_edge_pairs"] = unsewn;
  out["sewn_edges"] = result.sewn_edges;
  py::list turned;
  for (int f : result.turned_faces) turned.append(f);
  out["turned_faces"] = turned;
  py::list conflicts;
  for (const auto& [a, b] : result.orientation_conflicts) conflicts.append(py::make_tuple(a, b));
  out["orientation_conflicts"] = conflicts;
  py::list contracted;
  for (int e : result.contracted_edges) contracted.append(e);
  out["contracted_edges"] = contracted;
  py::list absorbed;
  for (const AbsorbedStrip& strip : result.absorbed_strips) {
    py::dict d;
    d["face"] = strip.face;
    d["width"] = strip.width;
    d["kept_edge"] = strip.kept;
    d["merged_edge"] = strip.merged;
    absorbed.append(d);
  }
  out["absorbed_faces"] = absorbed;
  py::list bad_faces;
  for (const auto& [face, count] : result.bad_quad_faces) {
    py::dict d;
    d["face"] = face;
    d["quads"] = count;
    bad_faces.append(d);
  }
  out["bad_quad_faces"] = bad_faces;
  py::list collapsed_faces;
  if (quality.collapsed > 0) {
    for (const auto& [face, count] : collapsed_quads_per_face(result.mesh)) {
      py::dict d;
      d["face"] = face;
      d["quads"] = count;
      collapsed_faces.append(d);
    }
  }
  out["collapsed_quad_faces"] = collapsed_faces;
  out["read_warnings"] = read_warnings;
  return out;
}

// Solids swept into hexahedra (occ/sweep/sweep.h), as plain Python data.
py::dict sweep_shape_binding(const std::string& brep_text_or_path, double size, double min_size, int layers,
                             int source, int target, bool keep_going, bool smooth, int threads,
                             double read_timeout, int order) {
  check_sizes_and_timeout(size, min_size, read_timeout);
  SweepOptions options;
  options.face.size = size;
  options.face.min_size = min_size;
  options.face.smooth = smooth;
  options.face.threads = threads;
  options.face.order = order;  // checked by mesh_shape (1 or 2)
  options.layers = layers;
  options.source = source;
  options.target = target;
  options.keep_going = keep_going;
  ReadLimits limits;
  limits.seconds = read_timeout;
  SweepResult result;
  std::vector<std::string> read_warnings;
  {
    py::gil_scoped_release release;
    const ReadShape read = read_text_or_file(brep_text_or_path, limits);
    read_warnings = read.warnings;
    for (int f : read.invalid_faces) options.face.damaged_faces[f] = kInvalidFaceReason;
    result = sweep_shape(read.shape, options);
  }
  const HexMesh& mesh = result.mesh;
  const py::array_t<double> nodes = node_array(mesh.nodes);
  const int per = mesh.nodes_per_element();
  py::array_t<std::int32_t> hexes({static_cast<py::ssize_t>(mesh.hexes.size()), py::ssize_t{per}});
  auto h = hexes.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < h.shape(0); ++i) {
    const HexMesh::ElementNodes ids = mesh.element_nodes(static_cast<std::size_t>(i));
    for (int k = 0; k < per; ++k) h(i, k) = ids[k];
  }
  py::list solids, refused;
  for (const SweptSolid& s : mesh.solids) {
    py::dict d;
    d["solid"] = s.solid;
    d["source"] = s.source;
    d["target"] = s.target;
    d["layers"] = s.layers;
    d["height"] = s.height;
    d["first_hex"] = s.first_hex;
    d["hex_count"] = s.hex_count;
    if (s.projected) {
      d["projection"] = "least squares";
    } else if (s.rotation) {
      py::dict turn;
      turn["point"] = py::make_tuple(s.point.x, s.point.y, s.point.z);
      turn["direction"] = py::make_tuple(s.vector.x, s.vector.y, s.vector.z);
      turn["angle"] = s.angle;
      d["rotation"] = turn;
    } else {
      d["translation"] = py::make_tuple(s.vector.x, s.vector.y, s.vector.z);
    }
    solids.append(d);
  }
  for (const RefusedSolid& r : mesh.refused) {
    py::dict d;
    d["solid"] = r.solid;
    d["reason"] = r.reason;
    refused.append(d);
  }
  // A face two solids share is one set.
  std::map<int, std::vector<std::int32_t>> merged;
  for (const auto& [face, ids] : mesh.face_nodes) merged[face].insert(merged[face].end(), ids.begin(), ids.end());
  py::dict face_nodes;
  for (auto& [face, ids] : merged) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    py::array_t<std::int32_t> a(static_cast<py::ssize_t>(ids.size()));
    std::copy(ids.begin(), ids.end(), a.mutable_data());
    face_nodes[py::int_(face)] = a;
  }
  py::dict out;
  out["nodes"] = nodes;
  out["hexes"] = hexes;
  out["scaled_jacobian"] = numpy_copy(mesh.scaled_jacobian);
  out["jacobian_ratio"] = mesh.second_order() ? py::object(numpy_copy(mesh.jacobian_ratio)) : py::none();
  out["solids"] = solids;
  out["refused_solids"] = refused;
  py::list unshared;
  for (int f : mesh.unshared_faces) unshared.append(f);
  out["unshared_faces"] = unshared;
  out["face_nodes"] = face_nodes;
  out["edge_size"] = result.size;
  out["read_warnings"] = read_warnings;
  return out;
}

}  // namespace
}  // namespace tquad

PYBIND11_MODULE(_core, m) {
  m.doc() = "Private binding of the TemplateQuad mesher; use the `tquad` package.";
  // Wrong input is the caller's to fix: ValueError with the engine's message.
  py::register_exception<tquad::InputError>(m, "InputError", PyExc_ValueError);
  // Cancelled from the progress callback: nothing is returned.
  py::register_exception<tquad::MeshCancelled>(m, "Cancelled", PyExc_RuntimeError);
  // Faces refused without keep_going: a ValueError that also carries the records, as
  // Mesh.refused_faces would list them (translators registered later are tried first).
  static py::exception<tquad::FacesRefusedError> faces_refused(m, "FacesRefused", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const tquad::FacesRefusedError& e) {
      py::list records;
      for (const tquad::RefusedFace& f : e.refused()) records.append(tquad::refused_face_dict(f));
      const py::object error =
          py::handle(faces_refused.ptr())(std::string(e.what()) + " (keep_going=True meshes the other faces)");
      error.attr("refused_faces") = records;
      PyErr_SetObject(faces_refused.ptr(), error.ptr());
    }
  });
  m.def("mesh_boundary", &tquad::mesh_boundary_binding, py::arg("points"), py::arg("corners"),
        py::arg("t4_ratio"), py::arg("t5_cut_edges"), py::arg("max_quads"), py::arg("smooth"),
        py::arg("best_corners"));
  // The options schema (core/mesh_option_schema.h): the package's docstring and the
  // tests read it.
  m.def("mesh_option_schema", [] {
    py::list rows;
    for (const tquad::MeshOptionField& f : tquad::mesh_option_schema()) {
      py::dict row;
      row["name"] = f.name;
      row["flag"] = f.flag;
      row["freecad"] = f.freecad;
      row["type"] = f.type;
      row["default"] = f.python_default;
      row["help"] = f.help;
      rows.append(row);
    }
    return rows;
  });
  m.def("sweep_shape", &tquad::sweep_shape_binding, py::arg("brep_text_or_path"), py::arg("size"),
        py::arg("min_size"), py::arg("layers"), py::arg("source"), py::arg("target"), py::arg("keep_going"),
        py::arg("smooth"), py::arg("threads"), py::arg("read_timeout"), py::arg("order"));
  m.def("mesh_shape", &tquad::mesh_shape_binding, py::arg("brep_text_or_path"), py::arg("size"),
        py::arg("faces"), py::arg("corners"), py::arg("keep_going"), py::arg("allow_inverted"),
        py::arg("threads"), py::arg("t4_ratio"), py::arg("t5_cut_edges"), py::arg("max_quads"), py::arg("smooth"),
        py::arg("progress"), py::arg("read_timeout"), py::arg("best_corners"), py::arg("min_size"), py::arg("order"),
        py::arg("sew"), py::arg("sizes"), py::arg("curvature_segments"), py::arg("growth_rate"));
}
