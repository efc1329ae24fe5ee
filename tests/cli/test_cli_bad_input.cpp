// Every wrong input gives exit status 2, one line on stderr that starts
// "tquad: error: " and names the file and the point / segment / curve at fault, and
// no output file (not even a temporary OUT.tmp.XXXXXX).
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_test_support.h"

namespace tquad::cli_test {
namespace {

class BadInput : public CliTest {
 protected:
  // A unit square with the given curve counts; corners at the curve starts.
  std::vector<Vec3> square(const std::vector<int>& counts, std::vector<int>& corners) const {
    return straight_loop({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, counts, corners);
  }
};

TEST_F(BadInput, OddTotalSegmentCount) {
  std::vector<int> corners;
  const auto points = square({4, 4, 4, 3}, corners);
  const std::string file = boundary_file("odd.json", points, corners);
  expect_refused(file, {}, {file, "15 segments", "odd"});
}

TEST_F(BadInput, OneCorner) {
  std::vector<int> corners;
  const auto points = square({4, 4, 4, 4}, corners);
  const std::string file = boundary_file("one.json", points, {0});
  expect_refused(file, {}, {file, "1 corners", "2, 3 or 4"});
}

TEST_F(BadInput, FiveCorners) {
  std::vector<int> corners;
  const auto points = square({4, 4, 4, 4}, corners);
  const std::string file = boundary_file("five.json", points, {0, 3, 6, 9, 12});
  expect_refused(file, {}, {file, "5 corners"});
}

TEST_F(BadInput, CornerIndexOutOfRange) {
  std::vector<int> corners;
  const auto points = square({4, 4, 4, 4}, corners);
  const std::string file = boundary_file("range.json", points, {0, 4, 8, 99});
  expect_refused(file, {}, {file, "corner 3", "99"});
}

TEST_F(BadInput, NegativeCornerIndex) {
  std::vector<int> corners;
  const auto points = square({4, 4, 4, 4}, corners);
  const std::string file = boundary_file("negative.json", points, {0, 4, -1, 12});
  expect_refused(file, {}, {file, "corner 2", "-1"});
}

TEST_F(BadInput, RepeatedCorner) {
  std::vector<int> corners;
  const auto points = square({4, 4, 4, 4}, corners);
  const std::string file = boundary_file("repeat.json", points, {0, 4, 8, 8});
  expect_refused(file, {}, {file, "corner index 8", "twice"});
}

TEST_F(BadInput, ZeroLengthSegment) {
  std::vector<int> corners;
  auto points = square({4, 4, 4, 4}, corners);
  points[5] = points[4];
  const std::string file = boundary_file("zero.json", points, corners);
  expect_refused(file, {}, {file, "segment 4", "point 4", "point 5", "zero length"});
}

TEST_F(BadInput, SelfIntersectingPlanarBoundary) {
  // Point 2 of the bottom side pulled above the top side: segments 1-2 and 2-3
  // cross the top curve (a bow-tie like loop with non-zero area).
  std::vector<int> corners;
  auto points = square({4, 4, 4, 4}, corners);
  points[2] = {0.5, 1.3, 0};
  const std::string file = boundary_file("bowtie.json", points, corners);
  expect_refused(file, {}, {file, "crosses itself", "segment"});
}

TEST_F(BadInput, TwoCurvesOfOneSegmentEach) {
  // Two points, two curves of one segment each: no quad mesh exists.
  const std::string file = boundary_file("two.json", {{0, 0, 0}, {1, 0, 0}}, {0, 1});
  expect_refused(file, {}, {file, "2 points"});
}

TEST_F(BadInput, JsonSyntaxError) {
  const std::string file = path("syntax.json");
  write_text(file, "{\"points\": [[0, 0], [1, 0]], \"corners\": [0, 1,]}");
  expect_refused(file, {}, {file, "invalid JSON", "byte"});
}

TEST_F(BadInput, EmptyFile) {
  const std::string file = path("empty.json");
  write_text(file, "");
  expect_refused(file, {}, {file, "the file is empty"});
}

TEST_F(BadInput, MissingFile) {
  const std::string file = path("does_not_exist.json");
  expect_refused(file, {}, {file, "cannot open"});
}

TEST_F(BadInput, MissingCornersKey) {
  const std::string file = path("nokey.json");
  write_text(file, "{\"points\": [[0, 0], [1, 0], [1, 1], [0, 1]]}");
  expect_refused(file, {}, {file, "missing key \"corners\""});
}

TEST_F(BadInput, PointWithFourCoordinates) {
  const std::string file = path("four.json");
  write_text(file, "{\"points\": [[0, 0], [1, 0], [1, 1, 0, 7], [0, 1]], \"corners\": [0, 1, 2, 3]}");
  expect_refused(file, {}, {file, "points[2] has 4 coordinates"});
}

TEST_F(BadInput, PointWithOneCoordinate) {
  const std::string file = path("onecoord.json");
  write_text(file, "{\"points\": [[0, 0], [1], [1, 1], [0, 1]], \"corners\": [0, 1, 2, 3]}");
  expect_refused(file, {}, {file, "points[1] has 1 coordinates"});
}

TEST_F(BadInput, CoordinateNotANumber) {
  const std::string file = path("string.json");
  write_text(file, "{\"points\": [[0, 0], [\"1\", 0], [1, 1], [0, 1]], \"corners\": [0, 1, 2, 3]}");
  expect_refused(file, {}, {file, "points[1][0] must be a number"});
}

TEST_F(BadInput, NonIntegerCorner) {
  const std::string file = path("fraction.json");
  write_text(file, "{\"points\": [[0, 0], [1, 0], [1, 1], [0, 1]], \"corners\": [0, 1.5, 2, 3]}");
  expect_refused(file, {}, {file, "corners[1]", "not an integer"});
}

TEST_F(BadInput, CornersNotAnArray) {
  const std::string file = path("cornerobj.json");
  write_text(file, "{\"points\": [[0, 0], [1, 0], [1, 1], [0, 1]], \"corners\": 4}");
  expect_refused(file, {}, {file, "\"corners\" must be an array"});
}

// Strict JSON has no NaN or infinity; the nearest a file can get is a literal that
// overflows a double, which the reader refuses (nlohmann reports the overflow).
TEST_F(BadInput, NumberOverflowingADouble) {
  const std::string file = path("huge.json");
  write_text(file, "{\"points\": [[0, 0], [1e999, 0], [1, 1], [0, 1]], \"corners\": [0, 1, 2, 3]}");
  expect_refused(file, {}, {file, "1e999"});
}

TEST_F(BadInput, UnknownOutputExtension) {
  std::vector<int> corners;
  const std::string file = boundary_file("ok.json", square({4, 4, 4, 4}, corners), corners);
  expect_refused(file, {}, {"out.xyz", "unknown output format"}, "out.xyz");
}

TEST_F(BadInput, UnknownOutputExtensionListsTheFormats) {
  std::vector<int> corners;
  const std::string file = boundary_file("ok.json", square({4, 4, 4, 4}, corners), corners);
  expect_refused(file, {}, {"out.stl", "unknown output format", ".json", ".vtu", ".inp", ".msh", ".svg"},
                 "out.stl");
}

TEST_F(BadInput, InpAndMshOutputsAreWrittenOnlyForAGoodInput) {
  std::vector<int> corners;
  const std::string file = boundary_file("odd.json", square({4, 4, 4, 3}, corners), corners);
  expect_refused(file, {}, {file, "odd"}, "out.inp");
  expect_refused(file, {}, {file, "odd"}, "out.msh");
}

TEST_F(BadInput, UnreadableCadFile) {
  for (const std::string ext : {".step", ".stp", ".brep", ".iges", ".igs", ".STEP"}) {
    const std::string file = path("shape" + ext);
    write_text(file, "not a real shape");
    expect_refused(file, {}, {file});
  }
}

TEST_F(BadInput, MissingCadFile) {
  expect_refused(path("absent.step"), {}, {"absent.step", "cannot open"});
}

TEST_F(BadInput, UnknownInputExtension) {
  const std::string file = path("boundary.txt");
  write_text(file, "{}");
  expect_refused(file, {}, {file, "unknown input format"});
}

TEST_F(BadInput, T4RatioBelowTwo) {
  std::vector<int> corners;
  const std::string file = boundary_file("ok.json", square({4, 4, 4, 4}, corners), corners);
  expect_refused(file, {"--t4-ratio", "1"}, {"--t4-ratio"});
}

TEST_F(BadInput, NegativeT5CutEdges) {
  std::vector<int> corners;
  const std::string file = boundary_file("ok.json", square({4, 4, 4, 4}, corners), corners);
  expect_refused(file, {"--t5-cut-edges", "-1"}, {"--t5-cut-edges"});
}

TEST_F(BadInput, NonNumericOption) {
  std::vector<int> corners;
  const std::string file = boundary_file("ok.json", square({4, 4, 4, 4}, corners), corners);
  expect_refused(file, {"--t4-ratio", "two"}, {"--t4-ratio"});
}

TEST_F(BadInput, MeshLargerThanMaxQuads) {
  std::vector<int> corners;
  const std::string file = boundary_file("ok.json", square({4, 4, 4, 4}, corners), corners);
  expect_refused(file, {"--max-quads", "10"}, {file, "16 quads", "limit of 10"});
}

TEST_F(BadInput, UnknownReportFormat) {
  std::vector<int> corners;
  const std::string file = boundary_file("ok.json", square({4, 4, 4, 4}, corners), corners);
  expect_refused(file, {"--report", "xml"}, {"--report"});
}

TEST_F(BadInput, OutputFolderMissing) {
  std::vector<int> corners;
  const std::string file = boundary_file("ok.json", square({4, 4, 4, 4}, corners), corners);
  expect_refused(file, {}, {"no_such_folder/out.json"}, "no_such_folder/out.json");
}

TEST_F(BadInput, OutputIsTheInputFile) {
  std::vector<int> corners;
  const std::string file = boundary_file("ok.json", square({4, 4, 4, 4}, corners), corners);
  const std::string before = read_text(file);
  expect_refused(file, {}, {"the output file is the input file"}, "ok.json");
  EXPECT_EQ(read_text(file), before);
}

TEST_F(BadInput, FailedRunLeavesAnExistingOutputUntouched) {
  std::vector<int> corners;
  const std::string file = boundary_file("odd.json", square({4, 4, 4, 3}, corners), corners);
  write_text(path("out.json"), "previous content");
  expect_refused(file, {}, {file, "odd"});
  EXPECT_EQ(read_text(path("out.json")), "previous content");
}

TEST_F(BadInput, CoordinatesTooLargeForTheGeometry) {
  // Scaled by 1e300 the points are finite, but their products overflow: refused as
  // such (it was reported as "lies on a line").
  std::vector<int> corners;
  std::vector<Vec3> points = square({4, 4, 4, 4}, corners);
  for (Vec3& p : points) p = 1e300 * p;
  expect_refused(boundary_file("huge.json", points, corners), {}, {"point 1", "beyond 1e12"});
}

TEST_F(BadInput, ANonPlanarLoopThatTouchesItself) {
  // A square of 16 points bent out of plane, its point 10 moved onto point 2.
  std::vector<int> corners;
  std::vector<Vec3> points = square({4, 4, 4, 4}, corners);
  for (std::size_t i = 0; i < points.size(); ++i) points[i].z = 0.1 * (i % 3);
  points[10] = points[2];
  expect_refused(boundary_file("touching.json", points, corners), {}, {"points 2 and 10 coincide"});
}

TEST_F(BadInput, T5CutEdgesAboveTheCountLimit) {
  std::vector<int> corners;
  const std::string file = boundary_file("ok.json", square({4, 4, 4, 4}, corners), corners);
  expect_refused(file, {"--t5-cut-edges", "2000000000"}, {"T5 cut edges", "1e8"});
}

TEST_F(BadInput, TwoRunsWritingOneOutputAtOnceLeaveOneCompleteFile) {
  // Each run writes its own temporary file and renames it: the output is one run's
  // complete file, never a mix, and no temporary file is left.
  std::vector<int> corners_a, corners_b;
  const std::string a = boundary_file("a.json", square({300, 320, 300, 320}, corners_a), corners_a);
  const std::string b = boundary_file("b.json", square({310, 330, 310, 330}, corners_b), corners_b);
  ASSERT_EQ(run_tquad({"mesh", a, "-o", path("alone_a.json")}).exit_status, 0);
  ASSERT_EQ(run_tquad({"mesh", b, "-o", path("alone_b.json")}).exit_status, 0);
  const std::string alone_a = read_text(path("alone_a.json")), alone_b = read_text(path("alone_b.json"));
  const std::string exe = TQUAD_EXE;
  for (int round = 0; round < 5; ++round) {
    const std::string out = path("out.json");
    const RunResult r = run_program(
        "/bin/sh", {"-c", "'" + exe + "' mesh '" + a + "' -o '" + out + "' & '" + exe + "' mesh '" + b + "' -o '" +
                              out + "' & wait"});
    ASSERT_EQ(r.exit_status, 0) << r.err;
    const std::string written = read_text(out);
    EXPECT_TRUE(written == alone_a || written == alone_b) << "round " << round << ": a mixed or cut file";
    for (const auto& entry : std::filesystem::directory_iterator(path(""))) {
      EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
    }
  }
}

TEST(CommandLine, UsageErrorsExitWithTwo) {
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {}, {"mesh"}, {"mesh", "a.json"}, {"frobnicate"}, {"mesh", "a.json", "-o", "b.json", "--bogus"}}) {
    const RunResult r = run_tquad(args);
    EXPECT_EQ(r.exit_status, 2) << r.err;
    EXPECT_EQ(r.err.rfind("tquad: error: ", 0), 0u) << r.err;
  }
}

}  // namespace
}  // namespace tquad::cli_test
