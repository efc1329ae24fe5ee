#include "cli/mesh_command.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <new>
#include <optional>
#include <stdexcept>

#include "core/input_error.h"
#include "core/mesh_validation.h"
#include "core/planar_self_intersection.h"
#include "core/quality.h"
#include "io/boundary_json_reader.h"
#include "io/mesh_json_writer.h"
#include "io/report_json.h"
#include "io/svg_writer.h"
#include "io/vtu_writer.h"

namespace tquad {

namespace {

enum class OutputFormat { json, vtu, svg };

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

void check_input_format(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".json") return;
  if (ext == ".step" || ext == ".stp" || ext == ".brep" || ext == ".iges" || ext == ".igs") {
    throw InputError(path + ": CAD input (" + ext +
                     ") is not yet supported in this build; give a .json boundary");
  }
  throw InputError(path + ": unknown input format '" + ext +
                   "'; expected a .json boundary (or .step/.stp/.brep/.iges/.igs, not yet supported)");
}

OutputFormat output_format(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".json") return OutputFormat::json;
  if (ext == ".vtu") return OutputFormat::vtu;
  if (ext == ".svg") return OutputFormat::svg;
  if (ext == ".inp" || ext == ".msh") {
    throw InputError(path + ": output format " + ext + " is not yet supported in this build; use .json, .vtu or .svg");
  }
  throw InputError(path + ": unknown output format '" + ext + "'; use .json, .vtu or .svg");
}

std::string fixed(double value, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
  return buffer;
}

void print_summary(std::ostream& out, const MeshCommand& command, const QuadMesh& mesh,
                   const QualitySummary& quality, double seconds) {
  out << command.input << " -> " << command.output << "\n"
      << "  nodes " << mesh.nodes.size() << ", quads " << mesh.quads.size() << "\n"
      << "  template tree " << mesh.template_tree << "\n"
      << "  Lee-Lo min " << fixed(quality.lee_lo.min, 3) << " avg " << fixed(quality.lee_lo.avg, 3)
      << "; scaled Jacobian min " << fixed(quality.scaled_jacobian.min, 3) << " avg "
      << fixed(quality.scaled_jacobian.avg, 3) << "\n"
      << "  inverted " << quality.inverted << ", degenerate " << quality.degenerate << "; time "
      << fixed(seconds, 3) << " s\n";
}

// Messages are one line on stderr.
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

int run(const MeshCommand& command, std::ostream& out, std::ostream& err) {
  check_input_format(command.input);
  const OutputFormat format = output_format(command.output);  // before the work
  std::error_code ec;
  if (std::filesystem::equivalent(command.input, command.output, ec)) {
    throw InputError(command.output + ": the output file is the input file");
  }
  const auto start = std::chrono::steady_clock::now();

  const BoundaryLoop loop = read_boundary_json(command.input);
  QuadMesh mesh;
  try {
    mesh = mesh_boundary(loop, command.options);
  } catch (const InputError& e) {
    // Core messages name the point / segment / curve; add the file.
    throw InputError(command.input + ": " + e.what());
  }
  const int boundary_points = static_cast<int>(loop.points.size());
  const std::string problem = check_disk_mesh(mesh, boundary_points);
  if (!problem.empty()) throw std::logic_error("the mesh of " + command.input + " is invalid: " + problem);

  Vec3 normal;
  const std::optional<Vec3> reference =
      planar_normal(loop.points, normal) ? std::optional<Vec3>(normal) : std::nullopt;
  const QualitySummary quality = summarize_quality(mesh, reference);

  switch (format) {
    case OutputFormat::json: write_mesh_json_file(command.output, mesh); break;
    case OutputFormat::vtu: write_vtu_file(command.output, mesh); break;
    case OutputFormat::svg: {
      SvgOptions svg;
      svg.columns = 1;
      svg.panel_size = 600;
      // A curved patch is seen along its loop's mean normal (Newell's), when it has one.
      const Vec3 newell = newell_normal(loop.points);
      if (reference) svg.view_normal = reference;
      else if (norm(newell) > 0) svg.view_normal = newell;
      const std::string caption = std::to_string(mesh.quads.size()) + " quads: " + mesh.template_tree;
      write_svg_file(command.output, {SvgPanel{&mesh, boundary_points, caption}}, svg);
      break;
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (quality.inverted > 0) {
    err << "tquad: warning: " << quality.inverted << " of " << mesh.quads.size()
        << " quads are inverted (negative scaled Jacobian)\n";
  }
  if (command.report_json) {
    out << mesh_report_json(mesh, quality).dump(2) << "\n";
  } else {
    print_summary(out, command, mesh, quality, seconds);
  }
  out.flush();
  return 0;
}

}  // namespace

int run_mesh_command(const MeshCommand& command, std::ostream& out, std::ostream& err) {
  try {
    return run(command, out, err);
  } catch (const InputError& e) {
    err << "tquad: error: " << one_line(e.what()) << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    err << "tquad: error: internal failure: out of memory (try a smaller --max-quads)\n";
    return 1;
  } catch (const std::exception& e) {
    err << "tquad: error: internal failure: " << one_line(e.what()) << "\n";
    return 1;
  } catch (...) {
    err << "tquad: error: internal failure: unknown exception\n";
    return 1;
  }
}

}  // namespace tquad
