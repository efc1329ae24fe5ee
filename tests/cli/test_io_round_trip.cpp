// Unit tests of the io library: mesh JSON write / read round trip (bit-exact), the
// boundary reader's accepted forms, VTU ASCII, SVG captions, the report object and
// the all-or-nothing file writing.
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_test_support.h"
#include "core/input_error.h"
#include "core/templates/mesher.h"
#include "core/mesh/quality.h"
#include "core/mesh/shape_mesh.h"
#include "io/atomic_file_writer.h"
#include "io/boundary_json_reader.h"
#include "io/mesh_json_reader.h"
#include "io/mesh_json_writer.h"
#include "io/report_json.h"
#include "io/svg_writer.h"
#include "io/vtu_writer.h"

namespace tquad::cli_test {
namespace {

// The file writers take a shape's mesh; a copy keeps the QuadMesh for comparisons.
ShapeMesh as_shape(const QuadMesh& mesh) { return single_face_mesh(QuadMesh(mesh)); }

QuadMesh disk_mesh() {
  BoundaryLoop loop;
  const int n = 36;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n;
    loop.points.push_back({std::cos(t) * 1.7, std::sin(t) * 0.3 + 1e-9, -0.0});
  }
  loop.corners = {0, 18};
  return mesh_boundary(loop);
}

TEST(MeshJson, WriteThenReadIsBitExact) {
  const QuadMesh mesh = disk_mesh();
  std::ostringstream text;
  write_mesh_json(text, as_shape(mesh));
  const QuadMesh back = parse_mesh_json(text.str(), "memory");
  ASSERT_EQ(back.nodes.size(), mesh.nodes.size());
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    EXPECT_EQ(back.nodes[i], mesh.nodes[i]) << "node " << i;
    EXPECT_EQ(std::signbit(back.nodes[i].z), std::signbit(mesh.nodes[i].z)) << "node " << i;
  }
  EXPECT_EQ(back.quads, mesh.quads);
  EXPECT_EQ(back.template_tree, mesh.template_tree);
}

TEST(MeshJson, ExtremeDoublesRoundTrip) {
  QuadMesh mesh;
  mesh.nodes = {{std::numeric_limits<double>::denorm_min(), -0.0, 1e308},
                {std::numeric_limits<double>::max(), 0.1, 1.0 / 3.0},
                {-std::numeric_limits<double>::min(), 123456789012345678.0, 1.0},
                {2.0, -1e-300, 5e-324}};
  mesh.quads = {{0, 1, 2, 3}};
  mesh.template_tree = "T0 \"quoted\"";
  std::ostringstream text;
  write_mesh_json(text, as_shape(mesh));
  const QuadMesh back = parse_mesh_json(text.str(), "memory");
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) EXPECT_EQ(back.nodes[i], mesh.nodes[i]);
  EXPECT_TRUE(std::signbit(back.nodes[0].y));
  EXPECT_EQ(back.template_tree, mesh.template_tree);
}

TEST(MeshJson, NonFiniteNodeIsAnInternalError) {
  QuadMesh mesh;
  mesh.nodes = {{NAN, 0, 0}};
  std::ostringstream text;
  EXPECT_THROW(write_mesh_json(text, as_shape(mesh)), std::logic_error);
}

class IoFiles : public CliTest {};

TEST_F(IoFiles, MeshJsonFileRoundTrip) {
  const QuadMesh mesh = disk_mesh();
  write_mesh_json_file(path("disk.json"), as_shape(mesh));
  EXPECT_EQ(files(), std::vector<std::string>{"disk.json"});
  const QuadMesh back = read_mesh_json(path("disk.json"));
  EXPECT_EQ(back.quads, mesh.quads);
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) EXPECT_EQ(back.nodes[i], mesh.nodes[i]);
}

TEST_F(IoFiles, BoundaryReaderAcceptsTwoAndThreeCoordinatesAndIntegralFloats) {
  write_text(path("b.json"),
             "{\"name\": \"extra keys are ignored\", \"points\": [[0, 0], [1.5, 0, 2], [1, 1], [0, 1e-3]],"
             " \"corners\": [0, 1.0, 2, 3]}");
  const BoundaryLoop loop = read_boundary_json(path("b.json"));
  ASSERT_EQ(loop.points.size(), 4u);
  EXPECT_EQ(loop.points[0], (Vec3{0, 0, 0}));
  EXPECT_EQ(loop.points[1], (Vec3{1.5, 0, 2}));
  EXPECT_EQ(loop.points[3], (Vec3{0, 1e-3, 0}));
  EXPECT_EQ(loop.corners, (std::vector<int>{0, 1, 2, 3}));
}

