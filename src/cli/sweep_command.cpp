#include "cli/sweep_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <new>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "cli/cad_input.h"
#include "cli/exit_status.h"
#include "core/elapsed.h"
#include "core/input_error.h"
#include "io/atomic_file_writer.h"
#include "io/hex_writers.h"
#include "occ/read/shape_formats.h"

namespace tquad {

namespace {

std::string fixed(double value, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
  return buffer;
}

SweepOutput sweep_through_module(const SweepCommand& command) {
  const auto entry = reinterpret_cast<SweepCadInputEntry>(cad_module_symbol(kSweepEntryPoint));
  SweepOutput out;
  std::string error;
  switch (entry(command, out, error)) {
    case 0: return out;
    case 2: throw InputError(error);
    case 3: throw std::bad_alloc();
    default: throw std::runtime_error(error);
  }
}

int run(const SweepCommand& command, std::ostream& out, std::ostream& err) {
  if (!is_shape_path(command.input)) {
    throw InputError(command.input + ": tquad sweep takes a CAD shape (.step .stp .iges .igs .brep)");
  }
  if (!is_hex_output(command.output)) {
    throw InputError(command.output + ": a swept mesh is written as .inp, .vtu, .msh or .json");
  }
  check_output_location(command.output);
  const SweepOutput result = sweep_through_module(command);
  for (const std::string& w : result.read_warnings) err << "tquad: warning: " << one_line(w) << "\n";
  for (const RefusedSolid& r : result.mesh.refused) err << "tquad: warning: not swept: " << one_line(r.reason) << "\n";
  for (int f : result.mesh.unshared_faces) {
    err << "tquad: warning: face " << f
        << " is shared by two swept solids whose nodes there differ: the mesh does not conform across it\n";
  }
  const auto write_start = std::chrono::steady_clock::now();
  write_hex_file(command.output, result.mesh);
  const double write_seconds = seconds_since(write_start);
  const std::vector<double>& sj = result.mesh.scaled_jacobian;
  const double worst = sj.empty() ? 0.0 : *std::min_element(sj.begin(), sj.end());
  double sum = 0;
  for (double v : sj) sum += v;
  const double mean = sj.empty() ? 0.0 : sum / static_cast<double>(sj.size());
  if (command.report_json) {
    nlohmann::ordered_json report;
    report["nodes"] = result.mesh.nodes.size();
    report["hexes"] = result.mesh.hexes.size();
    report["edge_size"] = result.size;
    report["quality"] = {{"scaled_jacobian", {{"min", worst}, {"avg", mean}}}};
    nlohmann::ordered_json solids = nlohmann::ordered_json::array();
    for (const SweptSolid& s : result.mesh.solids) {
      nlohmann::ordered_json row = {{"solid", s.solid},   {"source", s.source}, {"target", s.target},
                                    {"layers", s.layers}, {"height", s.height}, {"hexes", s.hex_count}};
      if (s.projected) {
        row["projection"] = "least squares";
      } else if (s.rotation) {
        row["rotation"] = {{"point", {s.point.x, s.point.y, s.point.z}},
                           {"direction", {s.vector.x, s.vector.y, s.vector.z}},
                           {"angle", s.angle}};
      } else {
        row["translation"] = {s.vector.x, s.vector.y, s.vector.z};
      }
      solids.push_back(row);
    }
    report["solids"] = solids;
    nlohmann::ordered_json refused = nlohmann::ordered_json::array();
    for (const RefusedSolid& r : result.mesh.refused) refused.push_back({{"solid", r.solid}, {"reason", r.reason}});
    report["refused_solids"] = refused;
    report["unshared_faces"] = result.mesh.unshared_faces;
    report["read_warnings"] = result.read_warnings;
    report["seconds"] = {{"read", result.read_seconds},
                         {"source", result.source_seconds},
                         {"layers", result.layer_seconds},
                         {"node_sets", result.node_set_seconds},
                         {"write", write_seconds}};
    out << report.dump(2) << "\n";
    return 0;
  }
  out << command.output << ": " << result.mesh.hexes.size() << " hexahedra, " << result.mesh.nodes.size()
      << " nodes; " << result.mesh.solids.size() << " solid(s) swept";
  if (!result.mesh.refused.empty()) out << ", " << result.mesh.refused.size() << " refused";
  out << "; element size " << fixed(result.size, 4) << "; scaled Jacobian min " << fixed(worst, 3) << ", mean "
      << fixed(mean, 3) << "\n";
  for (const SweptSolid& s : result.mesh.solids) {
    out << "  solid " << s.solid << ": ";
    if (s.source >= 0) {
      out << "face " << s.source << " to face " << s.target;
    } else {
      out << "a full turn of its profile about its axis";
    }
    out << ", " << s.layers << " layers, " << s.hex_count << " hexahedra\n";
  }
  return 0;
}

}  // namespace

int run_sweep_command(const SweepCommand& command, std::ostream& out, std::ostream& err) {
  return exit_status_of([&] { return run(command, out, err); }, err, "use a larger --size or fewer --layers");
}

}  // namespace tquad
