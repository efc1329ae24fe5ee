#include "io/vtu_writer.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <functional>
#include <utility>
#include <stdexcept>
#include <vector>

#include "io/atomic_file_writer.h"
#include "io/shape_mesh_check.h"

namespace tquad {

namespace {

constexpr std::uint8_t vtk_quad = 9;
constexpr std::uint8_t vtk_quadratic_quad = 23;

bool little_endian() {
  const std::uint16_t probe = 1;
  unsigned char first = 0;
  std::memcpy(&first, &probe, 1);
  return first == 1;
}

// One DataArray: its XML attributes, its size in bytes and what writes those bytes
// (raw, in the machine's byte order) to a stream.
struct ArrayBlock {
  std::string type, name;
  int components;
  std::uint64_t bytes;
  std::function<void(std::ostream&)> write_bytes;
};

// A block of an array held in memory.
ArrayBlock stored_block(std::string type, std::string name, int components, const void* data, std::uint64_t bytes) {
  return {std::move(type), std::move(name), components, bytes, [data, bytes](std::ostream& out) {
            out.write(static_cast<const char*>(data), static_cast<std::streamsize>(bytes));
          }};
}

// A block of `count` values of type T, value(i) each, derived from the mesh as it is
// written through a small buffer, never held whole: a million-quad mesh's offsets,
// types and face numbers took 13 bytes a quad at the writer's peak.
template <typename T, typename Value>
ArrayBlock generated_block(std::string type, std::string name, int components, std::size_t count, Value value) {
  return {std::move(type), std::move(name), components, count * sizeof(T), [count, value](std::ostream& out) {
            constexpr std::size_t kChunk = std::size_t{1} << 14;
            std::vector<T> buffer;
            buffer.reserve(std::min(count, kChunk));
            for (std::size_t i = 0; i < count; i += kChunk) {
              buffer.clear();
              for (std::size_t j = i; j < std::min(count, i + kChunk); ++j) buffer.push_back(value(j));
              out.write(reinterpret_cast<const char*>(buffer.data()),
                        static_cast<std::streamsize>(buffer.size() * sizeof(T)));
            }
          }};
}

// The values of a generated array, for the ASCII encoding (small meshes).
template <typename T, typename Value>
std::vector<T> values_of(std::size_t count, const Value& value) {
  std::vector<T> values;
  values.reserve(count);
  for (std::size_t i = 0; i < count; ++i) values.push_back(value(i));
  return values;
}

void write_header(std::ostream& out, const ShapeMesh& mesh) {
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
      << (little_endian() ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt64\">\n"
      << "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << mesh.nodes.size() << "\" NumberOfCells=\""
      << mesh.quads.size() << "\">\n";
}

void write_data_array_tag(std::ostream& out, const ArrayBlock& a, const std::string& format,
                          std::uint64_t offset) {
  out << "        <DataArray type=\"" << a.type << "\" Name=\"" << a.name << "\"";
  if (a.components > 1) out << " NumberOfComponents=\"" << a.components << "\"";
  out << " format=\"" << format << "\"";
  if (format == "appended") out << " offset=\"" << offset << "\"/>\n";
  else out << ">\n";
}

template <typename T>
void write_ascii_values(std::ostream& out, const T* values, std::size_t count, int per_line) {
  std::string line;
  char buffer[32];
  for (std::size_t i = 0; i < count; ++i) {
    // Shortest round-trip text for doubles; plain integers otherwise (no char output).
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, +values[i]);
    line.append(buffer, r.ptr);
    line += (i + 1) % per_line == 0 || i + 1 == count ? '\n' : ' ';
    if (line.size() > (1u << 16)) { out << line; line.clear(); }
  }
  out << line;
}

}  // namespace

void write_vtu(std::ostream& out, const ShapeMesh& mesh, VtuEncoding encoding) {
  check_shape_mesh(mesh);
  const std::size_t cells = mesh.quads.size();
  // Vec3 and Quad are plain arrays of double / int32 without padding, so their
  // storage is the VTK array layout itself.
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
  static_assert(sizeof(Quad) == 4 * sizeof(std::int32_t), "Quad must be four packed int32");
  const int per_cell = mesh.nodes_per_element();
  const std::uint8_t cell_type = mesh.second_order() ? vtk_quadratic_quad : vtk_quad;
  // Each value a function of its index: cell k's end in the connectivity, its type,
  // its face, and (second order) its corners then edge middles, VTK's quadratic
  // quad order.
  const auto offset = [per_cell](std::size_t k) { return per_cell * static_cast<std::int64_t>(k + 1); };
  const auto type = [cell_type](std::size_t) { return cell_type; };
  // The face of each quad: the face records own consecutive quads (check_shape_mesh).
  std::vector<std::int64_t> face_ends;
  for (const FaceMesh& f : mesh.faces) face_ends.push_back(f.first_quad + f.quad_count);
  const auto face = [&mesh, &face_ends](std::size_t k) {
    const auto record = std::upper_bound(face_ends.begin(), face_ends.end(), static_cast<std::int64_t>(k));
    return static_cast<std::int32_t>(mesh.faces[record - face_ends.begin()].face);
  };
  const auto element_node = [&mesh](std::size_t i) { return mesh.element_nodes(i / 8).ids[i % 8]; };

  const ArrayBlock points = stored_block("Float64", "Points", 3, mesh.nodes.data(), mesh.nodes.size() * sizeof(Vec3));
  const ArrayBlock connectivity =
      mesh.second_order()
          ? generated_block<std::int32_t>("Int32", "connectivity", 1, 8 * cells, element_node)
          : stored_block("Int32", "connectivity", 1, mesh.quads.data(), cells * 4 * sizeof(std::int32_t));
  const ArrayBlock offset_block = generated_block<std::int64_t>("Int64", "offsets", 1, cells, offset);
  const ArrayBlock type_block = generated_block<std::uint8_t>("UInt8", "types", 1, cells, type);
  const ArrayBlock face_block = generated_block<std::int32_t>("Int32", "face", 1, cells, face);
  // Cell data: the face of each quad, and its quality when the mesh carries it
  // (ParaView colours by any of them).
  std::vector<const ArrayBlock*> cell_blocks{&face_block};
  const bool has_quality = cells > 0 && mesh.scaled_jacobian.size() == cells && mesh.lee_lo.size() == cells;
  const ArrayBlock jacobian_block =
      stored_block("Float64", "scaled_jacobian", 1, mesh.scaled_jacobian.data(), cells * sizeof(double));
  const ArrayBlock lee_lo_block = stored_block("Float64", "lee_lo", 1, mesh.lee_lo.data(), cells * sizeof(double));
  if (has_quality) cell_blocks.insert(cell_blocks.end(), {&jacobian_block, &lee_lo_block});

  write_header(out, mesh);
  if (encoding == VtuEncoding::appended_raw) {
    // Each block of the appended section is a UInt64 byte count and the bytes.
    std::uint64_t appended = 0;
    auto tag = [&](const ArrayBlock& a) {
      write_data_array_tag(out, a, "appended", appended);
      appended += sizeof(std::uint64_t) + a.bytes;
    };
    out << "      <Points>\n";
    tag(points);
    out << "      </Points>\n      <Cells>\n";
    tag(connectivity);
    tag(offset_block);
    tag(type_block);
    out << "      </Cells>\n      <CellData Scalars=\"face\">\n";
    for (const ArrayBlock* a : cell_blocks) tag(*a);
    out << "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n"
        << "  <AppendedData encoding=\"raw\">\n   _";
    std::vector<const ArrayBlock*> blocks{&points, &connectivity, &offset_block, &type_block};
    blocks.insert(blocks.end(), cell_blocks.begin(), cell_blocks.end());
    for (const ArrayBlock* a : blocks) {
      out.write(reinterpret_cast<const char*>(&a->bytes), sizeof a->bytes);
      a->write_bytes(out);
    }
    out << "\n  </AppendedData>\n</VTKFile>\n";
    return;
  }

  // ASCII: meant for small meshes, so flat copies of the arrays are fine.
  std::vector<double> xyz;
  xyz.reserve(3 * mesh.nodes.size());
  for (const Vec3& p : mesh.nodes) xyz.insert(xyz.end(), {p.x, p.y, p.z});
  std::vector<std::int32_t> ids;
  ids.reserve(per_cell * cells);
  for (std::size_t k = 0; k < cells; ++k) {
    for (NodeId id : mesh.element_nodes(k)) ids.push_back(id);
  }
  auto block = [&](const ArrayBlock& a, const auto& values, int per_line) {
    write_data_array_tag(out, a, "ascii", 0);
    write_ascii_values(out, values.data(), values.size(), per_line);
    out << "        </DataArray>\n";
  };
  out << "      <Points>\n";
  block(points, xyz, 3);
  out << "      </Points>\n      <Cells>\n";
  block(connectivity, ids, per_cell);
  block(offset_block, values_of<std::int64_t>(cells, offset), 16);
  block(type_block, values_of<std::uint8_t>(cells, type), 32);
  out << "      </Cells>\n      <CellData Scalars=\"face\">\n";
  block(face_block, values_of<std::int32_t>(cells, face), 32);
  if (has_quality) {
    block(jacobian_block, mesh.scaled_jacobian, 6);
    block(lee_lo_block, mesh.lee_lo, 6);
  }
  out << "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

void write_vtu_file(const std::string& path, const ShapeMesh& mesh, VtuEncoding encoding) {
  write_file_atomically(path, [&](std::ostream& out) { write_vtu(out, mesh, encoding); });
}

}  // namespace tquad
