// Unit tests of the file writers on a mesh of several faces (two_face_mesh: faces 3
// and 7 sharing an edge, face 5 refused): .inp element sets per face and 1-based ids,
// .msh sections, node blocks and entities, .vtu face data, .json face records, the
// report's faces and refused faces, and the checks every writer makes first.
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.h"
#include "core/mesh/mesh_edges.h"
#include "core/mesh/quality.h"
#include "io/inp_writer.h"
#include "io/mesh_json_reader.h"
#include "io/mesh_json_writer.h"
#include "io/msh_writer.h"
#include "io/report_json.h"
#include "io/shape_mesh_check.h"
#include "io/vtu_writer.h"

namespace tquad::cli_test {
namespace {

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> split_words(const std::string& line, char separator) {
  std::vector<std::string> words;
  std::istringstream in(line);
  for (std::string word; std::getline(in, word, separator);) {
    const auto first = word.find_first_not_of(' ');
    const auto last = word.find_last_not_of(' ');
    words.push_back(first == std::string::npos ? "" : word.substr(first, last - first + 1));
  }
  return words;
}

double number(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  EXPECT_EQ(*end, '\0') << "not a number: '" << text << "'";
  return value;
}

long long integer(const std::string& text) {
  std::size_t used = 0;
  const long long value = std::stoll(text, &used);
  EXPECT_EQ(used, text.size()) << "not an integer: '" << text << "'";
  return value;
}

std::string write_to_string(const std::function<void(std::ostream&, const ShapeMesh&)>& write,
                            const ShapeMesh& mesh) {
  std::ostringstream out;
  write(out, mesh);
  return out.str();
}

// ---------------------------------------------------------------- .inp

// Keyword lines and their data lines ("**" comments dropped).
struct InpBlock {
  std::string keyword;
  std::vector<std::string> data;
};

std::vector<InpBlock> inp_blocks(const std::string& text) {
  std::vector<InpBlock> blocks;
  for (const std::string& line : split_lines(text)) {
    if (line.rfind("**", 0) == 0) continue;
    if (line.rfind("*", 0) == 0) blocks.push_back({line, {}});
    else if (!blocks.empty()) blocks.back().data.push_back(line);
    else ADD_FAILURE() << "data before the first keyword: " << line;
  }
  return blocks;
}

TEST(InpWriter, NodesElementsAndOneElementSetPerFace) {
  const ShapeMesh mesh = two_face_mesh();
  const std::string text = write_to_string(write_inp, mesh);
  const std::vector<InpBlock> blocks = inp_blocks(text);
  ASSERT_EQ(blocks.size(), 4u) << text;

  EXPECT_EQ(blocks[0].keyword, "*NODE, NSET=NALL");
  ASSERT_EQ(blocks[0].data.size(), mesh.nodes.size());
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const auto words = split_words(blocks[0].data[i], ',');
    ASSERT_EQ(words.size(), 4u) << blocks[0].data[i];
    EXPECT_EQ(integer(words[0]), static_cast<long long>(i + 1));
    // Full precision: the text reads back to the same doubles (1/3 among them).
    EXPECT_EQ(number(words[1]), mesh.nodes[i].x) << blocks[0].data[i];
    EXPECT_EQ(number(words[2]), mesh.nodes[i].y) << blocks[0].data[i];
    EXPECT_EQ(number(words[3]), mesh.nodes[i].z) << blocks[0].data[i];
  }

  EXPECT_EQ(blocks[1].keyword, "*ELEMENT, TYPE=S4, ELSET=FACE3");
  EXPECT_EQ(blocks[2].keyword, "*ELEMENT, TYPE=S4, ELSET=FACE7");
  ASSERT_EQ(blocks[1].data.size(), 4u);
  ASSERT_EQ(blocks[2].data.size(), 4u);
  long long expected_id = 1;  // continuous over the faces
  for (int b = 1; b <= 2; ++b) {
    for (const std::string& line : blocks[b].data) {
      const auto words = split_words(line, ',');
      ASSERT_EQ(words.size(), 5u) << line;
      EXPECT_EQ(integer(words[0]), expected_id);
      const Quad& q = mesh.quads[static_cast<std::size_t>(expected_id - 1)];
      for (int i = 0; i < 4; ++i) EXPECT_EQ(integer(words[i + 1]), q[i] + 1) << line;
      ++expected_id;
    }
  }
  EXPECT_EQ(blocks[3].keyword, "*ELSET, ELSET=EALL, GENERATE");
  EXPECT_EQ(blocks[3].data, std::vector<std::string>{"1, 8, 1"});