TEST_F(IoFiles, BoundaryReaderMessagesNameFileAndEntry) {
  auto message = [&](const std::string& text) {
    write_text(path("b.json"), text);
    try {
      read_boundary_json(path("b.json"));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("[1, 2]").rfind(path("b.json") + ": expected a JSON object", 0), 0u);
  EXPECT_NE(message("{\"points\": {}, \"corners\": []}").find("\"points\" must be an array"), std::string::npos);
  EXPECT_NE(message("{\"points\": [[0,0],[1,0],[1,1],[0,1],[0.5, true]], \"corners\": [0]}")
                .find("points[4][1] must be a number, not a JSON boolean"),
            std::string::npos);
  EXPECT_NE(message("{\"points\": [[0,0]], \"corners\": [\"0\"]}").find("corners[0] must be an integer"),
            std::string::npos);
  EXPECT_NE(message("{\"points\": [[0,0]], \"corners\": [3000000000]}").find("corners[0] = 3000000000"),
            std::string::npos);
  EXPECT_NE(message("{\"points\": [[0,0]], \"corners\": [0]} trailing").find("byte"), std::string::npos);
  EXPECT_NE(message("{\"points\": [[1e400, 0]], \"corners\": [0]}").find("overflow"), std::string::npos);
  // A directory is not a boundary file.
  try {
    read_boundary_json(dir_.string());
    ADD_FAILURE() << "a directory was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("directory"), std::string::npos) << e.what();
  }
}

TEST(Vtu, AsciiListsPointsCellsAndFace) {
  QuadMesh mesh;
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.25}, {0, 1, 0}};
  mesh.quads = {{0, 1, 2, 3}};
  std::ostringstream out;
  write_vtu(out, as_shape(mesh), VtuEncoding::ascii);
  const std::string text = out.str();
  EXPECT_NE(text.find("NumberOfPoints=\"4\" NumberOfCells=\"1\""), std::string::npos);
  EXPECT_NE(text.find("1 1 0.25\n"), std::string::npos) << text;
  EXPECT_NE(text.find("0 1 2 3\n"), std::string::npos) << text;
  EXPECT_NE(text.find("Name=\"types\" format=\"ascii\">\n9\n"), std::string::npos) << text;
  EXPECT_NE(text.find("Name=\"face\" format=\"ascii\">\n0\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("AppendedData"), std::string::npos);
}

TEST(Svg, PanelsCaptionsAndEscaping) {
  const QuadMesh mesh = disk_mesh();
  std::ostringstream out;
  SvgOptions options;
  options.columns = 2;
  options.panel_size = 200;
  write_svg(out, {{&mesh, 36, "a <b> & c"}, {&mesh, 36, "line one\nline two"}, {&mesh, 0, ""}}, options);
  const std::string svg = out.str();
  EXPECT_NE(svg.find("width=\"400.00\""), std::string::npos);
  EXPECT_NE(svg.find("a &lt;b&gt; &amp; c"), std::string::npos);
  EXPECT_NE(svg.find(">line one<"), std::string::npos);
  EXPECT_NE(svg.find(">line two<"), std::string::npos);
  EXPECT_EQ(svg.find("<b>"), std::string::npos);
}

TEST(Svg, LongCaptionsWrapAtCommas) {
  const QuadMesh mesh = disk_mesh();
  std::ostringstream out;
  SvgOptions options;
  options.panel_size = 120;  // about 14 characters per line
  write_svg(out, {{&mesh, 36, "T4[T3[T0,T0,T0],T1[T0,T0,T0,T0]]"}}, options);
  const std::string svg = out.str();
  EXPECT_EQ(svg.find("T4[T3[T0,T0,T0],T1[T0,T0,T0,T0]]"), std::string::npos);
  EXPECT_NE(svg.find(">T4[T3[T0,T0,"), std::string::npos) << svg;
}

TEST(Report, FieldsInContractOrder) {
  const QuadMesh mesh = disk_mesh();
  const auto report = mesh_report_json(as_shape(mesh), summarize_quality(mesh, Vec3{0, 0, 1}));
  std::vector<std::string> keys;
  for (const auto& item : report.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"nodes", "quads", "triangles", "quality", "faces", "refused_faces"}));
  EXPECT_EQ(report["nodes"], mesh.nodes.size());
  EXPECT_EQ(report["faces"][0]["template_tree"], mesh.template_tree);
  EXPECT_TRUE(report["refused_faces"].is_array());
  EXPECT_TRUE(report["refused_faces"].empty());
}

TEST_F(IoFiles, AtomicWriteLeavesNothingWhenTheWriterThrows) {
  write_text(path("out.txt"), "old");
  EXPECT_THROW(write_file_atomically(path("out.txt"),
                                     [](std::ostream& out) {
                                       out << "partial";
                                       throw std::runtime_error("boom");
                                     }),
               std::runtime_error);
  EXPECT_EQ(files(), std::vector<std::string>{"out.txt"});
  EXPECT_EQ(read_text(path("out.txt")), "old");
  write_file_atomically(path("out.txt"), [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(read_text(path("out.txt")), "new");
  EXPECT_THROW(write_file_atomically(path("missing/out.txt"), [](std::ostream&) {}), InputError);
}

}  // namespace
}  // namespace tquad::cli_test
