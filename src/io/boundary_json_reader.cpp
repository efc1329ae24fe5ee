#include "io/boundary_json_reader.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace tquad {

namespace {

using nlohmann::json;

std::string type_text(const json& value) {
  if (value.is_number()) return "the number " + value.dump();
  return std::string("a JSON ") + value.type_name();
}

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw InputError(source + ": " + what);
}

// nlohmann prefixes its messages with "[json.exception.parse_error.101] ".
std::string without_exception_id(const std::string& message) {
  if (!message.empty() && message[0] == '[') {
    const auto end = message.find("] ");
    if (end != std::string::npos) return message.substr(end + 2);
  }
  return message;
}

const json& required_array(const json& root, const char* key, const std::string& source) {
  const auto it = root.find(key);
  if (it == root.end()) fail(source, std::string("missing key \"") + key + "\"");
  if (!it->is_array()) {
    fail(source, std::string("\"") + key + "\" must be an array, not " + type_text(*it));
  }
  return *it;
}

Vec3 read_point(const json& value, std::size_t index, const std::string& source) {
  const std::string name = "points[" + std::to_string(index) + "]";
  if (!value.is_array()) {
    fail(source, name + " must be an array [x, y] or [x, y, z], not " + type_text(value));
  }
  if (value.size() < 2 || value.size() > 3) {
    fail(source, name + " has " + std::to_string(value.size()) +
                     " coordinates; expected [x, y] or [x, y, z]");
  }
  double xyz[3] = {0.0, 0.0, 0.0};
  for (std::size_t k = 0; k < value.size(); ++k) {
    const json& c = value[k];
    const std::string cname = name + "[" + std::to_string(k) + "]";
    if (!c.is_number()) fail(source, cname + " must be a number, not " + type_text(c));
    xyz[k] = c.get<double>();
    // JSON has no NaN or infinity, but a literal like 1e999 overflows to infinity.
    if (!std::isfinite(xyz[k])) fail(source, cname + " is not a finite double (" + c.dump() + ")");
  }
  return {xyz[0], xyz[1], xyz[2]};
}

int read_corner(const json& value, std::size_t index, const std::string& source) {
  const std::string name = "corners[" + std::to_string(index) + "]";
  if (value.is_number_integer()) {  // signed or unsigned
    const bool fits = value.is_number_unsigned()
                          ? value.get<std::uint64_t>() <= static_cast<std::uint64_t>(std::numeric_limits<int>::max())
                          : value.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
                                value.get<std::int64_t>() <= std::numeric_limits<int>::max();
    if (!fits) fail(source, name + " = " + value.dump() + " is not a valid point index");
    return static_cast<int>(value.get<std::int64_t>());
  }
  if (value.is_number_float()) {
    // Accept integral values written as floats (3.0), as some writers do.
    const double d = value.get<double>();
    if (std::isfinite(d) && d == std::floor(d) && std::abs(d) <= std::numeric_limits<int>::max()) {
      return static_cast<int>(d);
    }
    fail(source, name + " = " + value.dump() + " is not an integer point index");
  }
  fail(source, name + " must be an integer point index, not " + type_text(value));
}

}  // namespace

BoundaryLoop parse_boundary_json(const std::string& text, const std::string& source) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) fail(source, "the file is empty");
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    fail(source, "invalid JSON (byte " + std::to_string(e.byte) + "): " + without_exception_id(e.what()));
  } catch (const json::exception& e) {
    // e.g. out_of_range for a number beyond a double, such as 1e999.
    fail(source, "invalid JSON: " + without_exception_id(e.what()));
  }
  if (!root.is_object()) {
    fail(source, "expected a JSON object {\"points\": [...], \"corners\": [...]}, not " + type_text(root));
  }
  const json& points = required_array(root, "points", source);
  const json& corners = required_array(root, "corners", source);

  BoundaryLoop loop;
  loop.points.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) loop.points.push_back(read_point(points[i], i, source));
  loop.corners.reserve(corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i) loop.corners.push_back(read_corner(corners[i], i, source));
  return loop;
}

BoundaryLoop read_boundary_json(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not a boundary file");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot open the file: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();  // an empty file leaves "" (a JSON syntax error below)
  if (in.bad()) fail(path, "cannot read the file");
  return parse_boundary_json(text.str(), path);
}

}  // namespace tquad
