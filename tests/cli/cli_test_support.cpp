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

RunResult run_program(const std::string& program, const std::vector<std::string>& args,
                      const std::string& working_dir) {
  // stdout and stderr go to files in a fresh folder per call.
  char pattern[] = "/tmp/tquad_run_XXXXXX";
  const char* folder = mkdtemp(pattern);
  if (folder == nullptr) return {};
  const fs::path out = fs::path(folder) / "stdout", err = fs::path(folder) / "stderr";
  std::string command = working_dir.empty() ? "" : "cd " + shell_quote(working_dir) + " && ";
  command += shell_quote(program);
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

RunResult run_tquad(const std::vector<std::string>& args) { return run_program(TQUAD_EXE, args); }

bool program_on_path(const std::string& program) {
  const std::string command = "command -v " + shell_quote(program) + " >/dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

bool python_module_available(const std::string& module) {
  if (!fs::exists(system_python)) return false;
  return run_program(system_python, {"-c", "import " + module}).exit_status == 0;
}

ShapeMesh two_face_mesh() {
  ShapeMesh mesh;
  for (int j = 0; j <= 2; ++j) {
    for (int i = 0; i <= 4; ++i) mesh.nodes.push_back({i / 3.0, static_cast<double>(j), 0.1});
  }
  for (int face = 0; face < 2; ++face) {
    for (int j = 0; j < 2; ++j) {
      for (int i = 2 * face; i < 2 * face + 2; ++i) {
        const NodeId a = 5 * j + i;
        mesh.quads.push_back({a, a + 1, a + 6, a + 5});
      }
    }
  }
  mesh.faces = {{3, "T0", 0, 4, std::nullopt, ""}, {7, "T1[T0,T0,T0,T0]", 4, 4, std::nullopt, ""}};
  mesh.refused_faces = {{5, "the face has no corners", RefusalCode::cannot_mesh, {2, 4, 6}}};
  return mesh;
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

void CliTest::expect_refused(const std::string& input, const std::vector<std::string>& extra,
                             const std::vector<std::string>& message_parts, const std::string& output) const {
  const std::vector<std::string> before = files();
  std::vector<std::string> args = {"mesh", input, "-o", path(output)};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = run_tquad(args);
  EXPECT_EQ(r.exit_status, 2) << r.err;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.rfind("tquad: error: ", 0), 0u) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
  for (const std::string& part : message_parts) {
    EXPECT_NE(r.err.find(part), std::string::npos) << "'" << part << "' not in: " << r.err;
  }
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(files(), before) << "a failed run left files behind";
}

}  // namespace tquad::cli_test
