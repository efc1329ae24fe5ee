#include "occ/read/shape_reader.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <vector>

#include "core/input_error.h"
#include "occ/read/exchange_reader.h"

namespace tquad {

namespace {

void require_faces(const TopoDS_Shape& shape, const std::string& what) {
  if (shape.IsNull() || !TopExp_Explorer(shape, TopAbs_FACE).More()) {
    throw InputError(what + " holds no face to mesh");
  }
}

// The last non-blank line of a file (trailing spaces and carriage returns dropped),
// read from at most its last 4 KiB.
std::string last_line(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  const std::streamoff from = std::max<std::streamoff>(0, size - 4096);
  in.seekg(from);
  std::string tail((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  while (!tail.empty() && std::isspace(static_cast<unsigned char>(tail.back()))) tail.pop_back();
  const auto start = tail.find_last_of('\n');
  std::string line = start == std::string::npos ? tail : tail.substr(start + 1);
  while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
  return line;
}

// A STEP file ends with "END-ISO-10303-21;" and an IGES file with its Terminate
// section (column 73 'T'); OpenCASCADE's readers mesh what they find in a file cut
// short, so a truncated file would be meshed in part.
void require_complete(const std::string& path, ShapeFormat format) {
  const std::string line = last_line(path);
  if (format == ShapeFormat::step && line.find("END-ISO-10303-21;") == std::string::npos) {
    throw InputError("'" + path + "' is cut short: a STEP file ends with END-ISO-10303-21;");
  }
  if (format == ShapeFormat::iges && (line.size() < 73 || line[72] != 'T')) {
    throw InputError("'" + path + "' is cut short: an IGES file ends with its Terminate section");
  }
}

// BRepTools::Read prints to stdout when the text is not a BREP shape, and on a file
// cut short or a damaged count it can throw anything or loop for ever. So the text is
// checked first: it starts with the topology header within its first lines; every
// section ("Curves 15", "TShapes 47", ...) declares no more entries than lines follow
// it (each entry takes at least one line: a count edited to 10^9 made the reader loop
// until its deadline); after "TShapes N" come N shape records, each ending with a line
// that ends in '*', then the root shape reference ("+1 0"). Returns what is wrong, or "".
std::string brep_problem(std::istream& in) {
  std::string line;
  bool header = false;
  for (int i = 0; i < 5 && std::getline(in, line); ++i) {
    if (line.rfind("DBRep_DrawableShape", 0) == 0 || line.rfind("CASCADE Topology V", 0) == 0) {
      header = true;
      break;
    }
  }
  if (!header) return "is not a BREP file (no topology header)";
  struct Section {
    std::string name;
    long long entries;
    long long line;
  };
  static const char* const kSections[] = {"Locations",      "Curve2ds",  "Curves",
                                          "Polygon3D",      "PolygonOnTriangulations",
                                          "Polygon2D",      "Surfaces",  "Triangulations",
                                          "TShapes"};
  std::vector<Section> sections;
  long long lines = 0;
  long long shapes = -1;
  long long records = 0;
  std::string last;
  while (std::getline(in, line)) {
    ++lines;
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
    if (line.empty()) continue;
    if (shapes >= 0) {
      if (line.back() == '*') ++records;
      last = line;
      continue;
    }
    for (const char* name : kSections) {
      const std::size_t n = std::strlen(name);
      if (line.size() <= n + 1 || line.compare(0, n, name) != 0 || line[n] != ' ') continue;
      const char* digits = line.c_str() + n + 1;
      char* end = nullptr;
      errno = 0;
      const long long entries = std::strtoll(digits, &end, 10);
      if (end == digits || entries < 0 || errno == ERANGE) {
        return "is damaged (section '" + line + "' has no valid count)";
      }
      sections.push_back({name, entries, lines});
      if (std::strcmp(name, "TShapes") == 0) shapes = entries;
    }
  }
  if (shapes < 0) return "is cut short or damaged (no TShapes section)";
  for (const Section& section : sections) {
    if (section.entries > lines - section.line) {
      return "is damaged (section " + section.name + " declares " + std::to_string(section.entries) +
             " entries, but only " + std::to_string(lines - section.line) + " lines follow)";
    }
  }
  if (records < shapes) {
    return "is cut short (" + std::to_string(records) + " of " + std::to_string(shapes) + " shapes)";
  }
  if (last.empty() || last.back() == '*') return "is cut short (no root shape)";
  return "";
}

// Reads BREP text with OpenCASCADE, its stdout silenced and its exceptions turned
// into InputError.
TopoDS_Shape read_checked_brep(std::istream& in, const std::string& what) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  std::streambuf* saved = std::cout.rdbuf();
  std::ostringstream discarded;
  std::cout.rdbuf(discarded.rdbuf());
  // A damaged number puts the stream in a failed state, and OpenCASCADE's reader goes
  // on reading from it: counts it never received (a B-spline's poles, a polygon's
  // nodes) then run loops of up to 2^31 failed reads. The first failed read throws.
  in.exceptions(std::ios::failbit | std::ios::badbit);
  try {
    BRepTools::Read(shape, in, builder);
  } catch (...) {
    std::cout.rdbuf(saved);
    throw InputError(what + " is damaged: OpenCASCADE could not read it");
  }
  std::cout.rdbuf(saved);
  return shape;
}

}  // namespace

TopoDS_Shape read_shape(const std::string& path, std::vector<std::string>* warnings) {
  if (!std::ifstream(path).good()) throw InputError("cannot open '" + path + "'");
  const ShapeFormat format = shape_format_of(path);
  TopoDS_Shape shape;
  if (format == ShapeFormat::step || format == ShapeFormat::iges) {
    require_complete(path, format);
    shape = format == ShapeFormat::step ? read_step_file(path, warnings) : read_iges_file(path, warnings);
  } else if (format == ShapeFormat::brep) {
    std::ifstream check(path);
    const std::string problem = brep_problem(check);
    if (!problem.empty()) throw InputError("'" + path + "' " + problem);
    std::ifstream in(path);
    shape = read_checked_brep(in, "'" + path + "'");
  } else {
    throw InputError("'" + path + "': unknown shape format (use .step, .stp, .iges, .igs, .brep)");
  }
  require_faces(shape, "'" + path + "'");
  return shape;
}

TopoDS_Shape read_brep_text(const std::string& brep) {
  std::istringstream check(brep);
  const std::string problem = brep_problem(check);
  if (!problem.empty()) throw InputError("the BREP text " + problem);
  std::istringstream in(brep);
  const TopoDS_Shape shape = read_checked_brep(in, "the BREP text");
  require_faces(shape, "the BREP text");
  return shape;
}

}  // namespace tquad
