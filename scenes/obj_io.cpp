// Wavefront OBJ + MTL.
// Read: v, vt, vn, f (any polygon, fan-triangulated; v, v/vt, v//vn, v/vt/vn; negative indices
// count back from the last element defined), usemtl (per-face material), mtllib (MTL: newmtl, Kd,
// d, Tr, map_Kd resolved relative to the MTL file). Other statements (o, g, s, l, p, ...) are
// ignored. A vertex is a distinct (v, vt, vn) triple, numbered in order of first appearance, so
// vertices are shared exactly as the file shares them. When every face corner indexes v, vt and
// vn in lockstep (the same number, as rastrace and many exporters write), vertex i is simply the
// i-th v line, unreferenced ones included: an OBJ written by save_obj reads back unchanged.
#include <cmath>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/error.h"
#include "scenes/mesh_io.h"
#include "scenes/mesh_text_writer.h"
#include "scenes/text_parse.h"

namespace rastrace {

namespace {

namespace fs = std::filesystem;

template <int N>
void read_floats(TextLines& lines, std::string_view& rest, float* out, int required, const char* what) {
  for (int i = 0; i < N; ++i) {
    const std::string_view token = next_token(rest);
    if (token.empty() && i >= required) {
      out[i] = 0.0f;
      continue;
    }
    if (!parse_number(token, out[i]))
      lines.fail(std::string("expected ") + std::to_string(required) + " numbers after '" + what + "', found " +
                 describe_token(token));
    if (!std::isfinite(out[i]))
      lines.fail(std::string("'") + what + "' value " + describe_token(token) + " is not finite");
  }
}

// "a.mtl" or "a b.mtl": the whole rest of the line if that names a file, else its first token.
fs::path resolve_reference(const fs::path& folder, std::string_view rest) {
  std::string name(trim(rest));
  for (char& c : name)
    if (c == '\\') c = '/';
  fs::path whole = folder / name;
  std::error_code error;  // a name the OS refuses (too long, ...) is a missing file, not a crash
  if (fs::exists(whole, error)) return whole;
  std::string_view tokens = name;
  return folder / std::string(next_token(tokens));
}

// map_Kd [-option args...] file: skips options and their numeric / on|off arguments.
std::string_view strip_map_options(std::string_view rest) {
  while (true) {
    std::string_view probe = rest;
    const std::string_view token = next_token(probe);
    if (!token.starts_with("-")) return trim(rest);
    rest = probe;
    while (true) {
      std::string_view look = rest;
      const std::string_view argument = next_token(look);
      double number = 0.0;
      if (argument.empty() || !(parse_number(argument, number) || argument == "on" || argument == "off")) break;
      rest = look;
    }
  }
}

void load_mtl(const fs::path& path, std::vector<Material>& materials,
              std::unordered_map<std::string, std::uint32_t>& by_name) {
  const std::string text = read_whole_file(path.string());
  TextLines lines(path.string(), text);
  const fs::path folder = path.parent_path();
  Material* current = nullptr;
  std::string_view line;
  while (lines.next(line)) {
    std::string_view rest = line;
    const std::string_view keyword = next_token(rest);
    if (keyword.empty() || keyword.starts_with("#")) continue;
    if (keyword == "newmtl") {
      const std::string name(trim(rest));
      if (name.empty()) lines.fail("expected a material name after 'newmtl'");
      const auto [it, inserted] = by_name.emplace(name, static_cast<std::uint32_t>(materials.size()));
      if (inserted) {
        materials.push_back(Material{});
        materials.back().name = name;
      }
      current = &materials[it->second];
      continue;
    }
    const bool known = keyword == "Kd" || keyword == "d" || keyword == "Tr" || keyword == "map_Kd";
    if (!known) continue;
    if (!current) lines.fail("'" + std::string(keyword) + "' before any 'newmtl': expected 'newmtl <name>' first");
    if (keyword == "Kd") {
      float rgb[3];
      read_floats<3>(lines, rest, rgb, 3, "Kd");
      current->diffuse = glm::vec4(rgb[0], rgb[1], rgb[2], current->diffuse.a);
    } else if (keyword == "d" || keyword == "Tr") {
      float value[1];
      read_floats<1>(lines, rest, value, 1, keyword == "d" ? "d" : "Tr");
      current->diffuse.a = keyword == "d" ? value[0] : 1.0f - value[0];
    } else {
      const std::string_view file = strip_map_options(rest);
      if (file.empty()) lines.fail("expected a texture file name after 'map_Kd'");
      std::string name(file);
      for (char& c : name)
        if (c == '\\') c = '/';
      const fs::path texture = (folder / name).lexically_normal();
      std::error_code error;
      if (!fs::is_regular_file(texture, error))
        lines.fail("map_Kd " + describe_token(file) + ": texture file " + texture.string() + " not found");
      current->texture_source.kind = TextureSource::Kind::File;
      current->texture_source.path = texture.string();
    }
  }
}

struct Corner {
  std::int64_t v, vt, vn;  // 0-based; -1: absent
};

// Resolves one OBJ index (1-based, or negative from the end) against the count defined so far.
std::int64_t resolve_index(TextLines& lines, std::string_view token, std::size_t defined, const char* kind,
                           const char* kinds) {
  std::int64_t index = 0;
  if (!parse_number(token, index))
    lines.fail(std::string("expected a ") + kind + " index, found " + describe_token(token));
  const auto count = static_cast<std::int64_t>(defined);
  if (index > 0 && index <= count) return index - 1;
  if (index < 0 && index >= -count) return count + index;  // not -index: INT64_MIN has no negation
  if (index == 0) lines.fail(std::string(kind) + " index 0: OBJ indices start at 1 (or count back from -1)");
  lines.fail(std::string(kind) + " index " + std::to_string(index) + " out of range: " + std::to_string(count) + " " +
             (count == 1 ? kind : kinds) + " defined so far");
}

}  // namespace

Mesh load_obj(const std::string& path) {
  const std::string text = read_whole_file(path);
  // OBJ is text: a NUL byte means UTF-16 or binary data, whose lines would all be skipped as
  // unknown statements and load as an empty mesh.
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
    throw_at_byte(path, nul, "NUL byte: expected OBJ text (ASCII or UTF-8), not UTF-16 or binary data");
  TextLines lines(path, text);
  const fs::path folder = fs::path(path).parent_path();

  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec2> texcoords;
  std::vector<Corner> corners;              // three per triangle
  std::vector<std::int64_t> face_material;  // per triangle; -1: before any usemtl
  std::vector<Material> materials;
  std::unordered_map<std::string, std::uint32_t> by_name;
  bool have_library = false;
  std::int64_t current_material = -1;
  std::vector<Corner> polygon;

  std::string_view line;
  while (lines.next(line)) {
    std::string_view rest = line;
    const std::string_view keyword = next_token(rest);
    if (keyword.empty() || keyword.starts_with("#")) continue;
    if (keyword == "v") {
      float p[3];
      read_floats<3>(lines, rest, p, 3, "v");
      positions.emplace_back(p[0], p[1], p[2]);
    } else if (keyword == "vt") {
      float t[2];
      read_floats<2>(lines, rest, t, 1, "vt");
      texcoords.emplace_back(t[0], t[1]);
    } else if (keyword == "vn") {
      float n[3];
      read_floats<3>(lines, rest, n, 3, "vn");
      normals.emplace_back(n[0], n[1], n[2]);
    } else if (keyword == "f") {
      polygon.clear();
      for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
        Corner corner{-1, -1, -1};
        const std::size_t slash = token.find('/');
        corner.v = resolve_index(lines, token.substr(0, slash), positions.size(), "vertex", "vertices");
        if (slash != std::string_view::npos) {
          std::string_view tail = token.substr(slash + 1);
          const std::size_t slash2 = tail.find('/');
          const std::string_view vt = tail.substr(0, slash2);
          if (!vt.empty())
            corner.vt = resolve_index(lines, vt, texcoords.size(), "texture coordinate", "texture coordinates");
          if (slash2 != std::string_view::npos) {
            const std::string_view vn = tail.substr(slash2 + 1);
            if (!vn.empty()) corner.vn = resolve_index(lines, vn, normals.size(), "normal", "normals");
          }
        }
        polygon.push_back(corner);
      }
      if (polygon.size() < 3)
        lines.fail("face with " + std::to_string(polygon.size()) + " vertices: expected at least 3");
      for (std::size_t i = 2; i < polygon.size(); ++i) {
        corners.insert(corners.end(), {polygon[0], polygon[i - 1], polygon[i]});
        face_material.push_back(current_material);
      }
    } else if (keyword == "mtllib") {
      if (trim(rest).empty()) lines.fail("expected an MTL file name after 'mtllib'");
      const fs::path library = resolve_reference(folder, rest);
      std::error_code error;
      if (!fs::exists(library, error)) lines.fail("mtllib: material library " + library.string() + " not found");
      load_mtl(library, materials, by_name);
      have_library = true;
    } else if (keyword == "usemtl") {
      const std::string name(trim(rest));
      if (name.empty()) lines.fail("expected a material name after 'usemtl'");
      const auto it = by_name.find(name);
      if (it != by_name.end()) {
        current_material = it->second;
      } else {
        if (have_library) lines.fail("usemtl " + describe_token(name) + ": no such material in the mtllib files");
        by_name.emplace(name, static_cast<std::uint32_t>(materials.size()));
        current_material = static_cast<std::int64_t>(materials.size());
        materials.push_back(Material{});
        materials.back().name = name;
      }
    }
  }

