// The command's CAD layer is its modules (src/cli/cad_input.h): a boundary file is
// meshed without them, and a CAD input without its module is an internal failure
// (exit 1) naming the missing module, with no output; a BREP file needs no STEP or
// IGES reader, and a STEP file no IGES reader.
#include <filesystem>
#include <string>
#include <vector>

#include <BRepPrimAPI_MakeBox.hxx>
#include <IGESControl_Writer.hxx>
#include <gtest/gtest.h>

#include "cli_test_support.h"

namespace tquad::cli_test {
namespace {

namespace fs = std::filesystem;

class CommandModules : public CliTest {
 protected:
  // An installation in the test's folder: bin/tquad and the given modules in
  // lib/templatequad/. Returns the command's path.
  std::string install(const std::vector<std::string>& modules) const {
    fs::create_directories(dir_ / "bin");
    fs::create_directories(dir_ / "lib" / "templatequad");
    fs::copy_file(TQUAD_EXE, dir_ / "bin" / "tquad");
    for (const std::string& module : modules) {
      fs::copy_file(module, dir_ / "lib" / "templatequad" / fs::path(module).filename());
    }
    return (dir_ / "bin" / "tquad").string();
  }
  static std::string example(const std::string& name) { return std::string(TQUAD_SHAPES_DIR) + "/" + name; }
  // exit 1, an internal failure naming `module` on stderr, no output file.
  void expect_missing(const std::string& tquad, const std::string& input, const std::string& module) const {
    const RunResult r = run_program(tquad, {"mesh", input, "-o", path("out.vtu")});
    EXPECT_EQ(r.exit_status, 1) << r.err;
    EXPECT_NE(r.err.find("tquad: error: internal failure: cannot load"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(module), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("out.vtu")));
  }
};

TEST_F(CommandModules, ABoundaryFileNeedsNoModule) {
  const std::string tquad = install({});
  const RunResult r =
      run_program(tquad, {"mesh", std::string(TQUAD_EXAMPLES_DIR) + "/plate_t2.json", "-o", path("plate.vtu")});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("plate.vtu")));
}

TEST_F(CommandModules, ACadInputWithoutTheCadModuleIsAnInternalFailure) {
  const std::string tquad = install({});
  expect_missing(tquad, example("cylinder.brep"), "tquad_cad.so");
  expect_missing(tquad, example("plate_with_hole.step"), "tquad_cad.so");
}

TEST_F(CommandModules, ABrepFileNeedsNoStepOrIgesReader) {
  const std::string tquad = install({TQUAD_CAD_MODULE});
  const RunResult r = run_program(tquad, {"mesh", example("cylinder.brep"), "-o", path("cylinder.vtu")});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("cylinder.vtu")));
  // A STEP file then fails in the reader's child process, as the program's failure
  // (not as a damaged file).
  expect_missing(tquad, example("plate_with_hole.step"), "tquad_step.so");
}

TEST_F(CommandModules, AStepFileNeedsNoIgesReader) {
  const std::string tquad = install({TQUAD_CAD_MODULE, TQUAD_STEP_MODULE});
  const RunResult r = run_program(tquad, {"mesh", example("plate_with_hole.step"), "-o", path("plate.vtu")});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("plate.vtu")));
}

TEST_F(CommandModules, AnIgesFileNeedsTheIgesReaderOnly) {
  const std::string iges = path("box.igs");
  IGESControl_Writer writer("MM", 1);  // 1: BRep mode
  writer.AddShape(BRepPrimAPI_MakeBox(10, 20, 30).Shape());
  writer.ComputeModel();
  ASSERT_TRUE(writer.Write(iges.c_str()));
  const std::string tquad = install({TQUAD_CAD_MODULE, TQUAD_STEP_MODULE});
  expect_missing(tquad, iges, "tquad_iges.so");
  fs::copy_file(TQUAD_IGES_MODULE, dir_ / "lib" / "templatequad" / "tquad_iges.so");
  fs::remove(dir_ / "lib" / "templatequad" / "tquad_step.so");
  const RunResult r = run_program(tquad, {"mesh", iges, "-o", path("box.vtu")});
  EXPECT_EQ(r.exit_status, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("box.vtu")));
}

}  // namespace
}  // namespace tquad::cli_test
