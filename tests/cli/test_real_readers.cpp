// Real readers accept the files: meshio (Debian python3-meshio) reads the .vtu, .inp
// and .msh files and Gmsh (python3-gmsh, `import gmsh`) opens the .msh, both for
// files the CLI wrote and for a mesh of two faces written by the writers. Run with
// Debian's /usr/bin/python3; each test is skipped when its module is not importable.
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.h"
#include "io/inp_writer.h"
#include "io/mesh_json_writer.h"
#include "io/msh_writer.h"
#include "io/vtu_writer.h"

namespace tquad::cli_test {
namespace {

using nlohmann::json;

// argv: RESULT.json REFERENCE_MESH.json FILE...; writes per FILE what meshio read, and
// whether its points and cells equal the reference (the .json mesh file: same order),
// or its points are the same set (any order).
const char* const meshio_script = R"(
import json, sys
import numpy as np
import meshio
result_path, reference_path, paths = sys.argv[1], sys.argv[2], sys.argv[3:]
reference = json.load(open(reference_path))
ref_points = np.array(reference["nodes"], dtype=float).reshape(-1, 3)
ref_cells = np.array(reference["quads"], dtype=np.int64).reshape(-1, 4)
def rows(a):
    return a[np.lexsort(a.T[::-1])]
out = {}
for path in paths:
    m = meshio.read(path)
    points = np.asarray(m.points, dtype=float)
    quads = [np.asarray(b.data, dtype=np.int64) for b in m.cells if b.type == "quad"]
    cells = np.concatenate(quads) if quads else np.zeros((0, 4), dtype=np.int64)
    entry = {
        "points": int(len(points)),
        "cells": [[b.type, int(len(b.data))] for b in m.cells],
        "points_equal": bool(points.shape == ref_points.shape and np.array_equal(points, ref_points)),
        "points_same_set": bool(points.shape == ref_points.shape and np.array_equal(rows(points), rows(ref_points))),
        "cells_equal": bool(cells.shape == ref_cells.shape and np.array_equal(cells, ref_cells)),
        "cell_sets": {k: int(sum(len(x) for x in v)) for k, v in m.cell_sets.items()},
    }
    if "face" in m.cell_data:
        entry["face"] = [int(x) for b in m.cell_data["face"] for x in b]
    out[path] = entry
json.dump(out, open(result_path, "w"))
)";

// argv: RESULT.json REFERENCE_MESH.json FILE.msh; writes what Gmsh read (counts,
// entities, physical names, per-entity element counts), whether coordinates and
// element nodes equal the reference by tag, the exception if gmsh.open raised, and
// every log line that is not "Info".
const char* const gmsh_script = R"(
import json, sys
import gmsh
result_path, reference_path, path = sys.argv[1], sys.argv[2], sys.argv[3]
reference = json.load(open(reference_path))
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.logger.start()
result = {}
try:
    gmsh.open(path)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    types, element_tags, element_nodes = gmsh.model.mesh.getElements(2)
    result["nodes"] = len(tags)
    result["element_types"] = [int(t) for t in types]
    result["elements"] = [len(t) for t in element_tags]
    result["entities"] = [[int(d), int(t)] for d, t in gmsh.model.getEntities()]
    result["physical"] = [[int(d), int(t), gmsh.model.getPhysicalName(d, t)] for d, t in gmsh.model.getPhysicalGroups()]
    result["per_entity"] = [[int(t), sum(len(e) for e in gmsh.model.mesh.getElements(2, t)[1])]
                            for d, t in gmsh.model.getEntities(2)]
    nodes = reference["nodes"]
    result["coords_equal"] = all(
        [coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]] == nodes[int(tag) - 1] for i, tag in enumerate(tags))
    quads = reference["quads"]
    ok = len(types) == 1
    if ok:
        for k, tag in enumerate(element_tags[0]):
            if [int(n) - 1 for n in element_nodes[0][4 * k:4 * k + 4]] != quads[int(tag) - 1]:
                ok = False
    result["elements_equal"] = ok
except Exception as e:
    result["exception"] = str(e)
result["log"] = [line for line in gmsh.logger.get() if not line.startswith("Info")]
gmsh.finalize()
json.dump(result, open(result_path, "w"))
)";