  EXPECT_NE(text.find("** face 5 refused (not meshed): the face has no corners\n"), std::string::npos) << text;
  EXPECT_NE(text.find("** FACE7: elements 5 to 8\n"), std::string::npos) << text;
}

TEST(InpWriter, LinesFitCalculixAndEmptyFacesGetNoBlock) {
  ShapeMesh mesh = two_face_mesh();
  mesh.nodes[7] = {-1.0000000000000002e-300, 1.2345678901234567e+300, -0.1};  // longest numbers
  mesh.faces.insert(mesh.faces.begin() + 1, FaceMesh{9, "T0", 4, 0, std::nullopt, ""});
  mesh.refused_faces.push_back({11, std::string(400, 'x') + "\nsecond line", RefusalCode::damaged, {}});
  const std::string text = write_to_string(write_inp, mesh);
  for (const std::string& line : split_lines(text)) EXPECT_LE(line.size(), 132u) << line;
  EXPECT_EQ(text.find("FACE9"), std::string::npos) << text;
  EXPECT_EQ(text.find("second line"), std::string::npos);
  EXPECT_EQ(inp_blocks(text).size(), 4u);
}

TEST(InpWriter, EveryNumberFitsCalculixsTwentyCharacterField) {
  // CalculiX stops at a field over 20 characters ("*ERROR reading *NODE"); the shortest
  // round-trip text of a coordinate next to zero has 22.
  ShapeMesh mesh = two_face_mesh();
  const std::vector<double> values = {-4.269692791533339e-15, -1.0000000000000002e-300, 1.2345678901234567e+300,
                                      0.1 + 0.2, -123456.78901234567};
  for (std::size_t i = 0; i < values.size(); ++i) mesh.nodes[i] = {values[i], -values[i], values[i] * 0.5};
  const std::string text = write_to_string(write_inp, mesh);
  const std::vector<std::string> lines = split_lines(text);
  const auto first = std::find(lines.begin(), lines.end(), "*NODE, NSET=NALL");
  ASSERT_NE(first, lines.end());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::string& line = *(first + 1 + static_cast<std::ptrdiff_t>(i));
    std::istringstream fields(line);
    std::vector<double> read;
    for (std::string field; std::getline(fields, field, ',');) {
      const std::string trimmed = field.substr(field.find_first_not_of(' '));
      EXPECT_LE(trimmed.size(), 20u) << line;
      read.push_back(std::stod(trimmed));
    }
    ASSERT_EQ(read.size(), 4u) << line;
    EXPECT_NEAR(read[1], values[i], 1e-12 * std::abs(values[i])) << line;  // at least 13 digits
    EXPECT_NEAR(read[2], -values[i], 1e-12 * std::abs(values[i])) << line;
  }
}

TEST(InpWriter, EmptyMeshHasNoElements) {
  const std::string text = write_to_string(write_inp, ShapeMesh{});
  EXPECT_NE(text.find("*NODE"), std::string::npos);
  EXPECT_EQ(text.find("*ELEMENT"), std::string::npos);
  EXPECT_EQ(text.find("*ELSET"), std::string::npos);
}

// ---------------------------------------------------------------- .msh

// "$Name" -> the lines up to "$EndName".
std::map<std::string, std::vector<std::string>> msh_sections(const std::string& text) {
  std::map<std::string, std::vector<std::string>> sections;
  std::string open;
  for (const std::string& line : split_lines(text)) {
    if (open.empty()) {
      EXPECT_EQ(line.rfind('$', 0), 0u) << "outside a section: " << line;
      open = line.substr(1);
      EXPECT_EQ(sections.count(open), 0u) << "twice: " << open;
      sections[open];
    } else if (line == "$End" + open) {
      open.clear();
    } else {
      sections[open].push_back(line);
    }
  }
  EXPECT_TRUE(open.empty()) << "unterminated $" << open;
  return sections;
}

