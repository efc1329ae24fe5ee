// The options schema (core/mesh_option_schema.h) against ShapeMeshOptions: each row's
// Python default is the C++ default, so the command, Python and FreeCAD, which take
// their defaults from the schema or the struct, agree.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>

#include "core/mesh_option_schema.h"
#include "occ/shape_mesher.h"

namespace tquad {
namespace {

std::string python_number(double value) {
  std::ostringstream out;
  out << value;
  const std::string text = out.str();
  return text.find_first_of(".e") == std::string::npos ? text + ".0" : text;
}

std::string python_bool(bool value) { return value ? "True" : "False"; }

TEST(OptionSchema, DefaultsAreTheStructsDefaults) {
  const ShapeMeshOptions d;
  // Options whose default is "none given" in every front end, or the reader's.
  const std::map<std::string, std::string> cpp = {
      {"size", python_number(d.size)},
      {"faces", d.faces.empty() ? "None" : "?"},
      {"corners", d.corners.empty() ? "None" : "?"},
      {"keep_going", python_bool(d.keep_going)},
      {"allow_inverted", python_bool(d.allow_inverted)},
      {"threads", std::to_string(d.threads)},
      {"t4_ratio", std::to_string(d.templates.t4_ratio)},
      {"t5_cut_edges", std::to_string(d.templates.t5_cut_edges)},
      {"max_quads", std::to_string(d.templates.max_quads)},
      {"smooth", python_bool(d.smooth)},
      {"progress", d.progress ? "?" : "None"},
      {"read_timeout", "None"},  // ReadLimits: 0 seconds means the default scaled to the file
      {"best_corners", python_bool(d.best_corners)},
      {"min_size", python_number(d.min_size)},
      {"order", std::to_string(d.order)},
      {"sew", python_bool(d.sew)},
      {"sizes", d.local_sizes.empty() ? "None" : "?"},
      {"curvature_segments", std::to_string(d.curvature_segments)},
      {"growth_rate", python_number(d.growth_rate)},
  };
  ASSERT_EQ(mesh_option_schema().size(), cpp.size()) << "a row without its struct field here, or the reverse";
  for (const MeshOptionField& field : mesh_option_schema()) {
    SCOPED_TRACE(field.name);
    ASSERT_EQ(cpp.count(field.name), 1u);
    EXPECT_EQ(field.python_default, cpp.at(field.name));
  }
  EXPECT_THROW(mesh_option("no_such_option"), std::out_of_range);
}

TEST(OptionSchema, HelpWrapsAtWordsWithinTheWidth) {
  const std::string text = wrap_text("one two three four five six seven", 10);
  EXPECT_EQ(text, "one two\nthree four\nfive six\nseven");
  EXPECT_EQ(wrap_text("", 10), "");
  EXPECT_EQ(wrap_text("unbreakablewordlongerthanwidth x", 5), "unbreakablewordlongerthanwidth\nx");
}

}  // namespace
}  // namespace tquad