class RealReaders : public CliTest {
 protected:
  // Runs a script with system_python; returns the result file's JSON.
  json run_script(const char* script, const std::vector<std::string>& files) {
    std::vector<std::string> args = {"-c", script, path("result.json")};
    args.insert(args.end(), files.begin(), files.end());
    const RunResult r = run_program(system_python, args);
    EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
    if (r.exit_status != 0) return json::object();
    return json::parse(read_text(path("result.json")));
  }

  // A plate meshed by the CLI (opposite curves 12/16 and 20/10: template T2) into
  // plate.json (the reference) and the given formats; returns the JSON report.
  json mesh_plate(const std::vector<std::string>& extensions) {
    std::vector<int> corners;
    const auto points = straight_loop({{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {0, 2, 0}}, {12, 20, 16, 10}, corners);
    const std::string input = boundary_file("plate_boundary.json", points, corners);
    std::vector<std::string> all = {"json"};
    all.insert(all.end(), extensions.begin(), extensions.end());
    json report;
    for (const std::string& ext : all) {
      const RunResult r = run_tquad({"mesh", input, "-o", path("plate." + ext), "--report", "json"});
      EXPECT_EQ(r.exit_status, 0) << r.err;
      report = json::parse(r.out);
    }
    return report;
  }
};

void expect_gmsh_clean(const json& result) {
  EXPECT_FALSE(result.contains("exception")) << result.dump();
  EXPECT_EQ(result["log"], json::array()) << "Gmsh warned or failed: " << result["log"].dump();
  EXPECT_EQ(result["coords_equal"], true);
  EXPECT_EQ(result["elements_equal"], true);
  EXPECT_EQ(result["element_types"], json::array({3}));  // 4-node quadrangles only
}

TEST_F(RealReaders, MeshioReadsTheCliVtuInpAndMsh) {
  if (!python_module_available("meshio")) GTEST_SKIP() << "meshio is not importable by " << system_python;
  const json report = mesh_plate({"vtu", "inp", "msh"});
  ASSERT_FALSE(HasFailure());
  const auto nodes = report["nodes"].get<long long>();
  const auto quads = report["quads"].get<long long>();
  const json result =
      run_script(meshio_script, {path("plate.json"), path("plate.vtu"), path("plate.inp"), path("plate.msh")});
  for (const std::string ext : {"vtu", "inp", "msh"}) {
    SCOPED_TRACE(ext);
    const json& r = result[path("plate." + ext)];
    EXPECT_EQ(r["points"], nodes);
    EXPECT_EQ(r["cells"], json::array({json::array({"quad", quads})}));  // quads only
    EXPECT_EQ(r["points_equal"], true);  // bit-exact, same order
    EXPECT_EQ(r["cells_equal"], true);   // same quads, same node order
  }
  EXPECT_EQ(result[path("plate.vtu")]["face"], json(std::vector<int>(static_cast<std::size_t>(quads), 0)));
  EXPECT_EQ(result[path("plate.inp")]["cell_sets"]["FACE0"], quads);
  EXPECT_EQ(result[path("plate.inp")]["cell_sets"]["EALL"], quads);
  EXPECT_EQ(result[path("plate.msh")]["cell_sets"]["FACE0"], quads);
}

TEST_F(RealReaders, GmshOpensTheCliMsh) {
  if (!python_module_available("gmsh")) GTEST_SKIP() << "gmsh is not importable by " << system_python;
  const json report = mesh_plate({"msh"});
  ASSERT_FALSE(HasFailure());
  const json result = run_script(gmsh_script, {path("plate.json"), path("plate.msh")});
  expect_gmsh_clean(result);
  EXPECT_EQ(result["nodes"], report["nodes"]);
  EXPECT_EQ(result["elements"], json::array({report["quads"]}));
  EXPECT_EQ(result["entities"], json::parse("[[2, 1]]"));
  EXPECT_EQ(result["physical"], json::parse(R"([[2, 1, "FACE0"]])"));
}

class RealReadersTwoFaces : public RealReaders {
 protected:
  void SetUp() override {
    RealReaders::SetUp();
    const ShapeMesh mesh = two_face_mesh();
    write_mesh_json_file(path("two.json"), mesh);
    write_vtu_file(path("two.vtu"), mesh);
    write_inp_file(path("two.inp"), mesh);
    write_msh_file(path("two.msh"), mesh);
  }
};

TEST_F(RealReadersTwoFaces, MeshioReadsEveryFormat) {
  if (!python_module_available("meshio")) GTEST_SKIP() << "meshio is not importable by " << system_python;
  const json result =
      run_script(meshio_script, {path("two.json"), path("two.vtu"), path("two.inp"), path("two.msh")});
  for (const std::string ext : {"vtu", "inp", "msh"}) {
    SCOPED_TRACE(ext);
    const json& r = result[path("two." + ext)];
    EXPECT_EQ(r["points"], 15);
    long long quads = 0;
    for (const json& block : r["cells"]) {
      EXPECT_EQ(block[0], "quad");
      quads += block[1].get<long long>();
    }
    EXPECT_EQ(quads, 8);
    EXPECT_EQ(r["points_same_set"], true);
  }
  // .vtu and .inp keep the node order; .msh lists nodes by face.
  EXPECT_EQ(result[path("two.vtu")]["points_equal"], true);
  EXPECT_EQ(result[path("two.vtu")]["cells_equal"], true);
  EXPECT_EQ(result[path("two.inp")]["points_equal"], true);
  EXPECT_EQ(result[path("two.inp")]["cells_equal"], true);
  EXPECT_EQ(result[path("two.vtu")]["face"], json::parse("[3, 3, 3, 3, 7, 7, 7, 7]"));
  EXPECT_EQ(result[path("two.inp")]["cell_sets"], json::parse(R"({"FACE3": 4, "FACE7": 4, "EALL": 8})"));
  EXPECT_EQ(result[path("two.msh")]["cell_sets"]["FACE3"], 4);
  EXPECT_EQ(result[path("two.msh")]["cell_sets"]["FACE7"], 4);
}

TEST_F(RealReadersTwoFaces, GmshOpensTheMsh) {
  if (!python_module_available("gmsh")) GTEST_SKIP() << "gmsh is not importable by " << system_python;
  const json result = run_script(gmsh_script, {path("two.json"), path("two.msh")});
  expect_gmsh_clean(result);
  EXPECT_EQ(result["nodes"], 15);
  EXPECT_EQ(result["elements"], json::array({8}));
  EXPECT_EQ(result["entities"], json::parse("[[2, 4], [2, 8]]"));
  EXPECT_EQ(result["per_entity"], json::parse("[[4, 4], [8, 4]]"));
  EXPECT_EQ(result["physical"], json::parse(R"([[2, 4, "FACE3"], [2, 8, "FACE7"]])"));
}

// A node no quad uses is left out of the .msh, leaving a gap in the node tags.
TEST_F(RealReaders, GmshAndMeshioAcceptNodeTagGaps) {
  const bool have_gmsh = python_module_available("gmsh"), have_meshio = python_module_available("meshio");
  if (!have_gmsh && !have_meshio) GTEST_SKIP() << "neither gmsh nor meshio is importable by " << system_python;
  ShapeMesh mesh = two_face_mesh();
  mesh.nodes.insert(mesh.nodes.begin() + 6, Vec3{5, 5, 5});  // node 6, tag 7: unused
  for (Quad& q : mesh.quads) {
    for (NodeId& id : q) id += id >= 6 ? 1 : 0;
  }
  write_mesh_json_file(path("gap.json"), mesh);
  write_msh_file(path("gap.msh"), mesh);
  ASSERT_EQ(read_text(path("gap.msh")).find("\n7\n"), std::string::npos);
  if (have_gmsh) {
    const json result = run_script(gmsh_script, {path("gap.json"), path("gap.msh")});
    expect_gmsh_clean(result);
    EXPECT_EQ(result["nodes"], 15);
    EXPECT_EQ(result["elements"], json::array({8}));
  }
  if (have_meshio) {
    const json result = run_script(meshio_script, {path("gap.json"), path("gap.msh")});
    EXPECT_EQ(result[path("gap.msh")]["points"], 15);
    EXPECT_EQ(result[path("gap.msh")]["cells"], json::parse(R"([["quad", 4], ["quad", 4]])"));
  }
}

}  // namespace
}  // namespace tquad::cli_test
