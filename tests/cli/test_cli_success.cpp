// Successful runs: each output format, the JSON report, the human summary, --help,
// and the shipped example boundaries.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "boundary_generators.h"
#include "cli_test_support.h"

namespace tquad::cli_test {
namespace {

using nlohmann::json;

// A plate whose opposite curves differ (12/16 and 20/10: template T2) with
// coordinates that have no short decimal form, to test bit-exact output.
std::vector<Vec3> plate(std::vector<int>& corners) {
  auto points = straight_loop({{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {0, 2, 0}}, {12, 20, 16, 10}, corners);
  for (Vec3& p : points) p = {p.x * std::sqrt(2.0) + 0.1, p.y / 3.0 - 1e-7, 1.0 / 3.0};
  return points;
}

// A curved 3D patch: the octant of the unit sphere (three curves).
std::vector<Vec3> sphere_octant(std::vector<int>& corners) {
  const Vec3 ends[3][2] = {{{1, 0, 0}, {0, 1, 0}}, {{0, 1, 0}, {0, 0, 1}}, {{0, 0, 1}, {1, 0, 0}}};
  const int counts[3] = {10, 8, 6};
  std::vector<Vec3> points;
  corners.clear();
  for (int c = 0; c < 3; ++c) {
    corners.push_back(static_cast<int>(points.size()));
    for (int j = 0; j < counts[c]; ++j) {
      const double t = 0.5 * M_PI * j / counts[c];
      points.push_back(std::cos(t) * ends[c][0] + std::sin(t) * ends[c][1]);
    }
  }
  return points;
}

void expect_quality_stats(const json& stats, double lowest) {
  for (const char* key : {"min", "avg", "max", "std"}) {
    ASSERT_TRUE(stats.contains(key)) << key;
    ASSERT_TRUE(stats[key].is_number()) << key;
  }
  EXPECT_GE(stats["min"].get<double>(), lowest);
  EXPECT_LE(stats["min"].get<double>(), stats["avg"].get<double>());
  EXPECT_LE(stats["avg"].get<double>(), stats["max"].get<double>());
  EXPECT_LE(stats["max"].get<double>(), 1.0 + 1e-12);
  EXPECT_GE(stats["std"].get<double>(), 0.0);
}

class Success : public CliTest {};

TEST_F(Success, JsonOutputIsBitExactOnTheBoundaryAndMatchesTheReport) {
  std::vector<int> corners;
  const auto points = plate(corners);
  const std::string input = boundary_file("plate.json", points, corners);
  const RunResult r = run_tquad({"mesh", input, "-o", path("plate_mesh.json"), "--report", "json"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_EQ(files(), (std::vector<std::string>{"plate.json", "plate_mesh.json"}));

  const json mesh = json::parse(read_text(path("plate_mesh.json")));
  const json report = json::parse(r.out);  // stdout is the JSON object only
  ASSERT_TRUE(mesh["nodes"].is_array());
  ASSERT_GE(mesh["nodes"].size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const json& p = mesh["nodes"][i];
    // Bit-exact: == on doubles on purpose.
    EXPECT_EQ(p[0].get<double>(), points[i].x) << "node " << i;
    EXPECT_EQ(p[1].get<double>(), points[i].y) << "node " << i;
    EXPECT_EQ(p[2].get<double>(), points[i].z) << "node " << i;
  }
  const std::size_t quads = mesh["quads"].size();
  const std::size_t nodes = mesh["nodes"].size();
  EXPECT_EQ(report["quads"].get<std::size_t>(), quads);
  EXPECT_EQ(report["nodes"].get<std::size_t>(), nodes);
  EXPECT_EQ(nodes, 1 + quads + points.size() / 2);  // V = 1 + F + E/2 for a disk
  for (const json& q : mesh["quads"]) {
    ASSERT_EQ(q.size(), 4u);
    for (const json& id : q) {
      EXPECT_GE(id.get<long long>(), 0);
      EXPECT_LT(id.get<long long>(), static_cast<long long>(nodes));
    }
  }
  ASSERT_EQ(mesh["faces"].size(), 1u);
  EXPECT_EQ(mesh["faces"][0]["face"], 0);
  EXPECT_EQ(mesh["faces"][0]["quads"], json::array({0, quads}));
  EXPECT_EQ(mesh["faces"][0]["template_tree"], report["faces"][0]["template_tree"]);
  EXPECT_EQ(report["faces"][0]["template_tree"].get<std::string>().rfind("T2", 0), 0u);
}

TEST_F(Success, ReportJsonHasEveryField) {
  std::vector<int> corners;
  const std::string input = boundary_file("plate.json", plate(corners), corners);
  const RunResult r = run_tquad({"mesh", input, "-o", path("plate.vtu"), "--report", "json"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json report = json::parse(r.out);
  for (const char* key : {"nodes", "quads", "triangles", "quality", "faces", "refused_faces"}) {
    EXPECT_TRUE(report.contains(key)) << key;
  }
  EXPECT_EQ(report["triangles"], 0);
  EXPECT_GT(report["quads"].get<long long>(), 0);
  const json& quality = report["quality"];
  expect_quality_stats(quality["lee_lo"], 0.0);
  expect_quality_stats(quality["scaled_jacobian"], 0.0);
  EXPECT_EQ(quality["inverted"], 0);
  EXPECT_EQ(quality["degenerate"], 0);
  ASSERT_EQ(report["faces"].size(), 1u);
  EXPECT_EQ(report["faces"][0]["face"], 0);
  EXPECT_EQ(report["faces"][0]["template_tree"], "T2[T0,T0,T1[T0,T0,T0,T0]]");
  EXPECT_TRUE(report["refused_faces"].is_array());
  EXPECT_TRUE(report["refused_faces"].empty());
}

TEST_F(Success, ReportTimesEveryStageOfTheBoundaryRoute) {
  // Smoothed (the default) the check is part of "smooth"; unsmoothed it is a stage.
  std::vector<int> corners;
  const std::string input = boundary_file("plate.json", plate(corners), corners);
  const std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> routes = {
      {{}, {"read", "mesh", "smooth", "quality", "write"}},
      {{"--no-smooth"}, {"read", "mesh", "check", "quality", "write"}}};
  for (const auto& [extra, stages] : routes) {
    std::vector<std::string> args = {"mesh", input, "-o", path("plate.vtu"), "--report", "json"};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_tquad(args);
    ASSERT_EQ(r.exit_status, 0) << r.err;
    const json report = json::parse(r.out);
    ASSERT_TRUE(report["stage_seconds"].is_object()) << r.out;
    EXPECT_EQ(report["stage_seconds"].size(), stages.size()) << report["stage_seconds"].dump();
    for (const std::string& stage : stages) {
      ASSERT_TRUE(report["stage_seconds"].contains(stage)) << stage << " in " << report["stage_seconds"].dump();
      EXPECT_GE(report["stage_seconds"][stage].get<double>(), 0.0) << stage;
    }
  }
}

// Reads the appended raw binary of our .vtu: per DataArray a UInt64 byte count and
// the bytes, in the order of the tags.
TEST_F(Success, VtuOutputIsAValidAppendedBinaryUnstructuredGrid) {
  std::vector<int> corners;
  const auto points = plate(corners);
  const std::string input = boundary_file("plate.json", points, corners);
  const RunResult r = run_tquad({"mesh", input, "-o", path("plate.vtu"), "--report", "json"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json report = json::parse(r.out);
  const auto nodes = report["nodes"].get<std::uint64_t>();
  const auto quads = report["quads"].get<std::uint64_t>();

  const std::string vtu = read_text(path("plate.vtu"));
  EXPECT_EQ(vtu.rfind("<?xml", 0), 0u);
  EXPECT_NE(vtu.find("type=\"UnstructuredGrid\""), std::string::npos);
  EXPECT_NE(vtu.find("NumberOfPoints=\"" + std::to_string(nodes) + "\""), std::string::npos);
  EXPECT_NE(vtu.find("NumberOfCells=\"" + std::to_string(quads) + "\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"face\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"scaled_jacobian\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"lee_lo\""), std::string::npos);
  const std::string marker = "<AppendedData encoding=\"raw\">";
  std::size_t at = vtu.find(marker);
  ASSERT_NE(at, std::string::npos);
  at = vtu.find('_', at) + 1;
  // Points, connectivity, offsets, types; cell data face, scaled_jacobian, lee_lo.
  const std::uint64_t expected_bytes[] = {24 * nodes, 16 * quads, 8 * quads, quads, 4 * quads, 8 * quads, 8 * quads};
  std::vector<std::string> blocks;
  for (std::uint64_t expected : expected_bytes) {
    std::uint64_t bytes = 0;
    ASSERT_LE(at + 8, vtu.size());
    std::memcpy(&bytes, vtu.data() + at, 8);
    ASSERT_EQ(bytes, expected);
    blocks.push_back(vtu.substr(at + 8, bytes));
    at += 8 + bytes;
  }
  EXPECT_EQ(vtu.substr(at), "\n  </AppendedData>\n</VTKFile>\n");
  for (std::size_t i = 0; i < points.size(); ++i) {
    double xyz[3];
    std::memcpy(xyz, blocks[0].data() + 24 * i, 24);
    EXPECT_EQ(xyz[0], points[i].x);
    EXPECT_EQ(xyz[1], points[i].y);
    EXPECT_EQ(xyz[2], points[i].z);
  }
  for (std::uint64_t k = 0; k < quads; ++k) {
    std::int64_t offset = 0;
    std::memcpy(&offset, blocks[2].data() + 8 * k, 8);
    EXPECT_EQ(offset, static_cast<std::int64_t>(4 * (k + 1)));
    EXPECT_EQ(blocks[3][k], 9);  // VTK_QUAD
  }
  // The quality arrays: their minimum is the report's.
  for (const auto& [block, name] : {std::pair{5, "scaled_jacobian"}, std::pair{6, "lee_lo"}}) {
    double lowest = 2;
    for (std::uint64_t k = 0; k < quads; ++k) {
      double value = 0;
      std::memcpy(&value, blocks[block].data() + 8 * k, 8);
      lowest = std::min(lowest, value);
    }
    EXPECT_DOUBLE_EQ(lowest, report["quality"][name]["min"].get<double>()) << name;
  }
  std::uint64_t binned = 0;
  for (const auto& count : report["quality"]["jacobian_histogram"]) binned += count.get<std::uint64_t>();
  EXPECT_EQ(binned, quads);
}

TEST_F(Success, SvgOutputDrawsTheMeshAndItsTemplateTree) {
  std::vector<int> corners;
  const std::string input = boundary_file("plate.json", plate(corners), corners);
  const RunResult r = run_tquad({"mesh", input, "-o", path("plate.svg")});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const std::string svg = read_text(path("plate.svg"));
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("stroke-width=\"2.2\""), std::string::npos);  // thick cuts / boundary
  EXPECT_NE(svg.find("T2[T0,T0,T1[T0,T0,T0,T0]]"), std::string::npos);
}

TEST_F(Success, HumanSummaryNamesCountsTreeAndQuality) {
  std::vector<int> corners;
  const std::string input = boundary_file("plate.json", plate(corners), corners);
  const RunResult r = run_tquad({"mesh", input, "-o", path("plate.json.out.json")});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  for (const char* part : {"nodes", "quads", "T2[T0,T0,T1[T0,T0,T0,T0]]", "Lee-Lo", "scaled Jacobian", "time"}) {
    EXPECT_NE(r.out.find(part), std::string::npos) << part << " not in: " << r.out;
  }
}

TEST_F(Success, OptionsReachTheMesher) {
  // A triangle (10, 10, 4): T4 with k = 2, T3 when k = 3 (3 * 4 > 10).
  std::vector<int> corners;
  const auto points =
      straight_loop({{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}}, {10, 10, 4}, corners);
  const std::string input = boundary_file("triangle.json", points, corners);
  const RunResult k2 = run_tquad({"mesh", input, "-o", path("k2.json"), "--report", "json"});
  const RunResult k3 = run_tquad({"mesh", input, "-o", path("k3.json"), "--report", "json", "--t4-ratio", "3"});
  ASSERT_EQ(k2.exit_status, 0) << k2.err;
  ASSERT_EQ(k3.exit_status, 0) << k3.err;
  EXPECT_EQ(json::parse(k2.out)["faces"][0]["template_tree"].get<std::string>().rfind("T4", 0), 0u);
  EXPECT_EQ(json::parse(k3.out)["faces"][0]["template_tree"].get<std::string>().rfind("T3", 0), 0u);
}

TEST_F(Success, TwoDimensionalPointsAndOverwrite) {
  const std::string input = path("square2d.json");
  write_text(input,
             "{\"points\": [[0, 0], [0.5, 0], [1, 0], [1, 0.5], [1, 1], [0.5, 1], [0, 1], [0, 0.5]],"
             " \"corners\": [0, 2, 4, 6], \"name\": \"ignored\"}");
  write_text(path("square.json"), "old");
  const RunResult r = run_tquad({"mesh", input, "-o", path("square.json"), "--report", "json"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json mesh = json::parse(read_text(path("square.json")));
  EXPECT_EQ(mesh["quads"].size(), 4u);
  EXPECT_EQ(mesh["nodes"][3], json::array({1.0, 0.5, 0.0}));
}

TEST_F(Success, CurvedPatchUsesPerQuadNormals) {
  std::vector<int> corners;
  const auto points = sphere_octant(corners);
  const std::string input = boundary_file("octant.json", points, corners);
  const RunResult r = run_tquad({"mesh", input, "-o", path("octant.vtu"), "--report", "json"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json report = json::parse(r.out);
  EXPECT_EQ(report["quality"]["inverted"], 0);
  EXPECT_GT(report["quality"]["scaled_jacobian"]["min"].get<double>(), 0.0);
}

TEST_F(Success, GivenCornersThatLeaveAnInvertedQuadGiveWayAndTheReportSaysSo) {
  // Generated case 6535 (counts 6, 34, 2, one side bent in): its given corners keep
  // inverted quads after smoothing; the command meshes it with searched corners.
  const testing::GeneratedCase c = testing::generated_case(6535);
  const std::string input = boundary_file("folded.json", c.loop.points, c.loop.corners);
  const RunResult r = run_tquad({"mesh", input, "-o", path("folded.vtu"), "--report", "json"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json report = json::parse(r.out);
  EXPECT_EQ(report["quality"]["inverted"], 0);
  EXPECT_EQ(report["faces"][0]["corner_search"]["reason"], "inverted");
  EXPECT_LT(report["faces"][0]["corner_search"]["natural"]["min"].get<double>(), 0.0);
  const RunResult text = run_tquad({"mesh", input, "-o", path("folded.vtu")});
  ASSERT_EQ(text.exit_status, 0) << text.err;
  EXPECT_NE(text.out.find("the given corners left an inverted quad"), std::string::npos) << text.out;
}

TEST_F(Success, DegenerateAndCollapsedQuadsAreWarnedOf) {
  // A 40-point unit circle with one point 1.2e8 above it (a fuzzed loop): every quad
  // of its mesh has a scaled Jacobian of 0. It is written, as inverted quads of a
  // boundary file are, and the command says so; a sound loop gets no such warning.
  std::vector<Vec3> circle;
  for (int i = 0; i < 40; ++i) {
    const double angle = 2 * std::acos(-1.0) * i / 40;
    circle.push_back({std::cos(angle), std::sin(angle), 0.0});
  }
  const std::string sound = boundary_file("circle.json", circle, {0, 10, 20, 30});
  const RunResult good = run_tquad({"mesh", sound, "-o", path("circle.vtu")});
  ASSERT_EQ(good.exit_status, 0) << good.err;
  EXPECT_EQ(good.err.find("warning"), std::string::npos) << good.err;
  circle[7].z = 1.2e8;
  const std::string spiked = boundary_file("spiked.json", circle, {0, 10, 20, 30});
  const RunResult r = run_tquad({"mesh", spiked, "-o", path("spiked.vtu"), "--report", "json"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json report = json::parse(r.out);
  const long long degenerate = report["quality"]["degenerate"].get<long long>();
  const long long collapsed = report["quality"]["collapsed"].get<long long>();
  ASSERT_GT(degenerate, 0);
  ASSERT_GT(collapsed, 0);
  const std::string quads = std::to_string(report["quads"].get<long long>());
  EXPECT_NE(r.err.find("warning: " + std::to_string(degenerate) + " of " + quads + " quads are degenerate"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("warning: " + std::to_string(collapsed) + " of " + quads + " quads are collapsed"),
            std::string::npos)
      << r.err;
}

TEST_F(Success, ShippedExampleBoundariesMesh) {
  int examples = 0;
  for (const auto& entry : std::filesystem::directory_iterator(TQUAD_EXAMPLES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    ++examples;
    const std::string out = path(entry.path().stem().string() + ".vtu");
    const RunResult r = run_tquad({"mesh", entry.path().string(), "-o", out, "--report", "json"});
    EXPECT_EQ(r.exit_status, 0) << entry.path() << ": " << r.err;
    if (r.exit_status != 0) continue;
    const json report = json::parse(r.out);
    EXPECT_EQ(report["quality"]["inverted"], 0) << entry.path();
    // The file names say which root template the example is meant to show.
    const std::string stem = entry.path().stem().string();
    const std::string root = "T" + stem.substr(stem.rfind("_t") + 2);
    EXPECT_EQ(report["faces"][0]["template_tree"].get<std::string>().rfind(root, 0), 0u)
        << stem << ": " << report["faces"][0]["template_tree"];
  }
  EXPECT_GE(examples, 4);
}

TEST_F(Success, BestCornersOnTheShippedBoundariesAreNeverWorse) {
  // --corners best on each example (the paper's examples 3 and 4 among them): the
  // report gives the given corners' figures and the chosen ones, the chosen worst at
  // least the given one, and the mesh's quality is the chosen one.
  int changed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(TQUAD_EXAMPLES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    const std::string stem = entry.path().stem().string();
    const RunResult r = run_tquad({"mesh", entry.path().string(), "-o", path(stem + ".vtu"), "--report", "json",
                                   "--corners", "best"});
    ASSERT_EQ(r.exit_status, 0) << stem << ": " << r.err;
    const json report = json::parse(r.out);
    const json& search = report["faces"][0]["corner_search"];
    ASSERT_TRUE(search.is_object()) << stem;
    EXPECT_GT(search["tried"].get<int>(), 0) << stem;
    const double natural = search["natural"]["min"].get<double>(), chosen = search["chosen"]["min"].get<double>();
    EXPECT_GE(chosen, natural - 1e-12) << stem;
    EXPECT_NEAR(report["quality"]["scaled_jacobian"]["min"].get<double>(), chosen, 1e-9) << stem;
    EXPECT_EQ(report["quality"]["inverted"], 0) << stem;
    changed += search["changed"].get<bool>() ? 1 : 0;
  }
  EXPECT_GT(changed, 0) << "no example found better corners";
}

TEST_F(Success, ABoundaryFileTakesOnlyCornersBest) {
  const RunResult r = run_tquad({"mesh", std::string(TQUAD_EXAMPLES_DIR) + "/plate_t2.json", "-o", path("p.vtu"),
                                 "--corners", "0:1,2"});
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.err.find("only --corners best"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(path("p.vtu")));
}

TEST(CommandLineHelp, DocumentsEveryOption) {
  const RunResult top = run_tquad({"--help"});
  EXPECT_EQ(top.exit_status, 0) << top.err;
  EXPECT_NE(top.out.find("mesh"), std::string::npos) << top.out;
  EXPECT_NE(top.out.find("Exit status"), std::string::npos) << top.out;
  const RunResult mesh = run_tquad({"mesh", "--help"});
  EXPECT_EQ(mesh.exit_status, 0) << mesh.err;
  for (const char* option : {"input", "--output", "--report", "--t4-ratio", "--t5-cut-edges", "--max-quads", ".vtu",
                             ".inp", ".msh", ".svg", "CAD"}) {
    EXPECT_NE(mesh.out.find(option), std::string::npos) << option << " not in: " << mesh.out;
  }
  const RunResult version = run_tquad({"--version"});
  EXPECT_EQ(version.exit_status, 0);
  EXPECT_NE(version.out.find("tquad"), std::string::npos);
}

}  // namespace
}  // namespace tquad::cli_test