std::vector<long long> integers(const std::string& line) {
  std::vector<long long> values;
  for (const std::string& w : split_words(line, ' ')) values.push_back(integer(w));
  return values;
}

TEST(MshWriter, SectionsEntitiesAndPhysicalNames) {
  const std::string text = write_to_string(write_msh, two_face_mesh());
  auto sections = msh_sections(text);
  std::vector<std::string> names;
  for (const std::string& line : split_lines(text)) {
    if (line.rfind("$End", 0) != 0 && line.rfind('$', 0) == 0) names.push_back(line);
  }
  EXPECT_EQ(names,
            (std::vector<std::string>{"$MeshFormat", "$PhysicalNames", "$Entities", "$Nodes", "$Elements"}));
  EXPECT_EQ(sections["MeshFormat"], std::vector<std::string>{"4.1 0 8"});
  EXPECT_EQ(sections["PhysicalNames"], (std::vector<std::string>{"2", "2 4 \"FACE3\"", "2 8 \"FACE7\""}));
  // Entity tag = face + 1; bounding box of the face's quads; physical tag = the same.
  const auto& entities = sections["Entities"];
  ASSERT_EQ(entities.size(), 3u);
  EXPECT_EQ(entities[0], "0 0 2 0");
  const auto e3 = split_words(entities[1], ' ');
  const auto e7 = split_words(entities[2], ' ');
  ASSERT_EQ(e3.size(), 10u) << entities[1];
  ASSERT_EQ(e7.size(), 10u) << entities[2];
  EXPECT_EQ(e3[0], "4");
  EXPECT_EQ(e7[0], "8");
  const double box3[6] = {0, 0, 0.1, 2 / 3.0, 2, 0.1}, box7[6] = {2 / 3.0, 0, 0.1, 4 / 3.0, 2, 0.1};
  for (int a = 0; a < 6; ++a) {
    EXPECT_EQ(number(e3[1 + a]), box3[a]) << entities[1];
    EXPECT_EQ(number(e7[1 + a]), box7[a]) << entities[2];
  }
  EXPECT_EQ((std::vector<std::string>(e3.begin() + 7, e3.end())), (std::vector<std::string>{"1", "4", "0"}));
  EXPECT_EQ((std::vector<std::string>(e7.begin() + 7, e7.end())), (std::vector<std::string>{"1", "8", "0"}));
}

// Node and element blocks of the $Nodes / $Elements sections.
struct MshBlock {
  long long entity = 0, type_or_parametric = 0;
  std::vector<long long> tags;
  std::vector<std::vector<std::string>> rows;  // coordinates, or element tag + nodes
};

std::vector<MshBlock> msh_node_blocks(const std::vector<std::string>& lines, std::vector<long long>& header) {
  std::vector<MshBlock> blocks;
  header = integers(lines.at(0));
  std::size_t at = 1;
  for (long long b = 0; b < header.at(0); ++b) {
    const auto h = integers(lines.at(at++));
    EXPECT_EQ(h.at(0), 2);
    MshBlock block{h.at(1), h.at(2), {}, {}};
    for (long long i = 0; i < h.at(3); ++i) block.tags.push_back(integer(lines.at(at++)));
    for (long long i = 0; i < h.at(3); ++i) block.rows.push_back(split_words(lines.at(at++), ' '));
    blocks.push_back(block);
  }
  EXPECT_EQ(at, lines.size());
  return blocks;
}

std::vector<MshBlock> msh_element_blocks(const std::vector<std::string>& lines, std::vector<long long>& header) {
  std::vector<MshBlock> blocks;
  header = integers(lines.at(0));
  std::size_t at = 1;
  for (long long b = 0; b < header.at(0); ++b) {
    const auto h = integers(lines.at(at++));
    EXPECT_EQ(h.at(0), 2);
    MshBlock block{h.at(1), h.at(2), {}, {}};
    for (long long i = 0; i < h.at(3); ++i) {
      block.rows.push_back(split_words(lines.at(at++), ' '));
      block.tags.push_back(integer(block.rows.back().at(0)));
    }
    blocks.push_back(block);
  }
  EXPECT_EQ(at, lines.size());
  return blocks;
}

