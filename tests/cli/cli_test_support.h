// Helpers of the CLI tests: a temporary folder per test, boundary files written with
// round-trip precision, and running `tquad` with its exit status, stdout and stderr.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/mesh/shape_mesh.h"
#include "core/geometry/vec3.h"

namespace tquad::cli_test {

struct RunResult {
  int exit_status = -1;
  std::string out, err;
};

// Runs TQUAD_EXE with the arguments (each shell-quoted).
RunResult run_tquad(const std::vector<std::string>& args);

// Runs any program with the arguments (each shell-quoted), in `working_dir` when not
// empty. `program` is found on PATH unless it has a '/'.
RunResult run_program(const std::string& program, const std::vector<std::string>& args,
                      const std::string& working_dir = "");

// Whether `program` is an executable on PATH (e.g. "ccx").
bool program_on_path(const std::string& program);

// Debian's python, which has the python3-* packages (PLATFORM.md: not the pyenv one).
inline constexpr const char* system_python = "/usr/bin/python3";

// Whether system_python exists and can import `module`.
bool python_module_available(const std::string& module);

// Two faces side by side that share the nodes of their common edge: a 2 x 2 grid of
// quads each, on x in [0, 2/3] (face 3) and [2/3, 4/3] (face 7), y in [0, 2], z = 0.1,
// with node k = 5 j + i at (i / 3, j, 0.1); plus refused face 5. 15 nodes, 8 quads
// (quads 0-3 face 3, quads 4-7 face 7), counter-clockwise seen from +z.
ShapeMesh two_face_mesh();

std::string read_text(const std::filesystem::path& path);
void write_text(const std::filesystem::path& path, const std::string& text);

// {"points": [...], "corners": [...]} with %.17g coordinates.
std::string boundary_json(const std::vector<Vec3>& points, const std::vector<int>& corners);

// Straight sides between the corner points, counts[i] uniform segments on side i.
std::vector<Vec3> straight_loop(const std::vector<Vec3>& corners, const std::vector<int>& counts,
                                std::vector<int>& corner_indices);

// A temporary folder, removed after the test.
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // Writes a boundary file and returns its path.
  std::string boundary_file(const std::string& name, const std::vector<Vec3>& points,
                            const std::vector<int>& corners) const;
  // Files in the folder (to check that a failed run wrote nothing).
  std::vector<std::string> files() const;
  // Runs `tquad mesh INPUT -o OUTPUT` plus extra arguments and expects a refusal:
  // exit 2, one "tquad: error: " line on stderr holding every part, nothing on stdout
  // and no new file in the folder.
  void expect_refused(const std::string& input, const std::vector<std::string>& extra,
                      const std::vector<std::string>& message_parts,
                      const std::string& output = "out.json") const;

  std::filesystem::path dir_;
};

}  // namespace tquad::cli_test
