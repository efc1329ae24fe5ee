// bench_templates: wall time and peak memory of mesh_boundary on one large planar
// four-curve region (a W x H rectangle, evenly spaced points per side, unequal counts
// by default so the templates, not just one mapped grid, do the work).
//
//   bench_templates                          # counts 1000,1200,1400,1300, 5 runs
//   bench_templates --counts 1200,1000,1200,1000 --runs 3 --json
//   bench_templates 1000 1200 1400 1300
//
// Single-threaded. Meshing time covers mesh_boundary only (validation, planning, node
// placement, quads); the quality summary is timed on its own afterwards. Memory is the
// process's peak RSS (getrusage ru_maxrss) after the runs minus its RSS just before the
// first run, divided by the quad count; every run's mesh is freed before the next and
// its pages go back to the system, so every run pays its page faults (a cold call).
#include <sys/resource.h>
#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "core/templates/mesher.h"
#include "core/mesh/quality.h"

namespace tquad {
namespace {

struct BenchOptions {
  std::vector<int> counts{1000, 1200, 1400, 1300};  // bottom, right, top, left
  int runs = 5;
  double width = 1.0;
  double height = 0.8;
  bool json = false;
};

void usage(const char* argv0) {
  std::fprintf(stderr,
               "usage: %s [--counts a,b,c,d | a b c d] [--runs N] [--width W] [--height H] "
               "[--json]\n"
               "  counts: segments per side in loop order (bottom, right, top, left);\n"
               "  their sum must be even. Default 1000,1200,1400,1300, 5 runs, 1.0 x 0.8.\n",
               argv0);
}

bool parse_int(const char* text, int& out) {
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || value < 1 || value > 100000000) return false;
  out = static_cast<int>(value);
  return true;
}

bool parse_double(const char* text, double& out) {
  char* end = nullptr;
  out = std::strtod(text, &end);
  return end != text && *end == '\0' && out > 0;
}

bool parse_counts(const std::string& text, std::vector<int>& counts) {
  counts.clear();
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    int value = 0;
    if (!parse_int(text.substr(start, comma - start).c_str(), value)) return false;
    counts.push_back(value);
    start = comma + 1;
  }
  return counts.size() == 4;
}

// Returns nullopt (after printing why) on bad arguments.
std::optional<BenchOptions> parse_args(int argc, char** argv) {
  BenchOptions options;
  std::vector<int> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    bool ok = true;
    if (arg == "--json") {
      options.json = true;
    } else if (arg == "--counts" && has_value) {
      ok = parse_counts(argv[++i], options.counts);
    } else if (arg == "--runs" && has_value) {
      ok = parse_int(argv[++i], options.runs);
    } else if (arg == "--width" && has_value) {
      ok = parse_double(argv[++i], options.width);
    } else if (arg == "--height" && has_value) {
      ok = parse_double(argv[++i], options.height);
    } else if (arg == "-h" || arg == "--help") {
      usage(argv[0]);
      return std::nullopt;
    } else {
      int value = 0;
      ok = parse_int(arg.c_str(), value);
      positional.push_back(value);
    }
    if (!ok) {
      std::fprintf(stderr, "bad argument: %s\n", arg.c_str());
      usage(argv[0]);
      return std::nullopt;
    }
  }
  if (!positional.empty()) {
    if (positional.size() != 4) {
      std::fprintf(stderr, "give four counts, got %zu\n", positional.size());
      return std::nullopt;
    }
    options.counts = positional;
  }
  long long total = 0;
  for (int c : options.counts) total += c;
  if (total % 2 != 0) {
    std::fprintf(stderr, "the counts sum to %lld, an odd number; a quad mesh needs an even "
                 "number of boundary segments\n", total);
    return std::nullopt;
  }
  return options;
}

// Rectangle [0, W] x [0, H], counter-clockwise from the origin, each side's points
// evenly spaced; corners at the first point of each side.
BoundaryLoop rectangle_loop(const std::vector<int>& counts, double w, double h) {
  const Vec3 corner[4] = {{0, 0, 0}, {w, 0, 0}, {w, h, 0}, {0, h, 0}};
  BoundaryLoop loop;
  loop.points.reserve(static_cast<std::size_t>(counts[0]) + counts[1] + counts[2] + counts[3]);
  for (int side = 0; side < 4; ++side) {
    loop.corners.push_back(static_cast<int>(loop.points.size()));
    const Vec3 a = corner[side], b = corner[(side + 1) % 4];
    const int n = counts[side];
    for (int i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / n;
      loop.points.push_back((1.0 - t) * a + t * b);
    }
  }
  return loop;
}