  if (corners.empty())
    throw_in_file(path, "no faces: expected an OBJ mesh with at least one 'f' statement");
  Mesh mesh;
  mesh.name = path;
  // Lockstep files (each corner's vt and vn equal to its v, or absent throughout) keep v order.
  bool any_vt = false, all_vt = true, any_vn = false, all_vn = true, lockstep = true;
  for (const Corner& c : corners) {
    any_vt |= c.vt >= 0, all_vt &= c.vt >= 0, any_vn |= c.vn >= 0, all_vn &= c.vn >= 0;
    lockstep &= (c.vt < 0 || c.vt == c.v) && (c.vn < 0 || c.vn == c.v);
  }
  lockstep &= (!any_vt || (all_vt && texcoords.size() == positions.size())) &&
              (!any_vn || (all_vn && normals.size() == positions.size()));
  if (lockstep) {
    mesh.positions = std::move(positions);
    if (any_vt) mesh.uvs = std::move(texcoords);
    if (any_vn) mesh.normals = std::move(normals);
    mesh.indices.reserve(corners.size());
    for (const Corner& c : corners) mesh.indices.push_back(static_cast<std::uint32_t>(c.v));
  } else {
    // Distinct triples in order of first appearance; chains of vertices per position index.
    std::vector<std::int64_t> head(positions.size(), -1), next;
    std::vector<Corner> unique;
    mesh.indices.reserve(corners.size());
    for (const Corner& c : corners) {
      std::int64_t found = head[static_cast<std::size_t>(c.v)];
      while (found >= 0 &&
             (unique[static_cast<std::size_t>(found)].vt != c.vt || unique[static_cast<std::size_t>(found)].vn != c.vn))
        found = next[static_cast<std::size_t>(found)];
      if (found < 0) {
        found = static_cast<std::int64_t>(unique.size());
        unique.push_back(c);
        next.push_back(head[static_cast<std::size_t>(c.v)]);
        head[static_cast<std::size_t>(c.v)] = found;
      }
      mesh.indices.push_back(static_cast<std::uint32_t>(found));
    }
    mesh.positions.reserve(unique.size());
    for (const Corner& c : unique) {
      mesh.positions.push_back(positions[static_cast<std::size_t>(c.v)]);
      if (any_vt) mesh.uvs.push_back(c.vt >= 0 ? texcoords[static_cast<std::size_t>(c.vt)] : glm::vec2(0.0f));
      if (any_vn) mesh.normals.push_back(c.vn >= 0 ? normals[static_cast<std::size_t>(c.vn)] : glm::vec3(0.0f));
    }
  }

