#include "cli/shape_arguments.h"

#include <cctype>
#include <sstream>

#include "core/input_error.h"

namespace tquad {

namespace {

int parse_index(const std::string& item, const std::string& what) {
  if (item.empty() || item.find_first_not_of("0123456789") != std::string::npos || item.size() > 9) {
    throw InputError(what + ": '" + item + "' is not a non-negative index");
  }
  return std::stoi(item);
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

}  // namespace

std::vector<int> parse_face_list(const std::string& text, int face_count) {
  std::vector<int> faces;
  // Checked against the shape before a range is expanded (0-999999999 would fill memory).
  const auto existing = [&](int f) {
    if (f >= face_count) {
      throw InputError("--faces: face " + std::to_string(f) + " does not exist; the shape has faces 0.." +
                       std::to_string(face_count - 1));
    }
    return f;
  };
  for (const std::string& item : split(text, ',')) {
    const auto dash = item.find('-');
    if (dash == std::string::npos) {
      faces.push_back(existing(parse_index(item, "--faces")));
      continue;
    }
    const int first = existing(parse_index(item.substr(0, dash), "--faces"));
    const int last = existing(parse_index(item.substr(dash + 1), "--faces"));
    if (last < first) throw InputError("--faces: range '" + item + "' runs backwards");
    for (int f = first; f <= last; ++f) faces.push_back(f);
  }
  if (faces.empty()) throw InputError("--faces: no face given");
  return faces;
}

std::map<int, std::vector<int>> parse_corner_specs(const std::vector<std::string>& specs) {
  std::map<int, std::vector<int>> corners;
  for (const std::string& spec : specs) {
    const auto colon = spec.find(':');
    if (colon == std::string::npos) {
      throw InputError("--corners '" + spec + "': expected FACE:V1,V2[,V3[,V4]]");
    }
    const int face = parse_index(spec.substr(0, colon), "--corners face");
    std::vector<int> vertices;
    for (const std::string& v : split(spec.substr(colon + 1), ',')) vertices.push_back(parse_index(v, "--corners vertex"));
    if (corners.count(face)) throw InputError("--corners: face " + std::to_string(face) + " is given twice");
    corners[face] = vertices;
  }
  return corners;
}

}  // namespace tquad
