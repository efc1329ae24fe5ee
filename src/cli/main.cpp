// tquad: the command-line front end. Parses the arguments and runs the job in
// run_mesh_command; exit status 0 done, 2 wrong input or usage, 1 internal failure.
#include <climits>
#include <csignal>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>

#ifdef __GLIBC__
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

#include <CLI/CLI.hpp>

#include "cli/mesh_command.h"
#include "cli/sweep_command.h"
#include "core/mesh_option_schema.h"
#include "occ/read/isolated_reader.h"

namespace {

const char* const exit_status_text =
    "Exit status: 0 done; 2 the input or the command line is wrong (stderr says what and\n"
    "where); 1 an internal failure. The output file is written only when the whole mesh\n"
    "succeeded and passed its checks.";

// The help of schema option `name` (core/mesh_option_schema.h), wrapped, after
// "CAD input: " for an option boundary files do not take, and before `syntax`.
std::string option_help(const std::string& name, bool cad_only, const std::string& syntax = "") {
  const std::string text = (cad_only ? "CAD input. " : "") + tquad::mesh_option(name).help;
  return tquad::wrap_text(syntax.empty() ? text : text + " " + syntax, 78);
}

// A length option's check: a finite number over 0, or of 0 or more with `zero_allowed`.
CLI::Validator length_check(const std::string& flag, bool zero_allowed) {
  return CLI::Validator(
      [flag, zero_allowed](std::string& text) -> std::string {
        try {
          std::size_t used = 0;
          const double value = std::stod(text, &used);
          if (used == text.size() && std::isfinite(value) && (value > 0 || (zero_allowed && value == 0))) return "";
        } catch (const std::exception&) {
        }
        return flag + (zero_allowed ? " must be a length of 0 or more" : " must be a positive length") + ", got '" +
               text + "'";
      },
      "", zero_allowed ? "non-negative" : "positive");
}

int run_cli(int argc, char** argv) {
  CLI::App app{"TemplateQuad: all-quadrilateral meshes by hierarchical templates (T0..T5)", "tquad"};
  app.footer(std::string("Examples: tquad mesh plate.json -o plate.vtu --report json\n"
                        "          tquad mesh part.step -o part.inp --size 2 --keep-going\n\n") + exit_status_text);
  app.set_version_flag("--version", "tquad 0.1.0");
  app.require_subcommand(1);

  tquad::MeshCommand command;
  std::string report;
  CLI::App* mesh = app.add_subcommand("mesh", "Mesh a boundary or the faces of a CAD shape into quads");
  mesh->add_option("input", command.input,
                   "Boundary file .json: {\"points\": [[x,y,z] or [x,y], ...], \"corners\": [i, ...]},\n"
                   "a closed loop with an even number of points and 2, 3 or 4 corners;\n"
                   "or a CAD shape (.step .stp .iges .igs .brep): every face of every solid\n"
                   "and shell is meshed, conforming across shared edges.")
      ->type_name("INPUT")
      ->required();
  mesh->add_option("-o,--output", command.output,
                   "Output file; the format follows the extension: .json (mesh JSON), .vtu (VTK\n"
                   "XML, binary), .inp (Abaqus/CalculiX, S4 shells, element set FACE<k> per\n"
                   "face and EALL), .msh (Gmsh 4.1 ASCII), .svg (drawing with subregion boundaries)")
      ->type_name("OUTPUT")
      ->required();
  mesh->add_option("--report", report,
                   "Print a report instead of the summary; 'json' prints one JSON object\n"
                   "(counts, quality, template tree per face, refused faces) on stdout")
      ->type_name("FORMAT")
      ->check(CLI::IsMember({"json"}));
  mesh->add_option("--t4-ratio", command.options.t4_ratio,
                   option_help("t4_ratio", false))
      ->type_name("K")
      ->check(CLI::Range(2, INT_MAX).description(""))
      ->capture_default_str();
  mesh->add_option("--t5-cut-edges", command.options.t5_cut_edges,
                   option_help("t5_cut_edges", false))
      ->type_name("C")
      ->check(CLI::Range(0, INT_MAX).description(""))
      ->capture_default_str();
  mesh->add_option("--max-quads", command.options.max_quads,
                   option_help("max_quads", false))
      ->type_name("N")
      ->check(CLI::Range(1LL, LLONG_MAX).description(""))
      ->capture_default_str();
  mesh->add_option("--size", command.shape.size,
                   option_help("size", true))
      ->type_name("H")
      ->check(length_check("--size", false));
  mesh->add_option("--min-size", command.shape.min_size,
                   option_help("min_size", true))
      ->type_name("H")
      ->check(length_check("--min-size", true));
  mesh->add_option("--faces", command.faces,
                   option_help("faces", true, "For example 0,2,5-7."))
      ->type_name("LIST");
  mesh->add_option("--corners", command.corners,
                   option_help("corners", true,
                               "For example --corners 3:0,4,7,2 (repeat for more faces). Or 'best' (a boundary "
                               "file's loop too): " + tquad::mesh_option("best_corners").help))
      ->type_name("FACE:V1,V2,...");
  mesh->add_option("--size-at", command.sizes_at,
                   option_help("sizes", true, "For example --size-at face3:0.5 (repeat for more)."))
      ->type_name("ENTITY:H");
  mesh->add_option("--curvature-segments", command.shape.curvature_segments, option_help("curvature_segments", true))
      ->type_name("N")
      ->check(CLI::Range(8, 1000).description(""))
      ->capture_default_str();
  mesh->add_option("--growth-rate", command.shape.growth_rate, option_help("growth_rate", true))
      ->type_name("G")
      ->capture_default_str();
  mesh->add_flag("--keep-going", command.shape.keep_going,
                   option_help("keep_going", true, "(exit 2)"));
  mesh->add_flag("--progress", command.progress,
                   option_help("progress", true, "On stderr, the faces in tenths."));
  mesh->add_flag("-v,--verbose", command.verbose,
                 "The summary lists each face's template tree (a shape of one face always shows it;\n"
                 "--report json always has them)");
  mesh->add_option("--read-timeout", command.read.seconds,
                   option_help("read_timeout", true))
      ->type_name("S")
      ->check(CLI::Range(tquad::kMinReadSeconds, tquad::kMaxReadSeconds));
  mesh->add_flag("!--no-smooth", command.shape.smooth,
                   option_help("smooth", false,
                             "On by default; this flag turns it off. A boundary region is smoothed in its "
                             "plane, or on the surface a curved loop's mesh spans."));
  mesh->add_flag("--allow-inverted", command.shape.allow_inverted,
                   option_help("allow_inverted", true));
  mesh->add_flag("--sew", command.shape.sew,
                   option_help("sew", true));
  mesh->add_option("--order", command.shape.order,
                   option_help("order", true, "Order 2 is written to .vtu, .inp (S8R), .msh and .json."))
      ->type_name("1|2")
      ->check(CLI::IsMember({1, 2}).description(""));
  mesh->add_option("--threads", command.shape.threads,
                   option_help("threads", true))
      ->type_name("N")
      ->check(CLI::Range(0, 1024).description(""));
  mesh->footer(exit_status_text);

  tquad::SweepCommand sweep_command;
  std::string sweep_report;
  CLI::App* sweep = app.add_subcommand(
      "sweep", "Sweep the solids of a CAD shape into hexahedra (extrusions; other solids are refused)");
  sweep->add_option("input", sweep_command.input, "A CAD shape (.step .stp .iges .igs .brep) with solids")
      ->type_name("INPUT")
      ->required();
  sweep->add_option("-o,--output", sweep_command.output,
                    "Output file: .inp (CalculiX/Abaqus C3D8, an element set SOLID<k> per solid,\n"
                    "a node set FACE<f> and a surface SFACE<f> per face), .vtu (VTK hexahedra), .msh\n"
                    "(Gmsh 4.1) or .json")
      ->type_name("OUTPUT")
      ->required();
  sweep->add_option("--report", sweep_report, "Print a JSON report instead of the summary")
      ->type_name("FORMAT")
      ->check(CLI::IsMember({"json"}));
  sweep->add_option("--size", sweep_command.sweep.face.size, option_help("size", false))
      ->type_name("H")
      ->check(length_check("--size", false));
  sweep->add_option("--min-size", sweep_command.sweep.face.min_size, option_help("min_size", false))
      ->type_name("H")
      ->check(length_check("--min-size", true));
  sweep->add_option("--layers", sweep_command.sweep.layers,
                    "Hexahedra through each solid, from source to target (default: the solid's\n"
                    "height / H, rounded, at least 1)")
      ->type_name("N")
      ->check(CLI::Range(1, 1000000).description(""));
  CLI::Option* source = sweep->add_option("--source", sweep_command.sweep.source,
                                          "The source face (0-based, as FreeCAD's Shape.Faces order) of the solid\n"
                                          "that holds it; with --target. Default: found per solid")
                            ->type_name("F")
                            ->check(CLI::Range(0, INT_MAX).description(""));
  CLI::Option* target = sweep->add_option("--target", sweep_command.sweep.target, "The target face, with --source")
                            ->type_name("F")
                            ->check(CLI::Range(0, INT_MAX).description(""));
  source->needs(target);
  target->needs(source);
  sweep->add_flag("--keep-going", sweep_command.sweep.keep_going,
                  "Sweep and write the other solids when one is refused, and list the refused\n"
                  "ones; without it a refused solid stops the job (exit 2)");
  sweep->add_option("--order", sweep_command.sweep.face.order,
                    "1: eight-node hexahedra (C3D8); 2: twenty-node (C3D20), the middle of every edge\n"
                    "on the CAD curve or surface it stands for, or on its node's path")
      ->type_name("1|2")
      ->check(CLI::IsMember({1, 2}).description(""));
  sweep->add_flag("!--no-smooth", sweep_command.sweep.face.smooth, option_help("smooth", false,
                  "On by default for the source faces; this flag turns it off."));
  sweep->add_option("--threads", sweep_command.sweep.face.threads, option_help("threads", false))
      ->type_name("N")
      ->check(CLI::Range(0, 1024).description(""));
  sweep->add_option("--read-timeout", sweep_command.read.seconds, option_help("read_timeout", false))
      ->type_name("S")
      ->check(CLI::Range(tquad::kMinReadSeconds, tquad::kMaxReadSeconds));
  sweep->footer(exit_status_text);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    const char* sub = mesh->parsed() ? " mesh" : sweep->parsed() ? " sweep" : "";
    std::cerr << "tquad: error: " << e.what() << " (see 'tquad" << sub << " --help')\n";
    return 2;
  }
  if (sweep->parsed()) {
    sweep_command.report_json = sweep_report == "json";
    return tquad::run_sweep_command(sweep_command, std::cout, std::cerr);
  }
  command.report_json = report == "json";
  return tquad::run_mesh_command(command, std::cout, std::cerr);
}