  if (!materials.empty()) {
    std::uint32_t fallback = 0;
    bool need_fallback = false;
    for (const std::int64_t m : face_material) need_fallback |= m < 0;
    if (need_fallback) {
      fallback = static_cast<std::uint32_t>(materials.size());
      materials.push_back(Material{});
      materials.back().name = "default";
    }
    mesh.face_material.reserve(face_material.size());
    for (const std::int64_t m : face_material)
      mesh.face_material.push_back(m < 0 ? fallback : static_cast<std::uint32_t>(m));
    mesh.materials = std::move(materials);
  }
  return mesh;
}

void save_obj(const Mesh& mesh, const std::string& path) {
  const bool uvs = !mesh.uvs.empty() && mesh.uvs.size() == mesh.vertex_count();
  const bool normals = !mesh.normals.empty() && mesh.normals.size() == mesh.vertex_count();
  const fs::path obj_path(path);
  const fs::path folder = obj_path.parent_path();
  std::string out = "# written by rastrace\n";

  std::vector<std::string> names;
  if (!mesh.materials.empty()) {
    fs::path mtl_path = obj_path;
    mtl_path.replace_extension(".mtl");
    std::string mtl = "# written by rastrace\n";
    for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
      const Material& material = mesh.materials[m];
      std::string name = material.name.empty() ? "material" + std::to_string(m) : material.name;
      for (std::size_t k = 0; k < m; ++k)
        if (names[k] == name) name += "_" + std::to_string(m);
      names.push_back(name);
      mtl += "newmtl " + name + "\nKd ";
      append_components(mtl, glm::vec3(material.diffuse));
      mtl += "\nd ";
      append_number(mtl, material.diffuse.a);
      mtl += '\n';
      if (material.texture_source.kind == TextureSource::Kind::File) {
        const fs::path texture = fs::absolute(material.texture_source.path);
        const fs::path relative = texture.lexically_relative(fs::absolute(folder.empty() ? fs::path(".") : folder));
        mtl += "map_Kd " + (relative.empty() ? texture : relative).generic_string() + "\n";
      } else if (material.texture_source.kind != TextureSource::Kind::None) {
        mtl += "# procedural texture: not expressible in MTL\n";
      }
    }
    write_whole_file(mtl_path, mtl);
    out += "mtllib " + mtl_path.filename().string() + "\n";
  }

  append_attribute_lines(out, "v ", mesh.positions);
  if (uvs) append_attribute_lines(out, "vt ", mesh.uvs);
  if (normals) append_attribute_lines(out, "vn ", mesh.normals);
  std::int64_t written_material = -1;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (!names.empty() && static_cast<std::int64_t>(mesh.material_of(f)) != written_material) {
      written_material = mesh.material_of(f);
      if (static_cast<std::size_t>(written_material) >= names.size())
        throw_in_file(path, "face " + std::to_string(f) + " uses material " + std::to_string(written_material) +
                                " of " + std::to_string(names.size()));
      out += "usemtl " + names[static_cast<std::size_t>(written_material)] + "\n";
    }
    out += 'f';
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t index = std::uint64_t{mesh.indices[f * 3 + k]} + 1;
      out += ' ';
      append_number(out, index);
      if (uvs || normals) {
        out += '/';
        if (uvs) append_number(out, index);
        if (normals) {
          out += '/';
          append_number(out, index);
        }
      }
    }
    out += '\n';
  }
  write_whole_file(path, out);
}

}  // namespace rastrace
