// Helpers of the CLI tests: a temporary folder per test, boundary files written with
// round-trip precision, and running `tquad` with its exit status, stdout and stderr.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/vec3.h"

namespace tquad::cli_test {

struct RunResult {
  int exit_status = -1;
  std::string out, err;
};

// Runs TQUAD_EXE with the arguments (each shell-quoted).
RunResult run_tquad(const std::vector<std::string>& args);

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

  std::filesystem::path dir_;
};

}  // namespace tquad::cli_test
