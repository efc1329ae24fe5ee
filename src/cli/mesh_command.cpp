#include "cli/mesh_command.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <functional>
#include <map>
#include <cstdio>
#include <filesystem>
#include <new>
#include <optional>
#include <stdexcept>
#include <utility>

#include "core/input_error.h"
#include "core/boundary_region.h"
#include "core/elapsed.h"
#include "core/mesh/mesh_validation.h"
#include "core/geometry/planar_self_intersection.h"
#include "core/mesh/quality.h"
#include "core/mesh/shape_mesh.h"
#include "core/repair/smoothing.h"
#include "io/atomic_file_writer.h"
#include "io/boundary_json_reader.h"
#include "io/inp_writer.h"
#include "io/mesh_json_writer.h"
#include "io/msh_writer.h"
#include "io/report_json.h"
#include "io/svg_writer.h"
#include "io/vtu_writer.h"
#include "cli/cad_input.h"
#include "cli/exit_status.h"
#include "occ/model/edge_contraction.h"
#include "occ/read/shape_formats.h"

namespace tquad {

namespace {

enum class OutputFormat { json, vtu, inp, msh, svg };

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

enum class InputKind { boundary, shape };

InputKind input_kind(const std::string& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    throw InputError("'" + path + "' is not a regular file");
  }
  if (lower_extension(path) == ".json") return InputKind::boundary;
  if (is_shape_path(path)) return InputKind::shape;
  throw InputError(path + ": unknown input format '" + lower_extension(path) +
                   "'; expected a .json boundary or a CAD shape (.step .stp .iges .igs .brep)");
}

OutputFormat output_format(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".json") return OutputFormat::json;
  if (ext == ".vtu") return OutputFormat::vtu;
  if (ext == ".inp") return OutputFormat::inp;
  if (ext == ".msh") return OutputFormat::msh;
  if (ext == ".svg") return OutputFormat::svg;
  throw InputError(path + ": unknown output format '" + ext + "'; use .json, .vtu, .inp, .msh or .svg");
}

std::string fixed(double value, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
  return buffer;
}

// Two aligned rows: the scaled Jacobian's bins (below 0, then each tenth's lower
// end) and the quads in each.
void print_jacobian_histogram(std::ostream& out, const QualitySummary& quality) {
  const char* bins[kJacobianBins] = {"<0", "0", ".1", ".2", ".3", ".4", ".5", ".6", ".7", ".8", ".9"};
  std::size_t width = 2;
  for (long long count : quality.jacobian_histogram) width = std::max(width, std::to_string(count).size());
  std::string top = "  scaled Jacobian", bottom = "  quads          ";
  for (int b = 0; b < kJacobianBins; ++b) {
    const std::string count = std::to_string(quality.jacobian_histogram[b]);
    top += " " + std::string(width - std::string(bins[b]).size(), ' ') + bins[b];
    bottom += " " + std::string(width - count.size(), ' ') + count;
  }
  out << top << "\n" << bottom << "\n";
}

void print_summary(std::ostream& out, const MeshCommand& command, const ShapeMesh& mesh,
                   const QualitySummary& quality, double seconds, const ShapeMeshResult* shape) {
  out << command.input << " -> " << command.output << "\n"
      << "  nodes " << mesh.nodes.size() << ", quads " << mesh.quads.size()
      << (mesh.second_order() ? " (8-node: corners and edge middles)" : "") << "\n";
  if (shape) {
    out << "  edge size " << shape->size << "; " << shape->changes.size()
        << " edge count(s) changed for even faces";
    for (const IntervalChange& c : shape->changes) {
      out << " (edge " << c.edge << ": " << c.from << " -> " << c.to << ")";
    }
    out << "\n";
  }
  if (shape && command.shape.sew) out << "  sewn: " << shape->sewn_edges << " edge(s) merged into their neighbours\n";
  if (mesh.faces.size() == 1 && mesh.refused_faces.empty()) {
    out << "  template tree " << mesh.faces[0].template_tree << "\n";
    const std::optional<CornerSearch>& search = mesh.faces[0].corner_search;
    if (search && search->after_inverted) {
      out << "  the given corners left an inverted quad (scaled Jacobian " << fixed(search->natural_worst, 3)
          << "): meshed with other corners (" << fixed(search->chosen_worst, 3) << ")\n";
    }
  } else {
    out << "  faces " << mesh.faces.size() << " meshed, " << mesh.refused_faces.size() << " refused";
    if (shape && !shape->absorbed_strips.empty()) {
      out << ", " << shape->absorbed_strips.size() << " absorbed (strips under " << kContractedEdgeRatio
          << " of the size wide, no quads of their own:";
      for (const AbsorbedStrip& strip : shape->absorbed_strips) out << " " << strip.face;
      out << ")";
    }
    out << "\n";
    if (command.verbose) {
      for (const FaceMesh& f : mesh.faces) {
        out << "  face " << f.face << ": " << f.quad_count << " quads, template tree " << f.template_tree << "\n";
      }
    } else {
      out << "  (-v lists each face's quads and template tree)\n";
    }
    for (const RefusedFace& f : mesh.refused_faces) {
      out << "  face " << f.face << " refused (" << refusal_code_name(f.code) << "): " << one_line(f.reason) << "\n";
    }
  }
  out << "  Lee-Lo min " << fixed(quality.lee_lo.min, 3) << " avg " << fixed(quality.lee_lo.avg, 3)
      << "; scaled Jacobian min " << fixed(quality.scaled_jacobian.min, 3) << " avg "
      << fixed(quality.scaled_jacobian.avg, 3) << "\n"
      << "  inverted " << quality.inverted << ", degenerate " << quality.degenerate << ", collapsed " << quality.collapsed << "; time "
      << fixed(seconds, 3) << " s\n";
  print_jacobian_histogram(out, quality);
}