TEST(MshWriter, EachNodeOnceInTheBlockOfTheFirstFaceThatUsesIt) {
  const ShapeMesh mesh = two_face_mesh();
  auto sections = msh_sections(write_to_string(write_msh, mesh));
  std::vector<long long> header;
  const auto blocks = msh_node_blocks(sections["Nodes"], header);
  EXPECT_EQ(header, (std::vector<long long>{2, 15, 1, 15}));
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].entity, 4);
  EXPECT_EQ(blocks[1].entity, 8);
  EXPECT_EQ(blocks[0].type_or_parametric, 0);
  // Face 3 owns the columns i = 0, 1, 2 (the shared one too); face 7 the rest.
  EXPECT_EQ(blocks[0].tags, (std::vector<long long>{1, 2, 3, 6, 7, 8, 11, 12, 13}));
  EXPECT_EQ(blocks[1].tags, (std::vector<long long>{4, 5, 9, 10, 14, 15}));
  for (const MshBlock& block : blocks) {
    for (std::size_t i = 0; i < block.tags.size(); ++i) {
      const Vec3& p = mesh.nodes[static_cast<std::size_t>(block.tags[i] - 1)];
      ASSERT_EQ(block.rows[i].size(), 3u);
      EXPECT_EQ(number(block.rows[i][0]), p.x);
      EXPECT_EQ(number(block.rows[i][1]), p.y);
      EXPECT_EQ(number(block.rows[i][2]), p.z);
    }
  }
}

TEST(MshWriter, QuadrangleBlocksPerFaceWithContinuousTags) {
  const ShapeMesh mesh = two_face_mesh();
  auto sections = msh_sections(write_to_string(write_msh, mesh));
  std::vector<long long> header;
  const auto blocks = msh_element_blocks(sections["Elements"], header);
  EXPECT_EQ(header, (std::vector<long long>{2, 8, 1, 8}));
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].entity, 4);
  EXPECT_EQ(blocks[1].entity, 8);
  long long expected = 1;
  for (const MshBlock& block : blocks) {
    EXPECT_EQ(block.type_or_parametric, 3);  // 4-node quadrangle
    ASSERT_EQ(block.tags.size(), 4u);
    for (const auto& row : block.rows) {
      ASSERT_EQ(row.size(), 5u);
      EXPECT_EQ(integer(row[0]), expected);
      const Quad& q = mesh.quads[static_cast<std::size_t>(expected - 1)];
      for (int i = 0; i < 4; ++i) EXPECT_EQ(integer(row[i + 1]), q[i] + 1);
      ++expected;
    }
  }
}

TEST(MshWriter, UnusedNodesAreLeftOutAndEmptyFacesHaveNoBlocks) {
  ShapeMesh mesh = two_face_mesh();
  mesh.nodes.push_back({9, 9, 9});  // node 15: no quad uses it
  mesh.faces.push_back({12, "T0", 8, 0, std::nullopt, ""});
  auto sections = msh_sections(write_to_string(write_msh, mesh));
  std::vector<long long> header;
  const auto nodes = msh_node_blocks(sections["Nodes"], header);
  EXPECT_EQ(header, (std::vector<long long>{2, 15, 1, 15}));
  EXPECT_EQ(nodes.size(), 2u);
  const auto elements = msh_element_blocks(sections["Elements"], header);
  EXPECT_EQ(header, (std::vector<long long>{2, 8, 1, 8}));
  EXPECT_EQ(elements.size(), 2u);
  EXPECT_EQ(sections["Entities"].at(0), "0 0 3 0");
  EXPECT_EQ(sections["Entities"].at(3), "13 0 0 0 0 0 0 1 13 0");
}

TEST(MshWriter, EmptyMesh) {
  auto sections = msh_sections(write_to_string(write_msh, ShapeMesh{}));
  EXPECT_EQ(sections.count("PhysicalNames"), 0u);
  EXPECT_EQ(sections["Entities"], std::vector<std::string>{"0 0 0 0"});
  EXPECT_EQ(sections["Nodes"], std::vector<std::string>{"0 0 0 0"});
  EXPECT_EQ(sections["Elements"], std::vector<std::string>{"0 0 0 0"});
}

// ---------------------------------------------------------------- .vtu .json report

