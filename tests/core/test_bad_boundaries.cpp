// Bad boundaries are refused with an InputError that names the point, segment or curve.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "boundary_generators.h"
#include "core/input_error.h"
#include "core/templates/mesher.h"

namespace tquad {
namespace {

// Expects mesh_boundary to throw InputError whose message contains `expected`.
void expect_refused(const BoundaryLoop& loop, const std::string& expected, const MeshOptions& options = {}) {
  try {
    mesh_boundary(loop, options);
    ADD_FAILURE() << "accepted; expected an error containing '" << expected << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos)
        << "message '" << e.what() << "' lacks '" << expected << "'";
  }
}

BoundaryLoop square() { return testing::square_boundary(4, 4, 3, 3); }

TEST(BadBoundaries, OddSegmentCount) {
  BoundaryLoop loop = testing::square_boundary(4, 4, 3, 4);
  expect_refused(loop, "15 segments, an odd number");
}

TEST(BadBoundaries, CornerCountOutsideTwoToFour) {
  BoundaryLoop loop = square();
  loop.corners = {0};
  expect_refused(loop, "1 corners");
  loop.corners = {0, 2, 4, 6, 8};
  expect_refused(loop, "5 corners");
}

TEST(BadBoundaries, CornerOutOfRangeOrRepeated) {
  BoundaryLoop loop = square();
  loop.corners = {0, 4, 7, 14};
  expect_refused(loop, "corner 3 has index 14, outside the points 0..13");
  loop.corners = {0, 4, 4, 11};
  expect_refused(loop, "corner index 4 is given twice");
  loop.corners = {0, 4, 7, -1};
  expect_refused(loop, "corner 3 has index -1");
}

TEST(BadBoundaries, NonFiniteCoordinates) {
  BoundaryLoop loop = square();
  loop.points[5].y = std::numeric_limits<double>::quiet_NaN();
  expect_refused(loop, "point 5 has a coordinate that is NaN or infinite");
  loop = square();
  loop.points[9].z = std::numeric_limits<double>::infinity();
  expect_refused(loop, "point 9");
}

TEST(BadBoundaries, ZeroLengthSegment) {
  BoundaryLoop loop = square();
  loop.points[3] = loop.points[2];
  expect_refused(loop, "segment 2 from point 2 to point 3 has zero length");
}

TEST(BadBoundaries, SegmentShorterThanRoundingOfTheExtent) {
  // Two points one unit in the last place apart (a fuzzed loop; its T3 split's
  // parameter rounded to 1 and the centre became NaN): refused, named, with the length.
  BoundaryLoop loop = square();
  loop.points[3] = loop.points[2];
  loop.points[3].y = std::nextafter(loop.points[3].y, 10.0);
  expect_refused(loop, "segment 2 from point 2 to point 3 is ");
  expect_refused(loop, "long, under 1e-12 of the boundary's extent: its points coincide but for rounding");
  // A millionth of the extent is a short segment, not a degenerate one.
  loop.points[3].y = loop.points[2].y + 1e-6;
  EXPECT_NO_THROW(validate_boundary(loop));
}

TEST(BadBoundaries, SelfIntersectingPlanarBoundary) {
  // A bow-tie: the loop (0,0) (1,1) (1,0) (0,1) crosses itself.
  BoundaryLoop loop;
  const Vec3 p[4] = {{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}};
  for (int k = 0; k < 4; ++k) {
    for (int i = 0; i < 3; ++i) loop.points.push_back(testing::line(p[k], p[(k + 1) % 4])(i / 3.0));
  }
  loop.corners = {0, 3, 6, 9};
  expect_refused(loop, "boundary crosses itself: segment");
}

TEST(BadBoundaries, BoundaryTouchingItself) {
  // A square whose top side has a spike down to the bottom side.
  BoundaryLoop loop;
  loop.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1.5, 1, 0}, {1, 0, 0.0}, {0.5, 1, 0}, {0, 1, 0}};
  loop.points[5] = {1, 0, 0};
  loop.corners = {0, 2, 3, 7};
  EXPECT_THROW(mesh_boundary(loop), InputError);
}

TEST(BadBoundaries, FoldBack) {
  BoundaryLoop loop;
  loop.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1.5, 0, 0}, {2, 1, 0}, {0, 1, 0}};
  loop.corners = {0, 4, 5};
  EXPECT_THROW(mesh_boundary(loop), InputError);
}

TEST(BadBoundaries, TwoCurvesOfOneSegmentEach) {
  BoundaryLoop loop;
  loop.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  loop.corners = {0, 1};  // 1 and 3 segments: meshable
  EXPECT_NO_THROW(mesh_boundary(loop));
  loop.points = {{0, 0, 0}, {1, 0, 0}};
  loop.corners = {0, 1};
  expect_refused(loop, "at least 4");
}

TEST(BadBoundaries, AbsurdSizeIsRefusedBeforeAllocating) {
  MeshOptions options;
  options.max_quads = 1000;
  expect_refused(testing::square_boundary(40, 40, 40, 40), "1600 quads, more than the limit of 1000", options);
}

TEST(BadBoundaries, T4RatioBelowTwo) {
  MeshOptions options;
  options.t4_ratio = 1;
  expect_refused(square(), "T4 ratio k must be at least 2", options);
}

}  // namespace
}  // namespace tquad
