// OFF (Geomview's Object File Format) as CGAL writes it:
//   [ST][C][N]OFF            header keyword (optionally followed by the counts on the same line)
//   V F E                    vertex, face and edge counts (E ignored)
//   x y z [nx ny nz] [colour] [s t]        V vertex lines
//   n i0 i1 ... i(n-1) [colour]            F face lines, fan-triangulated
// '#' starts a comment; blank lines are skipped.
#include <algorithm>
#include <cmath>
#include <string>

#include "scenes/mesh_io.h"
#include "scenes/mesh_text_writer.h"
#include "scenes/polygon_fan.h"
#include "scenes/text_parse.h"

namespace rastrace {

namespace {

// Skips blank and comment-only lines; the returned line has its comment removed.
bool next_content_line(TextLines& lines, std::string_view& line) {
  while (lines.next(line)) {
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    if (!trim(line).empty()) return true;
  }
  return false;
}

std::int64_t read_count(TextLines& lines, std::string_view& rest, const char* what) {
  const std::string_view token = next_token(rest);
  std::int64_t value = 0;
  if (!parse_number(token, value) || value < 0)
    lines.fail(std::string("expected the ") + what + " count (a non-negative integer), found " + describe_token(token));
  return value;
}

}  // namespace

Mesh load_off(const std::string& path) {
  const std::string text = read_whole_file(path);
  TextLines lines(path, text);
  std::string_view line;
  if (!next_content_line(lines, line)) lines.fail("empty file: expected an OFF header");
  std::string_view rest = line;
  const std::string_view keyword = next_token(rest);
  // [ST][C][N]OFF; the 4D and n-dimensional variants have no meaning for triangle meshes.
  std::string_view k = keyword;
  const bool has_uv = k.starts_with("ST");
  if (has_uv) k.remove_prefix(2);
  const bool has_colour = k.starts_with("C");
  if (has_colour) k.remove_prefix(1);
  const bool has_normal = k.starts_with("N");
  if (has_normal) k.remove_prefix(1);
  if (k != "OFF")
    lines.fail("expected an OFF header ('OFF', 'NOFF', 'COFF', 'STOFF'...), found " + describe_token(keyword));
  if (trim(rest).empty()) {
    if (!next_content_line(lines, line))
      lines.fail("file ends after the header: expected 'vertices faces edges' counts");
    rest = line;
  }
  const std::int64_t vertex_count = read_count(lines, rest, "vertex");
  const std::int64_t face_count = read_count(lines, rest, "face");
  if (vertex_count > (std::int64_t{1} << 32) - 1 || face_count > (std::int64_t{1} << 32) - 1)
    lines.fail("vertex or face count too large (at most 4294967295)");

  Mesh mesh;
  mesh.name = path;
  const auto vertices = static_cast<std::size_t>(vertex_count);
  // Reserve only what the file could hold: a count from a corrupt header must not allocate wildly.
  const std::size_t plausible = text.size() / 6 + 1;
  mesh.positions.reserve(std::min(vertices, plausible));
  if (has_normal) mesh.normals.reserve(std::min(vertices, plausible));
  if (has_uv) mesh.uvs.reserve(std::min(vertices, plausible));
  for (std::size_t v = 0; v < vertices; ++v) {
    if (!next_content_line(lines, line))
      lines.fail("file ends after " + std::to_string(v) + " of " + std::to_string(vertices) + " vertices");
    rest = line;
    float x[3];
    for (float& c : x) {
      const std::string_view token = next_token(rest);
      if (!parse_number(token, c))
        lines.fail("vertex " + std::to_string(v) + ": expected a coordinate, found " + describe_token(token));
      if (!std::isfinite(c))
        lines.fail("vertex " + std::to_string(v) + ": coordinate " + describe_token(token) + " is not finite");
    }
    mesh.positions.emplace_back(x[0], x[1], x[2]);
    if (has_normal) {
      float n[3];
      for (float& c : n) {
        const std::string_view token = next_token(rest);
        if (!parse_number(token, c) || !std::isfinite(c))
          lines.fail("vertex " + std::to_string(v) + ": expected a finite normal component (NOFF), found " +
                     describe_token(token));
      }
      mesh.normals.emplace_back(n[0], n[1], n[2]);
    }
    if (has_uv) {
      // Colours between normal and texture coordinates have 1 to 4 values: s t are the last two.
      std::string_view tokens[8];
      std::size_t count = 0;
      for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
        tokens[count % 8] = token;
        ++count;
      }
      float st[2];
      if (count < 2 || !parse_number(tokens[(count - 2) % 8], st[0]) || !parse_number(tokens[(count - 1) % 8], st[1]) ||
          !std::isfinite(st[0]) || !std::isfinite(st[1]))
        lines.fail("vertex " + std::to_string(v) +
                   ": expected texture coordinates 's t' at the end of the line (STOFF)");
      mesh.uvs.emplace_back(st[0], st[1]);
    }
  }

  const auto faces = static_cast<std::size_t>(face_count);
  mesh.indices.reserve(std::min(faces, plausible) * 3);
  PolygonFan fan(mesh.indices, static_cast<std::uint64_t>(vertex_count));
  for (std::size_t f = 0; f < faces; ++f) {
    if (!next_content_line(lines, line))
      lines.fail("file ends after " + std::to_string(f) + " of " + std::to_string(faces) + " faces");
    rest = line;
    std::string_view token = next_token(rest);
    std::int64_t n = 0;
    if (!parse_number(token, n) || n < 3)
      lines.fail("face " + std::to_string(f) + ": expected the number of its vertices (at least 3), found " +
                 describe_token(token));
    fan.begin_polygon();
    for (std::int64_t i = 0; i < n; ++i) {
      token = next_token(rest);
      std::int64_t index = 0;
      if (!parse_number(token, index))
        lines.fail("face " + std::to_string(f) + ": expected " + std::to_string(n) + " vertex indices, found " +
                   describe_token(token) + " at position " + std::to_string(i));
      if (!fan.add(index)) lines.fail(fan.range_error(index));
    }
  }
  if (next_content_line(lines, line))
    lines.fail("unexpected data after the last of " + std::to_string(faces) +
               " faces (does the header give the wrong counts?): " + describe_token(trim(line)));
  return mesh;
}

void save_off(const Mesh& mesh, const std::string& path) {
  std::string out;
  out.reserve(mesh.vertex_count() * 36 + mesh.face_count() * 24 + 64);
  out += "OFF\n";
  append_number(out, mesh.vertex_count());
  out += ' ';
  append_number(out, mesh.face_count());
  out += " 0\n";
  append_attribute_lines(out, "", mesh.positions);
  append_triangle_lines(out, mesh.indices);
  write_whole_file(path, out);
}

}  // namespace rastrace
