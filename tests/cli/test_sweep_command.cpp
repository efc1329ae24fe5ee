// `tquad sweep`: the example solids of resources/shapes swept into hexahedra and
// written as .inp, .vtu and .json; what is not sweepable refused with exit 2 and no
// file; and CalculiX on the .inp: a cylinder pulled by a pressure on its target cap
// through the surface the writer names, its source cap on rollers, stretches by
// sigma L / E exactly (eight-node hexahedra hold a uniform stress exactly).
#include <cmath>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.h"

namespace tquad::cli_test {
namespace {

const std::string shapes = TQUAD_SHAPES_DIR;

// The ids of node set NAME in an .inp.
std::vector<long long> inp_node_set(const std::string& inp, const std::string& name) {
  std::vector<long long> ids;
  const std::string head = "*NSET, NSET=" + name + "\n";
  const auto at = inp.find(head);
  if (at == std::string::npos) return ids;
  std::istringstream in(inp.substr(at + head.size()));
  for (std::string line; std::getline(in, line) && line.rfind('*', 0) != 0;) {
    std::istringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) ids.push_back(std::stoll(field));
  }
  return ids;
}

std::map<long long, Vec3> inp_nodes(const std::string& inp) {
  std::map<long long, Vec3> nodes;
  std::istringstream in(inp.substr(inp.find("*NODE")));
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line) && line.rfind('*', 0) != 0) {
    long long id;
    Vec3 p;
    if (std::sscanf(line.c_str(), "%lld , %lf , %lf , %lf", &id, &p.x, &p.y, &p.z) == 4) nodes[id] = p;
  }
  return nodes;
}

class Sweep : public CliTest {};

TEST_F(Sweep, ASolidIsWrittenAsHexahedraInEveryFormat) {
  const std::string input = shapes + "/filleted_bracket.brep";
  const RunResult json = run_tquad({"sweep", input, "-o", path("b.inp"), "--size", "3", "--report", "json"});
  ASSERT_EQ(json.exit_status, 0) << json.err;
  const auto report = nlohmann::json::parse(json.out);
  const long long hexes = report["hexes"].get<long long>(), nodes = report["nodes"].get<long long>();
  ASSERT_EQ(report["solids"].size(), 1u);
  EXPECT_EQ(report["solids"][0]["hexes"].get<long long>(), hexes);
  EXPECT_GT(report["quality"]["scaled_jacobian"]["min"].get<double>(), 0.3);
  const std::string inp = read_text(path("b.inp"));
  EXPECT_NE(inp.find("*ELEMENT, TYPE=C3D8, ELSET=SOLID0\n"), std::string::npos);
  EXPECT_EQ(static_cast<long long>(inp_nodes(inp).size()), nodes);
  // The bracket's 9 faces each get a node set and a surface.
  for (int f = 0; f < 9; ++f) {
    EXPECT_FALSE(inp_node_set(inp, "FACE" + std::to_string(f)).empty()) << "face " << f;
    EXPECT_NE(inp.find("*SURFACE, NAME=SFACE" + std::to_string(f) + ", TYPE=ELEMENT"), std::string::npos);
  }
  const RunResult vtu = run_tquad({"sweep", input, "-o", path("b.vtu"), "--size", "3"});
  ASSERT_EQ(vtu.exit_status, 0) << vtu.err;
  EXPECT_NE(vtu.out.find(std::to_string(hexes) + " hexahedra"), std::string::npos) << vtu.out;
  const std::string cells = read_text(path("b.vtu"));
  EXPECT_NE(cells.find("NumberOfCells=\"" + std::to_string(hexes) + "\""), std::string::npos);
  const RunResult js = run_tquad({"sweep", input, "-o", path("b.json"), "--size", "3", "--layers", "4"});
  ASSERT_EQ(js.exit_status, 0) << js.err;
  const auto mesh = nlohmann::json::parse(read_text(path("b.json")));
  EXPECT_EQ(mesh["solids"][0]["layers"], 4);
  const long long layers = report["solids"][0]["layers"];
  EXPECT_EQ(static_cast<long long>(mesh["hexes"].size()) * layers, 4 * hexes);
  for (const auto& h : mesh["hexes"]) ASSERT_EQ(h.size(), 8u);
}