TEST(VtuWriter, FaceCellDataComesFromTheRecords) {
  const std::string text = write_to_string(
      [](std::ostream& out, const ShapeMesh& mesh) { write_vtu(out, mesh, VtuEncoding::ascii); }, two_face_mesh());
  EXPECT_NE(text.find("NumberOfPoints=\"15\" NumberOfCells=\"8\""), std::string::npos);
  EXPECT_NE(text.find("Name=\"face\" format=\"ascii\">\n3 3 3 3 7 7 7 7\n"), std::string::npos) << text;
}

TEST(MeshJsonWriter, OneFaceEntryPerRecord) {
  const ShapeMesh mesh = two_face_mesh();
  const std::string text = write_to_string(write_mesh_json, mesh);
  const auto j = nlohmann::json::parse(text);
  EXPECT_EQ(j["nodes"].size(), 15u);
  EXPECT_EQ(j["quads"].size(), 8u);
  EXPECT_EQ(j["faces"], nlohmann::json::parse(R"([
      {"face": 3, "template_tree": "T0", "quads": [0, 4]},
      {"face": 7, "template_tree": "T1[T0,T0,T0,T0]", "quads": [4, 4]}])"));
  EXPECT_FALSE(j.contains("refused_faces"));  // the report has them
  const QuadMesh back = parse_mesh_json(text, "memory");
  EXPECT_EQ(back.quads, mesh.quads);
  EXPECT_EQ(back.template_tree, "T0; T1[T0,T0,T0,T0]");
}

TEST(ReportJson, FacesAndRefusedFaces) {
  const ShapeMesh mesh = two_face_mesh();
  QuadMesh quads;
  quads.nodes = mesh.nodes;
  quads.quads = mesh.quads;
  const auto report = mesh_report_json(mesh, summarize_quality(quads, Vec3{0, 0, 1}));
  EXPECT_EQ(report["nodes"], 15);
  EXPECT_EQ(report["quads"], 8);
  EXPECT_EQ(report["faces"].dump(),
            R"([{"face":3,"template_tree":"T0"},{"face":7,"template_tree":"T1[T0,T0,T0,T0]"}])");
  EXPECT_EQ(report["refused_faces"].dump(),
            R"([{"face":5,"code":"cannot_mesh","reason":"the face has no corners","vertices":[2,4,6]}])");
}

// ---------------------------------------------------------------- checks

class WriterChecks : public CliTest {};

TEST_F(WriterChecks, InconsistentShapeMeshesAreRefusedBeforeWriting) {
  std::vector<std::pair<std::string, std::function<void(ShapeMesh&)>>> breakages = {
      {"node index", [](ShapeMesh& m) { m.quads[5][2] = 15; }},
      {"negative node index", [](ShapeMesh& m) { m.quads[0][0] = -1; }},
      {"gap", [](ShapeMesh& m) { m.faces[1].first_quad = 5, m.faces[1].quad_count = 3; }},
      {"overlap", [](ShapeMesh& m) { m.faces[0].quad_count = 5; }},
      {"not all quads", [](ShapeMesh& m) { m.faces[1].quad_count = 3; }},
      {"past the end", [](ShapeMesh& m) { m.faces[1].quad_count = 5; }},
      {"no records", [](ShapeMesh& m) { m.faces.clear(); }},
      {"out of order", [](ShapeMesh& m) { std::swap(m.faces[0], m.faces[1]); }},
      {"duplicate face", [](ShapeMesh& m) { m.faces[1].face = 3; }},
      {"negative face", [](ShapeMesh& m) { m.faces[0].face = -1; }},
      {"refused and meshed", [](ShapeMesh& m) { m.refused_faces[0].face = 7; }},
      // A binary writer (.vtu) would copy it as it is.
      {"a NaN node", [](ShapeMesh& m) { m.nodes[4].x = std::numeric_limits<double>::quiet_NaN(); }},
  };
  const std::vector<std::pair<std::string, std::function<void(const std::string&, const ShapeMesh&)>>> writers = {
      {"json", [](const std::string& p, const ShapeMesh& m) { write_mesh_json_file(p, m); }},
      {"vtu", [](const std::string& p, const ShapeMesh& m) { write_vtu_file(p, m); }},
      {"inp", write_inp_file},
      {"msh", write_msh_file},
  };
  for (const auto& [what, breakage] : breakages) {
    ShapeMesh mesh = two_face_mesh();
    breakage(mesh);
    EXPECT_THROW(check_shape_mesh(mesh), std::invalid_argument) << what;
    for (const auto& [format, write] : writers) {
      EXPECT_THROW(write(path("out." + format), mesh), std::invalid_argument) << what << ", " << format;
    }
  }
  EXPECT_TRUE(files().empty()) << "a refused mesh left a file";
  EXPECT_NO_THROW(check_shape_mesh(two_face_mesh()));
  EXPECT_NO_THROW(check_shape_mesh(ShapeMesh{}));
}

