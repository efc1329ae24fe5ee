// Local sizes (local_sizes.h): the graded spacing on generated edge fields (segments
// grow by at most the rate from one to the next, positions ascending inside the edge,
// ceil of the integral segments) and a plate with a hole whose hole face is given a
// tenth of the global size: its rims get about 2 pi r / h segments, neighbouring
// segments along every edge stay within the growth rate (a margin for the counts'
// rounding on short edges), and the mesh stays far under a uniform fine one.
#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom_Curve.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <algorithm>
#include <cmath>
#include <random>

#include "../case_stride.h"
#include "core/input_error.h"
#include "occ/intervals/local_sizes.h"
#include "occ/shape_mesher.h"

namespace tquad {
namespace {

TEST(LocalSizes, GradedSegmentsGrowByAtMostTheRate) {
  for (int c : testing::cases(400)) {
    SCOPED_TRACE(testing::case_trace(c));
    std::mt19937 rng(c);
    std::uniform_real_distribution<double> u(0, 1);
    EdgeSizing s;
    s.rate = 1.05 + 0.95 * u(rng);
    s.own = 0.1 + u(rng);
    s.first = s.own * (0.01 + 0.99 * u(rng));
    s.last = s.own * (0.01 + 0.99 * u(rng));
    const double length = 0.05 + 20 * u(rng);
    const double goal = graded_segments(s, length);
    ASSERT_GT(goal, 0);
    const int n = std::max(1, static_cast<int>(std::ceil(goal - 1e-9)));
    const std::vector<double> at = graded_positions(s, length, n);
    ASSERT_EQ(static_cast<int>(at.size()), n - 1);
    std::vector<double> cuts{0.0};
    cuts.insert(cuts.end(), at.begin(), at.end());
    cuts.push_back(length);
    for (std::size_t i = 1; i < cuts.size(); ++i) ASSERT_GT(cuts[i], cuts[i - 1]) << i;
    for (std::size_t i = 2; i < cuts.size(); ++i) {
      const double a = cuts[i - 1] - cuts[i - 2], b = cuts[i] - cuts[i - 1];
      EXPECT_LE(std::max(a / b, b / a), s.rate * 1.01) << "segments " << i - 1 << " and " << i;
    }
  }
}

TEST(LocalSizes, EntriesAreParsedOrRefusedByName) {
  const LocalSize f = parse_local_size("face3:0.5");
  EXPECT_EQ(f.kind, LocalSize::Kind::face);
  EXPECT_EQ(f.index, 3);
  EXPECT_EQ(f.size, 0.5);
  EXPECT_EQ(parse_local_size("edge12:2e-1").kind, LocalSize::Kind::edge);
  EXPECT_EQ(parse_local_size("vertex0:1").kind, LocalSize::Kind::vertex);
  for (const char* bad : {"face3", "face:1", "Face3:1", "solid1:1", "face3:0", "face3:-1", "face3:nan",
                          "face3:inf", "face3:1x", "face-1:1", "edge:", ""}) {
    EXPECT_THROW(parse_local_size(bad), InputError) << bad;
  }
  EXPECT_THROW(check_growth_rate(1.0), InputError);
  EXPECT_THROW(check_growth_rate(10.5), InputError);
  EXPECT_NO_THROW(check_growth_rate(1.3));
}

// A 100 x 60 x 5 plate with a through hole of radius 8 at (50, 30).
TopoDS_Shape holed_plate() {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(100, 60, 5).Shape();
  const TopoDS_Shape pin = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(50, 30, -1), gp_Dir(0, 0, 1)), 8, 7).Shape();
  return BRepAlgoAPI_Cut(box, pin).Shape();
}

int cylinder_face(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  for (int i = 1; i <= faces.Extent(); ++i) {
    if (BRepAdaptor_Surface(TopoDS::Face(faces(i))).GetType() == GeomAbs_Cylinder) return i - 1;
  }
  return -1;
}

// Per edge of the shape, the arc-length gaps between the mesh nodes on it.
std::vector<std::vector<double>> segments_along_edges(const TopoDS_Shape& shape, const ShapeMesh& mesh) {
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  std::vector<std::vector<double>> out;
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge edge = TopoDS::Edge(edges(i));
    if (BRep_Tool::Degenerated(edge)) continue;
    double u0 = 0, u1 = 0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, u0, u1);
    std::vector<double> params;
    for (const Vec3& p : mesh.nodes) {
      GeomAPI_ProjectPointOnCurve projection(gp_Pnt(p.x, p.y, p.z), curve, u0, u1);
      if (projection.NbPoints() > 0 && projection.LowerDistance() < 1e-6) {
        params.push_back(projection.LowerDistanceParameter());
      }
    }
    // Both ends (a closed edge's one vertex projects to one of them only), each once.
    params.push_back(u0);
    params.push_back(u1);
    std::sort(params.begin(), params.end());
    params.erase(std::unique(params.begin(), params.end(),
                             [&](double a, double b) { return std::abs(a - b) <= 1e-9 * (1 + std::abs(u1 - u0)); }),
                 params.end());
    const BRepAdaptor_Curve adaptor(edge);
    std::vector<double> gaps;
    for (std::size_t k = 1; k < params.size(); ++k) {
      gaps.push_back(GCPnts_AbscissaPoint::Length(adaptor, params[k - 1], params[k]));
    }
    out.push_back(gaps);
  }
  return out;
}