// Current resident set size in bytes (Linux /proc/self/statm); -1 when unavailable.
long long current_rss_bytes() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return -1;
  long long pages_total = 0, pages_resident = 0;
  const int got = std::fscanf(f, "%lld %lld", &pages_total, &pages_resident);
  std::fclose(f);
  if (got != 2) return -1;
  return pages_resident * static_cast<long long>(sysconf(_SC_PAGESIZE));
}

// Peak resident set size so far in bytes (ru_maxrss is in KiB on Linux).
long long peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<long long>(usage.ru_maxrss) * 1024;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Result {
  std::string tree;
  long long quads = 0, nodes = 0;
  std::vector<double> times;
  double best = 0, median = 0;
  long long rss_before = 0, peak_before = 0, peak_first = 0, peak_all = 0;
  long long payload_bytes = 0;  // capacity of the output vectors (nodes, quads, cuts)
  double quality_seconds = 0;
  QualitySummary quality;
};

Result run(const BenchOptions& options) {
  const BoundaryLoop loop = rectangle_loop(options.counts, options.width, options.height);
  Result r;
  // Baseline: the current RSS (not the peak so far), so that any earlier transient
  // would make the reported delta larger, never smaller.
  r.rss_before = current_rss_bytes();
  r.peak_before = peak_rss_bytes();
  if (r.rss_before < 0) r.rss_before = r.peak_before;

  for (int i = 0; i < options.runs; ++i) {
    const auto start = std::chrono::steady_clock::now();
    QuadMesh mesh = mesh_boundary(loop);
    r.times.push_back(seconds_since(start));
    if (i == 0) {
      r.peak_first = peak_rss_bytes();
      r.tree = mesh.template_tree;
      r.quads = static_cast<long long>(mesh.quads.size());
      r.nodes = static_cast<long long>(mesh.nodes.size());
      r.payload_bytes = static_cast<long long>(mesh.nodes.capacity() * sizeof(Vec3) +
                                               mesh.quads.capacity() * sizeof(Quad));
      for (const auto& cut : mesh.subregion_cuts) {
        r.payload_bytes += static_cast<long long>(cut.capacity() * sizeof(NodeId));
      }
    }
    if (i + 1 == options.runs) {
      r.peak_all = peak_rss_bytes();  // before the quality pass, which allocates nothing big
      const auto start_quality = std::chrono::steady_clock::now();
      r.quality = summarize_quality(mesh, Vec3{0, 0, 1});
      r.quality_seconds = seconds_since(start_quality);
    }
  }  // each run's mesh is destroyed here, before the next run starts
  std::vector<double> sorted = r.times;
  std::sort(sorted.begin(), sorted.end());
  r.best = sorted.front();
  const std::size_t n = sorted.size();
  r.median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  return r;
}

std::string counts_text(const std::vector<int>& counts) {
  std::string text;
  for (int c : counts) text += (text.empty() ? "" : ",") + std::to_string(c);
  return text;
}