// The boundary path: one region, face 0; also drawn as SVG on request. Its stages'
// wall times go to `stage_seconds`.
ShapeMesh mesh_boundary_input(const MeshCommand& command, OutputFormat format, QualitySummary& quality,
                              std::map<std::string, double>& stage_seconds) {
  const auto reading = std::chrono::steady_clock::now();
  const BoundaryLoop loop = read_boundary_json(command.input);
  stage_seconds["read"] = seconds_since(reading);
  bool best_corners = false;
  for (const std::string& spec : command.corners) {
    if (spec != "best") {
      throw InputError("--corners '" + spec + "': a boundary file's corners are its \"corners\" list; only "
                       "--corners best applies to it");
    }
    best_corners = true;
  }
  const int boundary_points = static_cast<int>(loop.points.size());
  Vec3 normal;
  const std::optional<Vec3> reference =
      planar_normal(loop.points, normal) ? std::optional<Vec3>(normal) : std::nullopt;
  BoundaryRegionMesh region;
  try {
    region = mesh_boundary_region(loop, command.options, reference, command.shape.smooth, best_corners);
  } catch (const InputError& e) {
    // Core messages name the point / segment / curve; add the file.
    throw InputError(command.input + ": " + e.what());
  }
  for (const auto& [stage, seconds] : region.stage_seconds) stage_seconds[stage] += seconds;
  const QuadMesh& mesh = region.mesh;
  if (format == OutputFormat::svg) {
    // The figure draws the template tree's cuts, which only the QuadMesh carries.
    const auto drawing = std::chrono::steady_clock::now();
    SvgOptions svg;
    svg.columns = 1;
    svg.panel_size = 600;
    // A curved patch is seen along its loop's mean normal (Newell's), when it has one.
    const Vec3 newell = newell_normal(loop.points);
    if (reference) svg.view_normal = reference;
    else if (norm(newell) > 0) svg.view_normal = newell;
    const std::string caption = std::to_string(mesh.quads.size()) + " quads: " + mesh.template_tree;
    write_svg_file(command.output, {SvgPanel{&mesh, boundary_points, caption}}, svg);
    stage_seconds["write"] = seconds_since(drawing);
  }
  quality = region.summary;
  // The file writers and the report take a shape's mesh: a boundary input is face 0.
  return boundary_shape_mesh(std::move(region));
}