TEST(LocalSizes, AHoleGivenATenthOfTheSizeIsFineAndGradedOut) {
  const TopoDS_Shape plate = holed_plate();
  const int hole = cylinder_face(plate);
  ASSERT_GE(hole, 0);
  ShapeMeshOptions options;
  options.size = 5.0;
  options.local_sizes = {{LocalSize::Kind::face, hole, 0.5}};
  const ShapeMeshResult local = mesh_shape(plate, options);
  EXPECT_EQ(local.inverted, 0);
  // The hole's rims: about 2 pi 8 / 0.5 = 100.5 segments each.
  int rims = 0;
  for (const std::vector<double>& gaps : segments_along_edges(plate, local.mesh)) {
    if (gaps.size() < 40) continue;
    double length = 0;
    for (double g : gaps) length += g;
    if (std::abs(length - 2 * M_PI * 8) > 0.5) continue;  // a rim (the seam line is 5 long)
    ++rims;
    EXPECT_NEAR(static_cast<double>(gaps.size()), 2 * M_PI * 8 / 0.5, 3.0);
  }
  EXPECT_EQ(rims, 2);
  // Along every edge, neighbouring segments differ by at most the rate; the counts'
  // rounding on an edge a few segments long may stretch one step a little more.
  double worst = 1.0;
  for (const std::vector<double>& gaps : segments_along_edges(plate, local.mesh)) {
    for (std::size_t k = 1; k < gaps.size(); ++k) worst = std::max(worst, std::max(gaps[k] / gaps[k - 1], gaps[k - 1] / gaps[k]));
  }
  EXPECT_LE(worst, 1.3 * 1.05);
  // Far fewer quads than a uniform mesh at the hole's size.
  ShapeMeshOptions fine;
  fine.size = 0.5;
  const ShapeMeshResult uniform = mesh_shape(plate, fine);
  EXPECT_LT(5 * local.mesh.quads.size(), uniform.mesh.quads.size())
      << local.mesh.quads.size() << " local, " << uniform.mesh.quads.size() << " uniform";
  // No local size: the uniform mesh, node for node.
  ShapeMeshOptions plain;
  plain.size = 5.0;
  ShapeMeshOptions empty = plain;
  empty.growth_rate = 2.0;  // without local sizes the rate changes nothing
  EXPECT_EQ(mesh_shape(plate, plain).mesh.nodes.size(), mesh_shape(plate, empty).mesh.nodes.size());
}

TEST(LocalSizes, CurvedEdgesGetTheSegmentsPerTurnAsked) {
  const TopoDS_Shape plate = holed_plate();
  for (int per_turn : {8, 24, 64}) {
    SCOPED_TRACE(per_turn);
    ShapeMeshOptions options;
    options.size = 5.0;
    options.curvature_segments = per_turn;
    const ShapeMeshResult result = mesh_shape(plate, options);
    int rims = 0;
    for (const std::vector<double>& gaps : segments_along_edges(plate, result.mesh)) {
      double length = 0;
      for (double g : gaps) length += g;
      if (std::abs(length - 2 * M_PI * 8) > 0.5) continue;
      ++rims;
      // 2 pi 8 / 5 = 10 segments from the size; at least per_turn from the curve (a
      // face's total made even may add one).
      EXPECT_GE(static_cast<int>(gaps.size()), std::max(per_turn, 10));
      EXPECT_LE(static_cast<int>(gaps.size()), std::max(per_turn, 10) + 2);
    }
    EXPECT_EQ(rims, 2);
  }
  ShapeMeshOptions too_few;
  too_few.curvature_segments = 7;
  EXPECT_THROW(mesh_shape(plate, too_few), InputError);
}

TEST(LocalSizes, EntriesOutsideTheShapeAreRefusedByName) {
  const TopoDS_Shape plate = holed_plate();
  ShapeMeshOptions options;
  options.size = 5.0;
  options.local_sizes = {{LocalSize::Kind::edge, 999, 0.5}};
  try {
    mesh_shape(plate, options);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("size at edge999: the shape has edges 0.."), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tquad
