// CalculiX solves a shell model on the .inp the CLI writes: a 100 x 40 mm steel plate
// (thickness 1 mm, E = 210000 MPa, nu = 0.3) clamped on x = 0 and pulled with
// F = 1000 N along x on x = 100. The tip moves F L / (E A) (A = width x thickness) up
// to the clamp's local restraint of the lateral contraction (well under 2 %). Skipped
// when `ccx` (Debian calculix-ccx) is not on PATH.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.h"

namespace tquad::cli_test {
namespace {

constexpr double length = 100, width = 40, thickness = 1;
constexpr double young = 210000, poisson = 0.3, force = 1000;

std::string g17(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

// The *NODE lines of the .inp: id -> (x, y, z).
std::map<long long, Vec3> inp_nodes(const std::string& text) {
  std::map<long long, Vec3> nodes;
  std::istringstream in(text);
  bool in_nodes = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("**", 0) == 0) continue;
    if (line.rfind('*', 0) == 0) {
      in_nodes = line.rfind("*NODE", 0) == 0;
      continue;
    }
    if (!in_nodes) continue;
    long long id = 0;
    double x = 0, y = 0, z = 0;
    if (std::sscanf(line.c_str(), "%lld , %lf , %lf , %lf", &id, &x, &y, &z) == 4) nodes[id] = {x, y, z};
    else ADD_FAILURE() << "bad node line: " << line;
  }
  return nodes;
}

// The lines of a *NODE PRINT block of the .dat for node set NSET: id -> (ux, uy, uz).
std::map<long long, Vec3> dat_displacements(const std::string& text, const std::string& nset) {
  std::map<long long, Vec3> u;
  std::istringstream in(text);
  bool in_block = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find("displacements (vx,vy,vz) for set") != std::string::npos) {
      in_block = line.find("set " + nset + " ") != std::string::npos;
      continue;
    }
    if (!in_block) continue;
    long long id = 0;
    double x = 0, y = 0, z = 0;
    if (std::sscanf(line.c_str(), "%lld %lf %lf %lf", &id, &x, &y, &z) == 4) u[id] = {x, y, z};
    else if (line.find_first_not_of(" \t\r") != std::string::npos) in_block = false;
  }
  return u;
}

class Calculix : public CliTest {
 protected:
  // Meshes the plate with the CLI (curve counts: bottom, right, top, left), appends the
  // analysis to the .inp, runs ccx and returns the mean x displacement of the tip.
  double tip_displacement(const std::vector<int>& counts) {
    std::vector<int> corners;
    const auto points = straight_loop({{0, 0, 0}, {length, 0, 0}, {length, width, 0}, {0, width, 0}}, counts, corners);
    const std::string input = boundary_file("plate.json", points, corners);
    const RunResult mesh = run_tquad({"mesh", input, "-o", path("plate.inp"), "--report", "json"});
    EXPECT_EQ(mesh.exit_status, 0) << mesh.err;
    if (mesh.exit_status != 0) return NAN;
    const auto report = nlohmann::json::parse(mesh.out);

    const std::string inp = read_text(path("plate.inp"));
    const std::map<long long, Vec3> nodes = inp_nodes(inp);
    EXPECT_EQ(static_cast<long long>(nodes.size()), report["nodes"].get<long long>());
    std::vector<long long> fixed;
    std::vector<std::pair<double, long long>> tip;  // (y, id)
    for (const auto& [id, p] : nodes) {
      if (p.x == 0) fixed.push_back(id);
      if (p.x == length) tip.push_back({p.y, id});
    }
    std::sort(tip.begin(), tip.end());
    EXPECT_EQ(fixed.size(), static_cast<std::size_t>(counts[3] + 1));
    EXPECT_EQ(tip.size(), static_cast<std::size_t>(counts[1] + 1));
    EXPECT_EQ(tip.front().first, 0.0);
    EXPECT_EQ(tip.back().first, width);

    std::string deck = inp;
    deck += "*NSET, NSET=FIX\n";
    for (long long id : fixed) deck += std::to_string(id) + "\n";
    deck += "*NSET, NSET=TIP\n";
    for (const auto& t : tip) deck += std::to_string(t.second) + "\n";
    deck +=
        "*MATERIAL, NAME=STEEL\n*ELASTIC\n" + g17(young) + ", " + g17(poisson) + "\n" +
        "*SHELL SECTION, ELSET=EALL, MATERIAL=STEEL\n" + g17(thickness) + "\n" +
        "*BOUNDARY\nFIX, 1, 6\n"
        "*STEP\n*STATIC\n*CLOAD\n";
    // The traction F / width as consistent nodal forces: half of each edge to its ends.
    for (std::size_t i = 0; i < tip.size(); ++i) {
      const double below = i > 0 ? tip[i].first - tip[i - 1].first : 0;
      const double above = i + 1 < tip.size() ? tip[i + 1].first - tip[i].first : 0;
      deck += std::to_string(tip[i].second) + ", 1, " + g17(force * (below + above) / 2 / width) + "\n";
    }
    deck += "*NODE PRINT, NSET=TIP\nU\n*NODE FILE\nU\n*EL FILE\nS\n*END STEP\n";
    write_text(path("plate.inp"), deck);

    const RunResult ccx = run_program("env", {"OMP_NUM_THREADS=1", "ccx", "-i", "plate"}, dir_.string());
    EXPECT_EQ(ccx.exit_status, 0) << ccx.out << ccx.err;
    EXPECT_EQ(ccx.out.find("*ERROR"), std::string::npos) << ccx.out;
    EXPECT_TRUE(std::filesystem::exists(path("plate.frd")));
    EXPECT_TRUE(std::filesystem::exists(path("plate.dat")));
    const std::map<long long, Vec3> u = dat_displacements(read_text(path("plate.dat")), "TIP");
    EXPECT_EQ(u.size(), tip.size()) << read_text(path("plate.dat"));
    if (u.empty()) return NAN;
    double sum = 0;
    for (const auto& [id, d] : u) sum += d.x;
    return sum / static_cast<double>(u.size());
  }
};

TEST_F(Calculix, PlateInTensionMatchesFLOverEA) {
  if (!program_on_path("ccx")) GTEST_SKIP() << "ccx (Debian calculix-ccx) is not on PATH";
  const double expected = force * length / (young * width * thickness);
  const double u = tip_displacement({10, 4, 10, 4});  // template T0: a 10 x 4 grid
  EXPECT_NEAR(u, expected, 0.02 * expected);
}

TEST_F(Calculix, TemplateMeshOfUnequalCountsAlsoMatches) {
  if (!program_on_path("ccx")) GTEST_SKIP() << "ccx (Debian calculix-ccx) is not on PATH";
  const double expected = force * length / (young * width * thickness);
  const double u = tip_displacement({12, 4, 8, 6});  // opposite counts differ: template T2
  EXPECT_NEAR(u, expected, 0.02 * expected);
}

}  // namespace
}  // namespace tquad::cli_test