TEST_F(Sweep, WhatCannotBeSweptIsRefusedAndNothingWritten) {
  const RunResult shell = run_tquad({"sweep", shapes + "/plate_with_hole.brep", "-o", path("p.inp")});
  EXPECT_EQ(shell.exit_status, 2);
  EXPECT_NE(shell.err.find("no solid to sweep"), std::string::npos) << shell.err;
  const RunResult lone = run_tquad({"sweep", shapes + "/cylinder.brep", "-o", path("c.inp"), "--source", "1"});
  EXPECT_EQ(lone.exit_status, 2) << "--source needs --target";
  const RunResult caps = run_tquad({"sweep", shapes + "/cylinder.brep", "-o", path("c.inp"), "--source", "0",
                                    "--target", "1"});
  EXPECT_EQ(caps.exit_status, 2);
  EXPECT_NE(caps.err.find("face 0 and face 1 are not the caps of a sweep"), std::string::npos) << caps.err;
  const RunResult stl = run_tquad({"sweep", shapes + "/cylinder.brep", "-o", path("c.stl")});
  EXPECT_EQ(stl.exit_status, 2);
  EXPECT_NE(stl.err.find(".inp, .vtu, .msh or .json"), std::string::npos) << stl.err;
  EXPECT_TRUE(files().empty()) << "a refused sweep writes nothing";
}