#ifdef __GLIBC__
// Every allocation of this process's main thread comes from one heap that the kernel
// may back by 2 MB pages (transparent huge pages, where the system leaves them to
// madvise, as Debian does) and that is never given back. A million-quad mesh's
// arrays are otherwise fresh 4 KB pages each time, and on a virtual machine each
// first touch is a trap: on large meshes those page faults took a large share of the
// run's time, which this saves for a slightly higher peak memory. The heap is grown
// once by kHeapReserve, untouched (no memory used until written), and advised; past
// it, it grows in 4 KB pages as before.
// Not under AddressSanitizer (its allocator is its own, and the reserve would cost its
// shadow memory), nor where the system commits memory strictly (the reserve would
// count against the limit).
void use_huge_page_heap() {
#if defined(__SANITIZE_ADDRESS__)
  return;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return;
#endif
#endif
  if (std::ifstream("/proc/sys/vm/overcommit_memory").get() == '2') return;
  constexpr std::size_t kHeapReserve = std::size_t{1} << 30;
  constexpr std::uintptr_t kHugePage = std::uintptr_t{1} << 21;
  mallopt(M_MMAP_MAX, 0);              // large arrays too from the heap, not their own mappings
  mallopt(M_TRIM_THRESHOLD, INT_MAX);  // and freed memory stays in it, for the next array
  const auto start = reinterpret_cast<std::uintptr_t>(sbrk(0));
  void* reserve = std::malloc(kHeapReserve);
  if (reserve == nullptr) return;
  std::free(reserve);
  const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0));
  const std::uintptr_t first = (start + kHugePage - 1) & ~(kHugePage - 1);
  if (end > first) madvise(reinterpret_cast<void*>(first), end - first, MADV_HUGEPAGE);
}
#endif

}  // namespace

int main(int argc, char** argv) {
  // Over a file-size limit (ulimit -f) a write would kill the process by SIGXFSZ and
  // leave the temporary output behind; ignored, the write fails like on a full disk
  // and the writer removes it (atomic_file_writer.h).
  std::signal(SIGXFSZ, SIG_IGN);
#ifdef __GLIBC__
  use_huge_page_heap();
#endif
  try {
    return run_cli(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "tquad: error: internal failure: " << e.what() << "\n";
    return 1;
  } catch (...) {
    std::cerr << "tquad: error: internal failure: unknown exception\n";
    return 1;
  }
}