// two_face_mesh at second order: a middle node per edge, at the edge's middle.
ShapeMesh two_face_second_order_mesh() {
  ShapeMesh mesh = two_face_mesh();
  const MeshEdges edges(mesh.nodes.size(), mesh.quads);
  std::vector<NodeId> middle(edges.count(), -1);
  mesh.mid_nodes.resize(mesh.quads.size());
  for (std::size_t k = 0; k < mesh.quads.size(); ++k) {
    for (int i = 0; i < 4; ++i) {
      const NodeId a = mesh.quads[k][i], b = mesh.quads[k][(i + 1) % 4];
      NodeId& m = middle[edges.index(a, b)];
      if (m < 0) {
        m = static_cast<NodeId>(mesh.nodes.size());
        mesh.nodes.push_back(0.5 * (mesh.nodes[a] + mesh.nodes[b]));
      }
      mesh.mid_nodes[k][i] = m;
    }
  }
  return mesh;
}

TEST_F(WriterChecks, InconsistentSecondOrderMeshesAreRefusedBeforeWriting) {
  // Quads 0 and 1 share the edge 1-6 (quad 0's edge 1, quad 1's edge 3).
  std::vector<std::pair<std::string, std::function<void(ShapeMesh&)>>> breakages = {
      {"a middle per quad", [](ShapeMesh& m) { m.mid_nodes.pop_back(); }},
      {"middle index", [](ShapeMesh& m) { m.mid_nodes[2][1] = static_cast<NodeId>(m.nodes.size()); }},
      {"neighbours disagree", [](ShapeMesh& m) { m.mid_nodes[1][3] = m.mid_nodes[1][0]; }},
      {"a corner as middle", [](ShapeMesh& m) { m.mid_nodes[0][0] = m.quads[0][2]; }},
      {"two edges, one middle", [](ShapeMesh& m) { m.mid_nodes[7][2] = m.mid_nodes[0][0]; }},
  };
  const ShapeMesh valid = two_face_second_order_mesh();
  ASSERT_EQ(valid.nodes.size(), 15u + 22u) << "a 2 x 4 grid of quads has 22 edges";
  EXPECT_NO_THROW(check_shape_mesh(valid));
  for (const auto& [what, breakage] : breakages) {
    ShapeMesh mesh = valid;
    breakage(mesh);
    EXPECT_THROW(check_shape_mesh(mesh), std::invalid_argument) << what;
    EXPECT_THROW(write_vtu_file(path("out.vtu"), mesh), std::invalid_argument) << what;
  }
  EXPECT_TRUE(files().empty()) << "a refused mesh left a file";
}

TEST(WriterChecksMessages, SayWhichRecord) {
  ShapeMesh mesh = two_face_mesh();
  mesh.faces[1].first_quad = 5;
  try {
    check_shape_mesh(mesh);
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("faces[1] (face 7)"), std::string::npos) << e.what();
  }
}

TEST(WriterChecksMessages, NonFiniteCoordinatesAreRefused) {
  // By check_shape_mesh, which every writer runs first (std::invalid_argument).
  ShapeMesh mesh = two_face_mesh();
  mesh.nodes[4].y = std::numeric_limits<double>::infinity();
  std::ostringstream out;
  EXPECT_THROW(write_inp(out, mesh), std::logic_error);
  EXPECT_THROW(write_msh(out, mesh), std::logic_error);
  EXPECT_THROW(write_mesh_json(out, mesh), std::logic_error);
}

}  // namespace
}  // namespace tquad::cli_test