int run(const MeshCommand& command, std::ostream& out, std::ostream& err) {
  const InputKind kind = input_kind(command.input);
  const OutputFormat format = output_format(command.output);  // before the work
  if (command.shape.order == 2) {
    if (kind == InputKind::boundary) {
      throw InputError(command.input + ": --order 2 needs a CAD input: a boundary file has no curve or surface "
                       "for the mid-edge nodes");
    }
    if (format == OutputFormat::svg) {
      throw InputError(command.output + ": second-order quads are written as .vtu, .inp, .msh or .json");
    }
  }
  check_output_location(command.output);
  std::error_code ec;
  if (std::filesystem::equivalent(command.input, command.output, ec)) {
    throw InputError(command.output + ": the output file is the input file");
  }
  const auto start = std::chrono::steady_clock::now();

  QualitySummary quality;
  ShapeMeshResult shape_result;
  std::vector<std::string> read_warnings;
  ShapeMesh shape;
  if (kind == InputKind::boundary) {
    shape = mesh_boundary_input(command, format, quality, shape_result.stage_seconds);
  } else {
    if (format == OutputFormat::svg) {
      throw InputError(command.output + ": SVG output draws boundary regions only; use .vtu, .inp, .msh or .json");
    }
    // Every (selected) face, conforming across shared edges (cad_input.h).
    CadInputMesh cad = mesh_cad_input(command, err);
    shape_result = std::move(cad.result);
    shape = std::move(shape_result.mesh);
    quality = cad.quality;
    read_warnings = std::move(cad.read_warnings);
  }
  const auto writing = std::chrono::steady_clock::now();
  switch (format) {
    case OutputFormat::json: write_mesh_json_file(command.output, shape); break;
    case OutputFormat::vtu: write_vtu_file(command.output, shape); break;
    case OutputFormat::inp: write_inp_file(command.output, shape); break;
    case OutputFormat::msh: write_msh_file(command.output, shape); break;
    case OutputFormat::svg: break;  // written with the boundary mesh
  }
  if (format != OutputFormat::svg) shape_result.stage_seconds["write"] = seconds_since(writing);
  const double seconds = seconds_since(start);

  if (quality.inverted > 0) {
    err << "tquad: warning: " << quality.inverted << " of " << shape.quads.size()
        << " quads are inverted (negative scaled Jacobian)\n";
  }
  // As unfit for analysis as an inverted quad, and as easy to miss in a histogram:
  // a boundary point far off a unit circle (fuzzed) gave a mesh of such quads only,
  // with exit 0 and nothing said.
  if (quality.degenerate > 0) {
    err << "tquad: warning: " << quality.degenerate << " of " << shape.quads.size()
        << " quads are degenerate (a corner's scaled Jacobian within 1e-6 of 0: an angle of 0 or 180 degrees)\n";
  }
  // A collapsed quad's corners can all be sound (quality.h): it is counted and named
  // by face. Of CAD input only a face kept by --allow-inverted has any.
  const std::vector<std::pair<int, long long>> collapsed_faces =
      kind == InputKind::shape && quality.collapsed > 0 ? collapsed_quads_per_face(shape)
                                                        : std::vector<std::pair<int, long long>>{};
  if (quality.collapsed > 0) {
    err << "tquad: warning: " << quality.collapsed << " of " << shape.quads.size()
        << " quads are collapsed (a corner's Jacobian under 1/1000 of another's: a triangle in effect)";
    std::string faces;
    for (const auto& [face, count] : collapsed_faces) {
      faces += (faces.empty() ? "" : ", ") + std::to_string(face) + " (" + std::to_string(count) + ")";
    }
    if (!faces.empty()) err << ", in faces " << faces;
    err << "\n";
  }
  for (const std::string& w : read_warnings) err << "tquad: warning: " << one_line(w) << "\n";
  if (!shape_result.bad_quad_faces.empty()) {
    long long bad = 0;
    std::string faces;
    for (const auto& [face, count] : shape_result.bad_quad_faces) {
      bad += count;
      faces += (faces.empty() ? "" : ", ") + std::to_string(face);
    }
    err << "tquad: warning: " << bad << " of " << shape.quads.size()
        << " quads are inverted, degenerate, folded or collapsed (kept by --allow-inverted), in faces " << faces
        << "\n";
  }
  for (const RefusedFace& f : shape.refused_faces) {
    err << "tquad: warning: refused " << one_line(f.reason) << "\n";
  }
  if (!shape_result.unsewn_edges.empty()) {
    const UnsewnEdgePair& first = shape_result.unsewn_edges.front();
    err << "tquad: warning: " << shape_result.unsewn_edges.size()
        << " pair(s) of edges lie on each other without being shared (the file's faces are not sewn there, "
        << "first: edges " << first.first << " and " << first.second
        << "): the mesh is not connected along them (--report json lists them"
        << (command.shape.sew ? "" : "; --sew joins them") << ")\n";
  }
  if (kind == InputKind::shape && shape_result.diagonal > 0 && shape_result.size > shape_result.diagonal) {
    err << "tquad: warning: the size " << shape_result.size << " is larger than the shape, "
        << shape_result.diagonal << " across: each edge gets the fewest segments its curvature and faces allow\n";
  }
  if (!shape_result.orientation_conflicts.empty()) {
    const auto& first = shape_result.orientation_conflicts.front();
    err << "tquad: warning: " << shape_result.orientation_conflicts.size()
        << " pair(s) of faces meet with normals that cannot agree (a one-sided shell, or solids whose faces "
        << "disagree; first: faces " << first.first << " and " << first.second
        << "): a shell element's top and bottom swap there (--report json lists them)\n";
  }
  if (command.report_json) {
    nlohmann::ordered_json report = mesh_report_json(shape, quality);
    report["stage_seconds"] = shape_result.stage_seconds;
    if (kind == InputKind::shape) {
      report["nodes_per_quad"] = shape.nodes_per_element();  // 4, or 8 at --order 2
      if (shape.second_order()) report["straightened_mid_nodes"] = shape_result.straightened_mid_nodes;
      report["edge_size"] = shape_result.size;
      report["shape_diagonal"] = shape_result.diagonal;
      report["refinement_rounds"] = shape_result.refinement_rounds;
      report["refused_per_round"] = shape_result.refused_per_round;
      report["kept_round"] = shape_result.kept_round;
      report["higher_mean_faces"] = shape_result.higher_mean_faces;
      report["off_surface_quads"] = shape_result.off_surface;
      nlohmann::ordered_json bad_faces = nlohmann::ordered_json::array();
      for (const auto& [face, count] : shape_result.bad_quad_faces) bad_faces.push_back({{"face", face}, {"quads", count}});
      report["bad_quad_faces"] = bad_faces;
      nlohmann::ordered_json collapsed = nlohmann::ordered_json::array();
      for (const auto& [face, count] : collapsed_faces) collapsed.push_back({{"face", face}, {"quads", count}});
      report["collapsed_quad_faces"] = collapsed;
      report["read_warnings"] = read_warnings;
      // Inside "mesh faces", summed over the faces (all threads): every candidate
      // route of each face before smoothing, then smoothing the chosen mesh.
      report["face_seconds"] = {{"meshing", shape_result.meshing_seconds},
                                {"smoothing", shape_result.smoothing_seconds}};
      report["interval_chains"] = {{"chains", shape_result.interval_chains},
                                   {"edges", shape_result.chained_edges},
                                   {"balanced_bands", shape_result.balanced_bands},
                                   {"balanced_rings", shape_result.balanced_rings},
                                   {"aligned_bands", shape_result.aligned_bands},
                                   {"quartered_pole_rims", shape_result.quartered_pole_rims}};
      nlohmann::ordered_json changes = nlohmann::ordered_json::array();
      for (const IntervalChange& c : shape_result.changes) {
        changes.push_back({{"edge", c.edge}, {"from", c.from}, {"to", c.to}});
      }
      report["changed_edges"] = changes;
      report["contracted_edges"] = shape_result.contracted_edges;
      nlohmann::ordered_json absorbed = nlohmann::ordered_json::array();
      for (const AbsorbedStrip& strip : shape_result.absorbed_strips) {
        absorbed.push_back({{"face", strip.face}, {"width", strip.width}, {"kept_edge", strip.kept},
                            {"merged_edge", strip.merged}});
      }
      report["absorbed_faces"] = absorbed;
      nlohmann::ordered_json unsewn = nlohmann::ordered_json::array();
      for (const UnsewnEdgePair& p : shape_result.unsewn_edges) unsewn.push_back({p.first, p.second});
      report["unsewn_edge_pairs"] = unsewn;
      report["turned_faces"] = shape_result.turned_faces;
      nlohmann::ordered_json conflicts = nlohmann::ordered_json::array();
      for (const auto& [a, b] : shape_result.orientation_conflicts) conflicts.push_back({a, b});
      report["orientation_conflicts"] = conflicts;
      if (command.shape.sew) report["sewn_edges"] = shape_result.sewn_edges;
    }
    // Reasons of refused faces may come from other libraries: never fail on bad UTF-8.
    out << report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  } else {
    print_summary(out, command, shape, quality, seconds, kind == InputKind::shape ? &shape_result : nullptr);
  }
  out.flush();
  return 0;
}

}  // namespace

int run_mesh_command(const MeshCommand& command, std::ostream& out, std::ostream& err) {
  return exit_status_of([&] { return run(command, out, err); }, err, "try a smaller --max-quads");
}

}  // namespace tquad
