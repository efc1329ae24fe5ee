#include "io/mesh_json_reader.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace tquad {

namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw InputError(source + ": " + what);
}

const json& required(const json& object, const char* key, const std::string& source) {
  const auto it = object.find(key);
  if (it == object.end() || !it->is_array()) {
    fail(source, std::string("missing array \"") + key + "\"");
  }
  return *it;
}

}  // namespace

QuadMesh parse_mesh_json(const std::string& text, const std::string& source) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    fail(source, "invalid JSON (byte " + std::to_string(e.byte) + ")");
  } catch (const json::exception& e) {
    fail(source, std::string("invalid JSON: ") + e.what());
  }
  if (!root.is_object()) fail(source, "expected a JSON object");
  QuadMesh mesh;
  const json& nodes = required(root, "nodes", source);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const json& p = nodes[i];
    if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number()) {
      fail(source, "nodes[" + std::to_string(i) + "] is not [x, y, z]");
    }
    mesh.nodes.push_back({p[0].get<double>(), p[1].get<double>(), p[2].get<double>()});
  }
  const json& quads = required(root, "quads", source);
  const auto node_count = static_cast<std::int64_t>(mesh.nodes.size());
  for (std::size_t k = 0; k < quads.size(); ++k) {
    const json& q = quads[k];
    if (!q.is_array() || q.size() != 4) fail(source, "quads[" + std::to_string(k) + "] is not 4 node indices");
    Quad quad{};
    for (int i = 0; i < 4; ++i) {
      if (!q[i].is_number_integer() || q[i].get<std::int64_t>() < 0 || q[i].get<std::int64_t>() >= node_count) {
        fail(source, "quads[" + std::to_string(k) + "][" + std::to_string(i) + "] is not a node index");
      }
      quad[i] = static_cast<NodeId>(q[i].get<std::int64_t>());
    }
    mesh.quads.push_back(quad);
  }
  const auto faces = root.find("faces");
  if (faces != root.end() && faces->is_array()) {
    for (const json& face : *faces) {
      const auto tree = face.find("template_tree");
      if (tree == face.end() || !tree->is_string()) continue;
      if (!mesh.template_tree.empty()) mesh.template_tree += "; ";
      mesh.template_tree += tree->get<std::string>();
    }
  }
  return mesh;
}

QuadMesh read_mesh_json(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot open the file: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_mesh_json(text.str(), path);
}

}  // namespace tquad
