#include "cli_test_support.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace tquad::cli_test {

namespace fs = std::filesystem;

namespace {

std::string shell_quote(const std::string& s) {
  std::string quoted = "'";
  for (char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

RunResult run_tquad(const std::vector<std::string>& args) {
  // Output files sit next to each other in a fresh folder per call.
  char pattern[] = "/tmp/tquad_run_XXXXXX";
  const char* folder = mkdtemp(pattern);
  if (folder == nullptr) return {};
  const fs::path out = fs::path(folder) / "stdout", err = fs::path(folder) / "stderr";
  std::string command = shell_quote(TQUAD_EXE);
  for (const std::string& a : args) command += " " + shell_quote(a);
  command += " >" + shell_quote(out.string()) + " 2>" + shell_quote(err.string()) + " </dev/null";
  const int status = std::system(command.c_str());
  RunResult result;
  result.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = read_text(out);
  result.err = read_text(err);
  std::error_code ignored;
  fs::remove_all(folder, ignored);
  return result;
}

std::string boundary_json(const std::vector<Vec3>& points, const std::vector<int>& corners) {
  std::string text = "{\"points\": [";
  char buffer[128];
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::snprintf(buffer, sizeof buffer, "%s[%.17g, %.17g, %.17g]", i == 0 ? "" : ", ", points[i].x,
                  points[i].y, points[i].z);
    text += buffer;
  }
  text += "], \"corners\": [";
  for (std::size_t i = 0; i < corners.size(); ++i) text += (i == 0 ? "" : ", ") + std::to_string(corners[i]);
  return text + "]}\n";
}

std::vector<Vec3> straight_loop(const std::vector<Vec3>& corners, const std::vector<int>& counts,
                                std::vector<int>& corner_indices) {
  std::vector<Vec3> points;
  corner_indices.clear();
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3& a = corners[i];
    const Vec3& b = corners[(i + 1) % corners.size()];
    corner_indices.push_back(static_cast<int>(points.size()));
    for (int j = 0; j < counts[i]; ++j) points.push_back(a + (static_cast<double>(j) / counts[i]) * (b - a));
  }
  return points;
}

void CliTest::SetUp() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  dir_ = fs::temp_directory_path() /
         ("tquad_cli_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
          std::to_string(::getpid()));
  fs::remove_all(dir_);
  fs::create_directories(dir_);
}

void CliTest::TearDown() {
  std::error_code ignored;
  if (!HasFailure()) fs::remove_all(dir_, ignored);  // kept for inspection on failure
}

std::string CliTest::boundary_file(const std::string& name, const std::vector<Vec3>& points,
                                   const std::vector<int>& corners) const {
  write_text(dir_ / name, boundary_json(points, corners));
  return path(name);
}

std::vector<std::string> CliTest::files() const {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace tquad::cli_test