TEST_F(Sweep, CalculixStretchesASweptCylinderBySigmaLOverE) {
  if (!program_on_path("ccx")) GTEST_SKIP() << "ccx (Debian calculix-ccx) is not on PATH";
  const RunResult r = run_tquad({"sweep", shapes + "/cylinder.brep", "-o", path("cyl.inp"), "--size", "4",
                                 "--report", "json"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto solid = nlohmann::json::parse(r.out)["solids"][0];
  const int source = solid["source"], target = solid["target"];
  const double height = solid["height"];
  std::string deck = read_text(path("cyl.inp"));
  const std::map<long long, Vec3> nodes = inp_nodes(deck);
  const std::vector<long long> fixed = inp_node_set(deck, "FACE" + std::to_string(source));
  const std::vector<long long> tip = inp_node_set(deck, "FACE" + std::to_string(target));
  ASSERT_FALSE(fixed.empty());
  ASSERT_FALSE(tip.empty());
  // Rollers on the source cap (the cylinder runs along z), and two nodes held sideways
  // against rigid motion: the stress is uniform, sigma = the pressure.
  const long long a = fixed.front();
  long long b = a;
  for (long long n : fixed) {
    if (std::abs(nodes.at(n).x - nodes.at(a).x) > std::abs(nodes.at(b).x - nodes.at(a).x)) b = n;
  }
  constexpr double young = 210000, pressure = 10;
  deck += "*NSET, NSET=TIP\n";
  for (long long n : tip) deck += std::to_string(n) + "\n";
  deck += "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000, 0.3\n*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n"
          "*BOUNDARY\nFACE" + std::to_string(source) + ", 3, 3\n" + std::to_string(a) + ", 1, 2\n" +
          std::to_string(b) + ", 2, 2\n*STEP\n*STATIC\n*DSLOAD\nSFACE" + std::to_string(target) + ", P, -" +
          std::to_string(pressure) + "\n*NODE PRINT, NSET=TIP\nU\n*END STEP\n";
  write_text(path("cyl.inp"), deck);
  const RunResult ccx = run_program("env", {"OMP_NUM_THREADS=1", "ccx", "-i", "cyl"}, dir_.string());
  ASSERT_EQ(ccx.exit_status, 0) << ccx.out << ccx.err;
  EXPECT_EQ(ccx.out.find("*ERROR"), std::string::npos) << ccx.out;
  // The .dat block: "node ux uy uz" lines.
  const std::string dat = read_text(path("cyl.dat"));
  const std::regex line(R"(^\s+(\d+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$)");
  std::istringstream in(dat);
  int count = 0;
  const double expected = pressure * height / young;
  for (std::string text; std::getline(in, text);) {
    std::smatch m;
    if (!std::regex_match(text, m, line)) continue;
    ++count;
    EXPECT_NEAR(std::abs(std::stod(m[4])), expected, 1e-5 * expected) << text;  // the .dat's digits
  }
  EXPECT_EQ(count, static_cast<int>(tip.size()));
}

// The mean z displacement of the .dat's printed nodes.
double mean_uz(const std::string& dat, int& count) {
  const std::regex line(R"(^\s+(\d+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$)");
  std::istringstream in(dat);
  double sum = 0;
  count = 0;
  for (std::string text; std::getline(in, text);) {
    std::smatch m;
    if (!std::regex_match(text, m, line)) continue;
    sum += std::stod(m[4]);
    ++count;
  }
  return count ? sum / count : NAN;
}

TEST_F(Sweep, CalculixBendsASweptCantileverOfTwentyNodeHexahedraAsTimoshenko) {
  if (!program_on_path("ccx")) GTEST_SKIP() << "ccx (Debian calculix-ccx) is not on PATH";
  // 100 x 10 x 10 steel, clamped at x = 0, 100 N down at x = 100 spread over the end
  // face's nodes. Timoshenko: P L^3 / (3 E I) + P L / (k G A), k = 5 / 6.
  constexpr double length = 100, side = 10, young = 210000, poisson = 0.3, force = 100;
  BRepTools::Write(BRepPrimAPI_MakeBox(length, side, side).Shape(), path("beam.brep").c_str());
  const RunResult r = run_tquad({"sweep", path("beam.brep"), "-o", path("beam.inp"), "--source", "0", "--target",
                                 "1", "--size", "2.5", "--order", "2", "--report", "json"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["solids"][0]["layers"], 40);
  std::string deck = read_text(path("beam.inp"));
  EXPECT_NE(deck.find("*ELEMENT, TYPE=C3D20, ELSET=SOLID0"), std::string::npos);
  const std::vector<long long> tip = inp_node_set(deck, "FACE1");
  ASSERT_FALSE(tip.empty());
  // C3D20R: CalculiX's usual choice for bending (reduced integration, no locking).
  const auto at = deck.find("TYPE=C3D20,");
  deck.replace(at, std::string("TYPE=C3D20,").size(), "TYPE=C3D20R,");
  deck += "*NSET, NSET=TIP\n";
  for (long long n : tip) deck += std::to_string(n) + "\n";
  deck += "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000, 0.3\n*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n"
          "*BOUNDARY\nFACE0, 1, 3\n*STEP\n*STATIC\n*CLOAD\nTIP, 3, " +
          std::to_string(-force / static_cast<double>(tip.size())) + "\n*NODE PRINT, NSET=TIP\nU\n*END STEP\n";
  write_text(path("beam.inp"), deck);
  const RunResult ccx = run_program("env", {"OMP_NUM_THREADS=1", "ccx", "-i", "beam"}, dir_.string());
  ASSERT_EQ(ccx.exit_status, 0) << ccx.out << ccx.err;
  EXPECT_EQ(ccx.out.find("*ERROR"), std::string::npos) << ccx.out;
  int count = 0;
  const double deflection = -mean_uz(read_text(path("beam.dat")), count);
  EXPECT_EQ(count, static_cast<int>(tip.size()));
  const double inertia = side * side * side * side / 12, area = side * side;
  const double shear = young / (2 * (1 + poisson));
  const double expected = force * length * length * length / (3 * young * inertia) +
                          force * length / (5.0 / 6.0 * shear * area);
  EXPECT_NEAR(deflection, expected, 0.02 * expected);
}

}  // namespace
}  // namespace tquad::cli_test