void print_table(const BenchOptions& o, const Result& r) {
  const double per_quad = static_cast<double>(r.peak_all - r.rss_before) / r.quads;
  const double per_quad_first = static_cast<double>(r.peak_first - r.rss_before) / r.quads;
  const double mib = 1024.0 * 1024.0;
  std::printf("TemplateQuad bench: %g x %g rectangle, counts %s (bottom,right,top,left), "
              "%d runs, 1 thread\n", o.width, o.height, counts_text(o.counts).c_str(), o.runs);
  std::printf("  %-26s %s\n", "template tree", r.tree.c_str());
  std::printf("  %-26s %lld\n", "quads", r.quads);
  std::printf("  %-26s %lld\n", "nodes", r.nodes);
  std::printf("  %-26s %.4f s\n", "mesh time first (cold)", r.times.front());
  std::printf("  %-26s %.4f s\n", "mesh time best", r.best);
  std::printf("  %-26s %.4f s\n", "mesh time median", r.median);
  std::printf("  %-26s", "mesh times");
  for (double t : r.times) std::printf(" %.4f", t);
  std::printf(" s\n");
  std::printf("  %-26s %.3f M quads/s\n", "throughput (best)", r.quads / r.best / 1e6);
  std::printf("  %-26s %.3f M quads/s\n", "throughput (median)", r.quads / r.median / 1e6);
  std::printf("  %-26s %.1f MiB\n", "RSS before first run", r.rss_before / mib);
  std::printf("  %-26s %.1f MiB (after run 1: %.1f MiB)\n", "peak RSS (ru_maxrss)",
              r.peak_all / mib, r.peak_first / mib);
  std::printf("  %-26s %.1f bytes/quad (after run 1: %.1f)\n", "peak RSS delta", per_quad,
              per_quad_first);
  std::printf("  %-26s %.1f bytes/quad (nodes %zu B, quads %zu B each)\n",
              "output vectors (capacity)", static_cast<double>(r.payload_bytes) / r.quads,
              sizeof(Vec3), sizeof(Quad));
  std::printf("  %-26s %.4f s (not in mesh time)\n", "quality summary time", r.quality_seconds);
  std::printf("  %-26s min %.4f avg %.4f; scaled Jacobian min %.4f; inverted %lld\n",
              "Lee-Lo quality", r.quality.lee_lo.min, r.quality.lee_lo.avg,
              r.quality.scaled_jacobian.min, r.quality.inverted);
  std::printf("  %-26s >= 10 M quads/s, <= 64 bytes/quad (reported, not asserted)\n",
              "targets");
}

void print_json(const BenchOptions& o, const Result& r) {
  // Plain printf keeps the bench free of dependencies; the tree string holds only
  // letters, digits, brackets and commas, so it needs no escaping.
  std::printf("{\"counts\":[%s],\"width\":%g,\"height\":%g,\"runs\":%d,\"threads\":1,"
              "\"template_tree\":\"%s\",\"quads\":%lld,\"nodes\":%lld,"
              "\"first_s\":%.6f,\"best_s\":%.6f,\"median_s\":%.6f,\"times_s\":[",
              counts_text(o.counts).c_str(), o.width, o.height, o.runs, r.tree.c_str(),
              r.quads, r.nodes, r.times.front(), r.best, r.median);
  for (std::size_t i = 0; i < r.times.size(); ++i) {
    std::printf("%s%.6f", i ? "," : "", r.times[i]);
  }
  std::printf("],\"quads_per_s_best\":%.1f,\"quads_per_s_median\":%.1f,"
              "\"rss_before_bytes\":%lld,\"peak_rss_bytes\":%lld,\"peak_rss_first_run_bytes\":%lld,"
              "\"bytes_per_quad\":%.2f,\"bytes_per_quad_first_run\":%.2f,"
              "\"payload_bytes_per_quad\":%.2f,\"quality_s\":%.6f,"
              "\"lee_lo_min\":%.6f,\"lee_lo_avg\":%.6f,\"scaled_jacobian_min\":%.6f,"
              "\"inverted\":%lld}\n",
              r.quads / r.best, r.quads / r.median, r.rss_before, r.peak_all, r.peak_first,
              static_cast<double>(r.peak_all - r.rss_before) / r.quads,
              static_cast<double>(r.peak_first - r.rss_before) / r.quads,
              static_cast<double>(r.payload_bytes) / r.quads, r.quality_seconds,
              r.quality.lee_lo.min, r.quality.lee_lo.avg, r.quality.scaled_jacobian.min,
              r.quality.inverted);
}

}  // namespace
}  // namespace tquad

int main(int argc, char** argv) {
  const auto options = tquad::parse_args(argc, argv);
  if (!options) return 2;
#if defined(__GLIBC__)
  // A fixed mmap threshold turns off glibc's dynamic one, which after the first free
  // would serve meshes under 32 MiB from already-faulted heap pages: runs would then
  // be "warm" or "cold" depending on the mesh size. With it every run maps fresh pages
  // and returns them on free, like a one-shot call, and the peak RSS stays honest.
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
  try {
    const tquad::Result result = tquad::run(*options);
    if (options->json) {
      tquad::print_json(*options, result);
    } else {
      tquad::print_table(*options, result);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_templates: %s\n", e.what());
    return 1;
  }
  return 0;
}
