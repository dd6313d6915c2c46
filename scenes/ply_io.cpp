// PLY (Turk's polygon file format): ascii, binary_little_endian and binary_big_endian 1.0.
// Read: element vertex (x y z, optional nx ny nz, s t / u v / texture_u texture_v /
// texture_s texture_t) and element face (list vertex_indices or vertex_index, any size,
// fan-triangulated); every other element and property is parsed and skipped.
// Written: binary_little_endian (or ascii) with float x y z [nx ny nz] [s t] and
// "property list uchar int vertex_indices".
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/input_guard.h"
#include "scenes/mesh_io.h"
#include "scenes/mesh_text_writer.h"
#include "scenes/polygon_fan.h"
#include "scenes/text_parse.h"

namespace rastrace {

namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool parse_type(std::string_view name, PlyType& type) {
  static constexpr struct {
    std::string_view name;
    PlyType type;
  } kTypes[] = {{"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
                {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
                {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
                {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
                {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
                {"float64", PlyType::Float64}};
  for (const auto& t : kTypes)
    if (t.name == name) {
      type = t.type;
      return true;
    }
  return false;
}

bool is_integer(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

// What a property means to the mesh.
enum Role { kSkip, kX, kY, kZ, kNX, kNY, kNZ, kU, kV, kIndices };

struct Property {
  std::string name;
  PlyType type = PlyType::Float32;
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;
  Role role = kSkip;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t header_line = 0;
  std::vector<Property> properties;
};

enum class Format { Ascii, BinaryLittle, BinaryBig };

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  std::size_t data_offset = 0;
  std::uint64_t data_line = 0;  // line number of the first data line (ascii)
};

Header parse_header(const std::string& path, std::string_view text) {
  TextLines lines(path, text);
  std::string_view line;
  if (!lines.next(line) || trim(line) != "ply") lines.fail("expected the PLY magic line 'ply'");
  Header header;
  bool have_format = false;
  while (true) {
    if (!lines.next(line)) lines.fail("file ends inside the header: expected 'end_header'");
    std::string_view rest = line;
    const std::string_view keyword = next_token(rest);
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") break;
    if (keyword == "format") {
      const std::string_view format = next_token(rest);
      const std::string_view version = next_token(rest);
      if (format == "ascii")
        header.format = Format::Ascii;
      else if (format == "binary_little_endian")
        header.format = Format::BinaryLittle;
      else if (format == "binary_big_endian")
        header.format = Format::BinaryBig;
      else
        lines.fail("expected format ascii, binary_little_endian or binary_big_endian, found " + describe_token(format));
      if (version != "1.0") lines.fail("expected PLY version 1.0, found " + describe_token(version));
      have_format = true;
    } else if (keyword == "element") {
      Element element;
      element.name = std::string(next_token(rest));
      const std::string_view count = next_token(rest);
      std::int64_t value = 0;
      if (element.name.empty() || !parse_number(count, value) || value < 0)
        lines.fail("expected 'element <name> <count>' with a non-negative count, found " + describe_token(trim(line)));
      element.count = static_cast<std::uint64_t>(value);
      element.header_line = lines.line_number();
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) lines.fail("property before any element: expected 'element <name> <count>' first");
      Property property;
      std::string_view type = next_token(rest);
      if (type == "list") {
        property.is_list = true;
        const std::string_view count_type = next_token(rest);
        if (!parse_type(count_type, property.count_type) || !is_integer(property.count_type))
          lines.fail("bad PLY property: list count type must be an integer type (uchar, int...), found " +
                     describe_token(count_type));
        type = next_token(rest);
      }
      if (!parse_type(type, property.type))
        lines.fail("bad PLY property: expected a type (char uchar short ushort int uint float double), found " +
                   describe_token(type));
      property.name = std::string(next_token(rest));
      if (property.name.empty()) lines.fail("bad PLY property: expected a property name after the type");
      header.elements.back().properties.push_back(std::move(property));
    } else {
      lines.fail("unexpected header line " + describe_token(keyword) +
                 ": expected format, element, property, comment or end_header");
    }
  }
  if (!have_format) lines.fail("header has no 'format' line");
  header.data_offset = lines.offset();
  header.data_line = lines.line_number() + 1;
  return header;
}

// Finds the vertex and face elements and gives their properties a role. Errors name the header line.
void assign_roles(const std::string& path, Header& header, Element*& vertex, Element*& face) {
  vertex = face = nullptr;
  for (Element& element : header.elements) {
    if (element.name == "vertex") vertex = &element;
    if (element.name == "face") face = &element;
  }
  if (!vertex) throw_in_file(path, "no 'element vertex' in the header");
  const auto find = [](Element& element, std::string_view name) -> Property* {
    for (Property& p : element.properties)
      if (p.name == name) return &p;
    return nullptr;
  };
  const char* const position_names[3] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis) {
    Property* p = find(*vertex, position_names[axis]);
    if (!p)
      throw_at_line(path, vertex->header_line, std::string("vertex element has no property ") + position_names[axis]);
    if (p->is_list)
      throw_at_line(path, vertex->header_line,
                    std::string("bad PLY property: vertex ") + position_names[axis] + " is a list, expected a scalar");
    p->role = static_cast<Role>(kX + axis);
  }
  Property* nx = find(*vertex, "nx");
  Property* ny = find(*vertex, "ny");
  Property* nz = find(*vertex, "nz");
  if (nx && ny && nz && !nx->is_list && !ny->is_list && !nz->is_list) {
    nx->role = kNX;
    ny->role = kNY;
    nz->role = kNZ;
  }
  static constexpr std::pair<std::string_view, std::string_view> kUvNames[] = {
      {"s", "t"}, {"u", "v"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
  for (const auto& [u_name, v_name] : kUvNames) {
    Property* u = find(*vertex, u_name);
    Property* v = find(*vertex, v_name);
    if (u && v && !u->is_list && !v->is_list) {
      u->role = kU;
      v->role = kV;
      break;
    }
  }
  if (face) {
    Property* indices = find(*face, "vertex_indices");
    if (!indices) indices = find(*face, "vertex_index");
    if (!indices)
      throw_at_line(path, face->header_line, "face element has no 'vertex_indices' (or 'vertex_index') list property");
    if (!indices->is_list || !is_integer(indices->type))
      throw_at_line(path, face->header_line,
                    "bad PLY property: " + indices->name + " must be a list of an integer type");
    indices->role = kIndices;
  }
}

// Reads values from ASCII data: tokens separated by whitespace, lines counted for errors.
class AsciiReader {
 public:
  AsciiReader(const std::string& path, std::string_view text, std::size_t offset, std::uint64_t line)
      : path_(path), text_(text), position_(offset), line_(line) {}

  double scalar(PlyType type, const char* what) {
    const std::string_view token = next(what);
    if (type == PlyType::Float32) {
      float value = 0.0f;  // parsed as float: the decimal rounds once, to the nearest float
      if (!parse_number(token, value))
        fail(std::string("expected a number for ") + what + ", found " + describe_token(token));
      return value;
    }
    if (type == PlyType::Float64) {
      double value = 0.0;
      if (!parse_number(token, value))
        fail(std::string("expected a number for ") + what + ", found " + describe_token(token));
      return value;
    }
    return static_cast<double>(integer(type, what, token));
  }
  std::int64_t integer(PlyType type, const char* what) { return integer(type, what, next(what)); }
  bool at_end() {
    skip_space();
    return position_ >= text_.size();
  }
  [[noreturn]] void fail(const std::string& message) const { throw_at_line(path_, line_, message); }

 private:
  std::int64_t integer(PlyType type, const char* what, std::string_view token) {
    std::int64_t value = 0;
    if (!is_integer(type)) {
      double d = 0.0;
      if (!parse_number(token, d) || d != std::floor(d) || std::fabs(d) > 9.0e15)
        fail(std::string("expected an integer for ") + what + ", found " + describe_token(token));
      return static_cast<std::int64_t>(d);
    }
    if (!parse_number(token, value))
      fail(std::string("expected an integer for ") + what + ", found " + describe_token(token));
    return value;
  }
  void skip_space() {
    while (position_ < text_.size()) {
      const char c = text_[position_];
      if (c == '\n')
        ++line_;
      else if (c != ' ' && c != '\t' && c != '\r')
        break;
      ++position_;
    }
  }
  std::string_view next(const char* what) {
    skip_space();
    if (position_ >= text_.size()) fail(std::string("file ends early: expected a value for ") + what);
    const std::size_t begin = position_;
    while (position_ < text_.size() && text_[position_] != ' ' && text_[position_] != '\t' &&
           text_[position_] != '\n' && text_[position_] != '\r')
      ++position_;
    return text_.substr(begin, position_ - begin);
  }

  const std::string& path_;
  std::string_view text_;
  std::size_t position_;
  std::uint64_t line_;
};

// Reads values from binary data of either byte order; every read is bounds-checked.
class BinaryReader {
 public:
  BinaryReader(const std::string& path, std::string_view data, std::size_t offset, bool big_endian)
      : path_(path), data_(data), position_(offset), swap_(big_endian != (std::endian::native == std::endian::big)) {}

  double scalar(PlyType type, const char* what) {
    switch (type) {
      case PlyType::Int8:
        return read<std::int8_t>(what);
      case PlyType::UInt8:
        return read<std::uint8_t>(what);
      case PlyType::Int16:
        return read<std::int16_t>(what);
      case PlyType::UInt16:
        return read<std::uint16_t>(what);
      case PlyType::Int32:
        return read<std::int32_t>(what);
      case PlyType::UInt32:
        return read<std::uint32_t>(what);
      case PlyType::Float32:
        return read<float>(what);
      case PlyType::Float64:
        return read<double>(what);
    }
    return 0.0;
  }
  std::int64_t integer(PlyType type, const char* what) {
    const double d = scalar(type, what);
    // Every 8- to 32-bit integer is exact in a double; a float type must hold a whole number.
    if (!is_integer(type) && (!(d == std::floor(d)) || std::fabs(d) > 9.0e15))
      fail(std::string("expected an integer value for ") + what);
    return static_cast<std::int64_t>(d);
  }
  bool at_end() const { return position_ >= data_.size(); }
  std::size_t position() const { return position_; }
  [[noreturn]] void fail(const std::string& message) const { throw_at_byte(path_, position_, message); }

 private:
  template <typename T>
  T read(const char* what) {
    if (data_.size() - position_ < sizeof(T))
      fail(std::string("file ends early (truncated?): expected ") + std::to_string(sizeof(T)) + " bytes for " + what);
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, data_.data() + position_, sizeof(T));
    if (swap_) std::reverse(bytes, bytes + sizeof(T));
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    position_ += sizeof(T);
    return value;
  }

  const std::string& path_;
  std::string_view data_;
  std::size_t position_;
  bool swap_;
};

template <typename Reader>
void read_body(Reader& reader, const Header& header, const Element* vertex_element, bool normals, bool uvs,
               Mesh& mesh) {
  PolygonFan fan(mesh.indices, vertex_element->count);
  for (const Element& element : header.elements) {
    const bool is_vertex = &element == vertex_element;
    for (std::uint64_t record = 0; record < element.count; ++record) {
      float values[kIndices] = {};
      for (const Property& property : element.properties) {
        const char* what = property.name.c_str();
        if (property.is_list) {
          const std::int64_t n = reader.integer(property.count_type, what);
          if (n < 0)
            reader.fail(element.name + " " + std::to_string(record) + ": negative list length " + std::to_string(n));
          if (property.role == kIndices) {
            if (n < 3)
              reader.fail("face " + std::to_string(record) + ": expected at least 3 vertex indices, found " +
                          std::to_string(n));
            fan.begin_polygon();
            for (std::int64_t i = 0; i < n; ++i) {
              const std::int64_t index = reader.integer(property.type, what);
              if (!fan.add(index)) reader.fail(fan.range_error(index));
            }
          } else {
            for (std::int64_t i = 0; i < n; ++i) reader.scalar(property.type, what);
          }
        } else {
          const double value = reader.scalar(property.type, what);
          if (property.role != kSkip) {
            if (!std::isfinite(value) || std::fabs(value) > std::numeric_limits<float>::max())
              reader.fail(element.name + " " + std::to_string(record) + ": " + property.name +
                          " is not finite (or beyond float range)");
            values[property.role] = static_cast<float>(value);
          }
        }
      }
      if (is_vertex) {
        mesh.positions.emplace_back(values[kX], values[kY], values[kZ]);
        if (normals) mesh.normals.emplace_back(values[kNX], values[kNY], values[kNZ]);
        if (uvs) mesh.uvs.emplace_back(values[kU], values[kV]);
      }
    }
  }
}

}  // namespace

Mesh load_ply(const std::string& path) {
  const std::string data = read_whole_file(path);
  Header header = parse_header(path, data);
  Element* vertex = nullptr;
  Element* face = nullptr;
  assign_roles(path, header, vertex, face);
  if (vertex->count > 0xffffffffull)
    throw_at_line(path, vertex->header_line, "vertex count too large (at most 4294967295)");

  // Every record of an element with properties reads at least one value, so the loop over its
  // count stops at the file's end; an element without any reads nothing and is bounded here.
  for (const Element& element : header.elements)
    if (element.properties.empty())
      check_empty_records(
          element.count, path + ":" + std::to_string(element.header_line) + ": element '" + excerpt(element.name) + "'",
          "records");

  Mesh mesh;
  mesh.name = path;
  // A record takes at least one byte (binary) or two (ascii): cap reservations by the file size.
  const std::size_t plausible = data.size() - header.data_offset + 1;
  const std::size_t vertices = std::min<std::size_t>(vertex->count, plausible);
  mesh.positions.reserve(vertices);
  bool has_normals = false, has_uvs = false;
  for (const Property& p : vertex->properties) {
    has_normals |= p.role == kNX;
    has_uvs |= p.role == kU;
  }
  if (has_normals) mesh.normals.reserve(vertices);
  if (has_uvs) mesh.uvs.reserve(vertices);
  if (face) mesh.indices.reserve(std::min<std::size_t>(face->count, plausible) * 3);

  if (header.format == Format::Ascii) {
    AsciiReader reader(path, data, header.data_offset, header.data_line);
    read_body(reader, header, vertex, has_normals, has_uvs, mesh);
    if (!reader.at_end())
      reader.fail("unexpected data after the last element (does the header give the wrong counts?)");
  } else {
    BinaryReader reader(path, data, header.data_offset, header.format == Format::BinaryBig);
    read_body(reader, header, vertex, has_normals, has_uvs, mesh);
    if (!reader.at_end())
      reader.fail(std::to_string(data.size() - reader.position()) +
                  " bytes after the last element (does the header give the wrong counts or types?)");
  }
  return mesh;
}

void save_ply(const Mesh& mesh, const std::string& path, bool ascii) {
  const bool normals = mesh.normals.size() == mesh.vertex_count() && !mesh.normals.empty();
  const bool uvs = mesh.uvs.size() == mesh.vertex_count() && !mesh.uvs.empty();
  std::string out;
  out += "ply\nformat ";
  out += ascii ? "ascii" : "binary_little_endian";
  out += " 1.0\ncomment written by rastrace\nelement vertex ";
  append_number(out, mesh.vertex_count());
  out += "\nproperty float x\nproperty float y\nproperty float z\n";
  if (normals) out += "property float nx\nproperty float ny\nproperty float nz\n";
  if (uvs) out += "property float s\nproperty float t\n";
  out += "element face ";
  append_number(out, mesh.face_count());
  out += "\nproperty list uchar int vertex_indices\nend_header\n";

  const std::size_t floats_per_vertex = 3 + (normals ? 3 : 0) + (uvs ? 2 : 0);
  if (ascii) {
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
      append_components(out, mesh.positions[v]);
      if (normals) out += ' ', append_components(out, mesh.normals[v]);
      if (uvs) out += ' ', append_components(out, mesh.uvs[v]);
      out += '\n';
    }
    append_triangle_lines(out, mesh.indices);
  } else {
    const std::size_t header_size = out.size();
    out.resize(header_size + mesh.vertex_count() * floats_per_vertex * 4 + mesh.face_count() * 13);
    char* cursor = out.data() + header_size;
    const auto put = [&cursor](const void* value, std::size_t size) {
      unsigned char bytes[4];
      std::memcpy(bytes, value, size);
      if constexpr (std::endian::native == std::endian::big) std::reverse(bytes, bytes + size);
      std::memcpy(cursor, bytes, size);
      cursor += size;
    };
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
      put(&mesh.positions[v].x, 4), put(&mesh.positions[v].y, 4), put(&mesh.positions[v].z, 4);
      if (normals) put(&mesh.normals[v].x, 4), put(&mesh.normals[v].y, 4), put(&mesh.normals[v].z, 4);
      if (uvs) put(&mesh.uvs[v].x, 4), put(&mesh.uvs[v].y, 4);
    }
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const std::uint8_t three = 3;
      put(&three, 1);
      for (int k = 0; k < 3; ++k) {
        if (mesh.indices[i + k] > 0x7fffffffu) throw_in_file(path, "vertex index too large for a PLY int");
        const auto index = static_cast<std::int32_t>(mesh.indices[i + k]);
        put(&index, 4);
      }
    }
  }
  write_whole_file(path, out);
}

}  // namespace rastrace
