// Scenes from JSON files (format in docs/scene-format.md), from plain mesh files, or built in.
#include "scenes/scene_io.h"

#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <tuple>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/input_guard.h"
#include "scenes/bounding_box.h"
#include "scenes/builtin_scenes.h"
#include "scenes/mesh_io.h"
#include "scenes/procedural.h"
#include "scenes/text_parse.h"
#include "scenes/texture_io.h"

#ifndef RASTRACE_DATA_DIR
#error "scenes/CMakeLists.txt must define RASTRACE_DATA_DIR"
#endif

namespace rastrace {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Reads a JSON scene, naming every wrong value by its path in the document ("objects[1].camera").
class SceneReader {
 public:
  SceneReader(std::string file) : file_(std::move(file)), folder_(fs::path(file_).parent_path()) {}

  Scene read(const json& root) {
    expect_object(root, "scene");
    allow_keys(root, "scene", {"name", "viewport", "background", "camera", "camera_path", "objects"});
    Scene scene;
    scene.name = root.contains("name") ? string(root["name"], "name") : file_;
    if (root.contains("viewport")) {
      const json& viewport = root["viewport"];
      expect_object(viewport, "viewport");
      allow_keys(viewport, "viewport", {"width", "height"});
      scene.width = integer(required(viewport, "viewport", "width"), "viewport.width", 1, 16384);
      scene.height = integer(required(viewport, "viewport", "height"), "viewport.height", 1, 16384);
    }
    if (root.contains("background")) scene.background = colour(root["background"], "background");
    const json& objects = required(root, "scene", "objects");
    if (!objects.is_array() || objects.empty()) fail("objects", "a non-empty array of objects");
    for (std::size_t i = 0; i < objects.size(); ++i)
      scene.objects.push_back(object(objects[i], "objects[" + std::to_string(i) + "]"));
    if (root.contains("camera")) {
      scene.camera = camera(root["camera"]);
    } else {
      const BoundingBox box = bounding_box(scene);
      scene.camera = frame_bounds(box.lo, box.hi, static_cast<float>(scene.width) / static_cast<float>(scene.height));
    }
    if (root.contains("camera_path")) scene.camera_path = camera_path(root["camera_path"], scene.camera);
    return scene;
  }

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& expected) const {
    throw_in_file(file_, where + ": expected " + expected);
  }
  static std::string kind(const json& value) { return value.is_null() ? "null" : value.type_name(); }
  // A value as the error quotes it: its JSON, cut to a short prefix (a value may be megabytes).
  static std::string shown(const json& value) { return excerpt(value.dump(), 40); }
  void expect_object(const json& value, const std::string& where) const {
    if (!value.is_object()) fail(where, "an object, found " + kind(value));
  }
  void allow_keys(const json& value, const std::string& where, std::initializer_list<const char*> keys) const {
    for (const auto& [key, ignored] : value.items()) {
      bool known = false;
      std::string list;
      for (const char* k : keys) {
        known |= key == k;
        list += list.empty() ? k : std::string(", ") + k;
      }
      if (!known) fail(where + "." + excerpt(key), "no such key; known keys here: " + list);
    }
  }
  const json& required(const json& value, const std::string& where, const char* key) const {
    if (!value.contains(key)) fail(where, std::string("a key \"") + key + "\"");
    return value[key];
  }
  std::string string(const json& value, const std::string& where) const {
    if (!value.is_string()) fail(where, "a string, found " + kind(value));
    return value.get<std::string>();
  }
  double number(const json& value, const std::string& where) const {
    if (!value.is_number()) fail(where, "a number, found " + kind(value));
    const double d = value.get<double>();
    // Every scene number ends up a float: 1e300 would silently become infinity.
    if (!std::isfinite(d) || std::fabs(d) > static_cast<double>(FLT_MAX))
      fail(where, "a finite number within float range (magnitude at most 3.4e38)");
    return d;
  }
  int integer(const json& value, const std::string& where, int lo, int hi) const {
    if (!value.is_number_integer() || value.get<std::int64_t>() < lo || value.get<std::int64_t>() > hi)
      fail(where, "an integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ", found " + shown(value));
    return static_cast<int>(value.get<std::int64_t>());
  }
  glm::vec3 vec3(const json& value, const std::string& where) const {
    if (!value.is_array() || value.size() != 3) fail(where, "an array of 3 numbers, found " + shown(value));
    return {number(value[0], where + "[0]"), number(value[1], where + "[1]"), number(value[2], where + "[2]")};
  }
  glm::vec4 colour(const json& value, const std::string& where) const {
    if (!value.is_array() || (value.size() != 3 && value.size() != 4))
      fail(where, "a colour [r, g, b] or [r, g, b, a] with components in 0..1, found " + shown(value));
    glm::vec4 c(1.0f);
    for (std::size_t i = 0; i < value.size(); ++i) {
      const double x = number(value[i], where + "[" + std::to_string(i) + "]");
      if (x < 0.0 || x > 1.0)
        fail(where + "[" + std::to_string(i) + "]", "a colour component in 0..1, found " + shown(value[i]));
      c[static_cast<int>(i)] = static_cast<float>(x);
    }
    return c;
  }

  // A path relative to the scene file's folder, else to the data folder.
  std::string file_path(const json& value, const std::string& where) const {
    const std::string name = string(value, where);
    const fs::path path(name);
    std::error_code error;  // a name the OS refuses (too long, ...) is a missing file, not a crash
    if (path.is_absolute()) {
      if (!fs::exists(path, error)) fail(where, "an existing file; " + excerpt(name, 200) + " not found");
      return name;
    }
    const fs::path beside = folder_ / path;
    if (fs::exists(beside, error)) return beside.string();
    const fs::path in_data = fs::path(data_directory()) / path;
    if (fs::exists(in_data, error)) return in_data.string();
    fail(where, "an existing file; \"" + excerpt(name, 200) + "\" found neither in " +
                    (folder_.empty() ? std::string(".") : folder_.string()) + " nor in the data folder " +
                    data_directory());
  }

  Camera camera(const json& value) const {
    expect_object(value, "camera");
    allow_keys(value, "camera", {"eye", "target", "up", "fov_y", "near", "far"});
    Camera c;
    c.eye = vec3(required(value, "camera", "eye"), "camera.eye");
    c.target = vec3(required(value, "camera", "target"), "camera.target");
    if (value.contains("up")) c.up = vec3(value["up"], "camera.up");
    if (value.contains("fov_y")) c.fov_y_degrees = static_cast<float>(number(value["fov_y"], "camera.fov_y"));
    if (value.contains("near")) c.near_plane = static_cast<float>(number(value["near"], "camera.near"));
    if (value.contains("far")) c.far_plane = static_cast<float>(number(value["far"], "camera.far"));
    if (!(c.fov_y_degrees > 0.0f && c.fov_y_degrees < 180.0f))
      fail("camera.fov_y", "degrees between 0 and 180 (exclusive)");
    if (!(c.near_plane > 0.0f)) fail("camera.near", "a positive distance");
    if (!(c.far_plane > c.near_plane)) fail("camera.far", "a distance greater than camera.near");
    if (glm::length(c.target - c.eye) == 0.0f) fail("camera.target", "a point different from camera.eye");
    if (glm::length(glm::cross(c.target - c.eye, c.up)) == 0.0f)
      fail("camera.up", "a direction not parallel to the view direction");
    return c;
  }

  // Keyframes omitting up or fov_y take them from the static camera (`base`).
  CameraPath camera_path(const json& value, const Camera& base) const {
    expect_object(value, "camera_path");
    allow_keys(value, "camera_path", {"keyframes"});
    const json& keys = required(value, "camera_path", "keyframes");
    if (!keys.is_array() || keys.empty()) fail("camera_path.keyframes", "a non-empty array of keyframes");
    CameraPath path;
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const std::string at = "camera_path.keyframes[" + std::to_string(i) + "]";
      const json& k = keys[i];
      expect_object(k, at);
      allow_keys(k, at, {"frame", "eye", "target", "up", "fov_y"});
      CameraKeyframe key;
      key.frame = static_cast<std::uint32_t>(integer(required(k, at, "frame"), at + ".frame", 0, 1000000000));
      key.eye = vec3(required(k, at, "eye"), at + ".eye");
      key.target = vec3(required(k, at, "target"), at + ".target");
      key.up = k.contains("up") ? vec3(k["up"], at + ".up") : base.up;
      if (!(glm::length(key.up) > 0.0f)) fail(at + ".up", "a non-zero direction");
      key.up = glm::normalize(key.up);
      key.fov_y_degrees =
          k.contains("fov_y") ? static_cast<float>(number(k["fov_y"], at + ".fov_y")) : base.fov_y_degrees;
      path.keyframes.push_back(key);
      const std::string error = camera_path_error(path);
      if (!error.empty()) throw_in_file(file_, "camera_path." + error);
    }
    return path;
  }

  // Counts a procedural mesh's bytes (positions, normals, UVs, indices, face materials) into the
  // scene's total before it is generated, through the one allocation limit: each side is bounded,
  // but a scene of many 4096 x 4096 grids is not.
  void reserve_procedural_mesh(std::uint64_t vertices, std::uint64_t triangles, const std::string& where,
                               const char* what = "the scene's procedural meshes") {
    constexpr std::uint64_t kVertexBytes = sizeof(glm::vec3) * 2 + sizeof(glm::vec2);
    constexpr std::uint64_t kTriangleBytes = sizeof(std::uint32_t) * 4;
    procedural_mesh_bytes_ += vertices * kVertexBytes + triangles * kTriangleBytes;
    checked_bytes(procedural_mesh_bytes_, 1, file_ + ": " + where + ": " + what);
  }

  // A mesh file is read once however many objects list it (a scene of a few hundred bytes could
  // list one large file thousands of times); each object's copy counts into the scene's total of
  // mesh bytes, as a procedural mesh does, so the copies are bounded by the allocation limit.
  Mesh file_mesh(const std::string& path, const std::string& where) {
    auto it = file_meshes_.find(path);
    if (it == file_meshes_.end()) it = file_meshes_.emplace(path, load_mesh(path)).first;
    const Mesh& mesh = it->second;
    reserve_procedural_mesh(mesh.positions.size(), mesh.indices.size() / 3, where, "the scene's meshes");
    return mesh;
  }

  Mesh procedural_mesh(const json& value, const std::string& where) {
    allow_keys(value, where, {"procedural", "width", "height", "subdivisions", "segments", "repeat"});
    const std::string name = string(required(value, where, "procedural"), where + ".procedural");
    const auto get = [&](const char* key, int fallback, int lo, int hi) {
      return value.contains(key) ? integer(value[key], where + "." + key, lo, hi) : fallback;
    };
    if (name == "grid") {
      const int width = get("width", 16, 1, 4096), height = get("height", 16, 1, 4096);
      reserve_procedural_mesh(std::uint64_t(width + 1) * std::uint64_t(height + 1),
                              2 * std::uint64_t(width) * std::uint64_t(height), where);
      return make_grid(width, height);
    }
    if (name == "icosphere") {
      const int subdivisions = get("subdivisions", 3, 0, 8);
      const std::uint64_t faces = std::uint64_t{20} << (2 * subdivisions);
      reserve_procedural_mesh(faces / 2 + 2, faces, where);
      return make_icosphere(subdivisions);
    }
    if (name == "plane") {
      const float repeat =
          value.contains("repeat") ? static_cast<float>(number(value["repeat"], where + ".repeat")) : 1.0f;
      if (!(repeat > 0.0f)) fail(where + ".repeat", "a positive number");
      const int segments = get("segments", 1, 1, 4096);
      reserve_procedural_mesh(std::uint64_t(segments + 1) * std::uint64_t(segments + 1),
                              2 * std::uint64_t(segments) * std::uint64_t(segments), where);
      return make_plane(segments, repeat);
    }
    fail(where + ".procedural", "\"grid\", \"icosphere\" or \"plane\", found \"" + excerpt(name) + "\"");
  }

  glm::mat4 transform(const json& value, const std::string& where) const {
    expect_object(value, where);
    if (value.contains("matrix")) {
      allow_keys(value, where, {"matrix"});
      const json& m = value["matrix"];
      if (!m.is_array() || m.size() != 16) fail(where + ".matrix", "16 numbers, row by row");
      glm::mat4 result(1.0f);
      for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column)
          result[column][row] = static_cast<float>(number(m[static_cast<std::size_t>(row * 4 + column)],
                                                          where + ".matrix[" + std::to_string(row * 4 + column) + "]"));
      return result;
    }
    allow_keys(value, where, {"translate", "rotate", "scale"});
    glm::mat4 result(1.0f);
    if (value.contains("translate")) result = glm::translate(result, vec3(value["translate"], where + ".translate"));
    if (value.contains("rotate")) {
      const glm::vec3 degrees = vec3(value["rotate"], where + ".rotate");
      result = glm::rotate(result, glm::radians(degrees.z), glm::vec3(0, 0, 1));
      result = glm::rotate(result, glm::radians(degrees.y), glm::vec3(0, 1, 0));
      result = glm::rotate(result, glm::radians(degrees.x), glm::vec3(1, 0, 0));
    }
    if (value.contains("scale")) {
      const json& s = value["scale"];
      const glm::vec3 factors =
          s.is_number() ? glm::vec3(static_cast<float>(number(s, where + ".scale"))) : vec3(s, where + ".scale");
      if (factors.x == 0.0f || factors.y == 0.0f || factors.z == 0.0f) fail(where + ".scale", "non-zero factors");
      result = glm::scale(result, factors);
    }
    return result;
  }

  TextureSource texture(const json& value, const std::string& where) const {
    TextureSource source;
    if (value.is_null()) return source;
    if (value.is_string()) {
      source.kind = TextureSource::Kind::File;
      source.path = file_path(value, where);
      return source;
    }
    if (!value.is_object())
      fail(where, "a texture file name, a procedural texture object or null, found " + kind(value));
    allow_keys(value, where, {"procedural", "file", "size", "checks", "format"});
    if (value.contains("format"))
      source.format = parse_texture_format(string(value["format"], where + ".format"), where + ".format");
    if (value.contains("file")) {
      if (value.contains("procedural") || value.contains("size") || value.contains("checks"))
        fail(where, "either \"file\" or \"procedural\" (with \"size\" and \"checks\"), not both");
      source.kind = TextureSource::Kind::File;
      source.path = file_path(value["file"], where + ".file");
      return source;
    }
    const std::string name = string(required(value, where, "procedural"), where + ".procedural");
    if (name == "checker")
      source.kind = TextureSource::Kind::Checker;
    else if (name == "four_colour" || name == "four_color")
      source.kind = TextureSource::Kind::FourColour;
    else if (name == "gradient")
      source.kind = TextureSource::Kind::Gradient;
    else
      fail(where + ".procedural", "\"checker\", \"four_colour\" or \"gradient\", found \"" + excerpt(name) + "\"");
    if (value.contains("size")) source.size = integer(value["size"], where + ".size", 1, 16384);
    if (value.contains("checks")) source.checks = integer(value["checks"], where + ".checks", 1, source.size);
    return source;
  }

  SceneObject object(const json& value, const std::string& where) {
    expect_object(value, where);
    allow_keys(value, where, {"name", "mesh", "uv_projection", "transform", "material"});
    SceneObject result;
    const json& mesh = required(value, where, "mesh");
    if (mesh.is_string())
      result.mesh = file_mesh(file_path(mesh, where + ".mesh"), where + ".mesh");
    else if (mesh.is_object())
      result.mesh = procedural_mesh(mesh, where + ".mesh");
    else
      fail(where + ".mesh", "a mesh file name or a procedural mesh object, found " + kind(mesh));
    if (value.contains("name")) result.mesh.name = string(value["name"], where + ".name");
    if (value.contains("uv_projection")) {
      const std::string projection = string(value["uv_projection"], where + ".uv_projection");
      if (projection == "spherical")
        project_uvs_spherical(result.mesh);
      else if (projection == "planar_x")
        project_uvs_planar(result.mesh, 0);
      else if (projection == "planar_y")
        project_uvs_planar(result.mesh, 1);
      else if (projection == "planar_z")
        project_uvs_planar(result.mesh, 2);
      else
        fail(where + ".uv_projection",
             "\"spherical\", \"planar_x\", \"planar_y\" or \"planar_z\", found \"" + excerpt(projection) + "\"");
    }
    if (value.contains("transform")) result.transform = transform(value["transform"], where + ".transform");
    if (value.contains("material")) {
      const json& m = value["material"];
      const std::string at = where + ".material";
      expect_object(m, at);
      allow_keys(m, at, {"name", "colour", "color", "texture"});
      if (result.mesh.materials.empty()) result.mesh.materials.push_back(Material{});
      for (Material& material : result.mesh.materials) {
        if (m.contains("name")) material.name = string(m["name"], at + ".name");
        if (m.contains("colour")) material.diffuse = colour(m["colour"], at + ".colour");
        if (m.contains("color")) material.diffuse = colour(m["color"], at + ".color");
        if (m.contains("texture")) material.texture_source = texture(m["texture"], at + ".texture");
      }
      if (m.contains("texture") && !m["texture"].is_null() && result.mesh.uvs.empty())
        fail(at + ".texture", "a mesh with texture coordinates; this one has none: add \"uv_projection\"");
    }
    return result;
  }

  std::string file_;
  fs::path folder_;
  std::uint64_t procedural_mesh_bytes_ = 0;  // summed over the scene by reserve_procedural_mesh()
  std::map<std::string, Mesh> file_meshes_;  // by path, each read once
};

// Line of byte `offset` in `text` (1-based).
std::uint64_t line_of(const std::string& text, std::size_t offset) {
  std::uint64_t line = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}

// Scenes nest 5 levels deep; a limit far above that keeps recursive code (dump, destruction,
// the reader) off the stack's edge for documents with 10^5 nested brackets.
constexpr int kMaxJsonDepth = 64;

// Refuses nesting deeper than kMaxJsonDepth before the document is parsed. Brackets inside
// strings and comments do not count.
void check_json_depth(const std::string& text, const std::string& path) {
  int depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') {
      for (++i; i < text.size() && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
    } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
      const std::size_t end = text.find("*/", i + 2);
      i = end == std::string::npos ? text.size() : end + 1;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        throw_at_line(path, line_of(text, i),
                      "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels of [ and {");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

Scene load_json_scene(const std::string& path, std::optional<TextureFormat> texture_format) {
  const std::string text = read_whole_file(path);
  check_json_depth(text, path);
  json root;
  try {
    root = json::parse(text, nullptr, true, true);
  } catch (const json::out_of_range& e) {
    // A number beyond double range (1e400): the library names the token but no place.
    std::string message = e.what();
    const std::size_t quote = message.find('\'');
    std::uint64_t line = 1;
    if (quote != std::string::npos) {
      const std::string token = message.substr(quote + 1, message.rfind('\'') - quote - 1);
      const std::size_t at = token.empty() ? std::string::npos : text.find(token);
      if (at != std::string::npos) line = line_of(text, at);
      message = "number " + excerpt(token) + " beyond the range of a double";
    }
    throw_at_line(path, line, "invalid JSON: " + message);
  } catch (const json::parse_error& e) {
    // Report the line and column of the byte where parsing stopped.
    const std::size_t byte = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    std::uint64_t line = 1, column = 1;
    for (std::size_t i = 0; i < byte; ++i) {
      if (text[i] == '\n')
        ++line, column = 1;
      else
        ++column;
    }
    std::string message = e.what();
    const std::size_t colon = message.find(": ", message.find("parse error"));
    if (colon != std::string::npos) message = message.substr(colon + 2);
    throw_at_line(path, line, "column " + std::to_string(column) + ": invalid JSON: " + excerpt(message, 200));
  }
  Scene scene = SceneReader(path).read(root);
  load_scene_textures(scene, texture_format);
  return scene;
}

}  // namespace

std::string data_directory() {
  const char* from_environment = std::getenv("RASTRACE_DATA");
  if (from_environment && *from_environment) return from_environment;
  return RASTRACE_DATA_DIR;
}

Camera frame_bounds(const glm::vec3& lo, const glm::vec3& hi, float aspect) {
  Camera camera;
  const glm::vec3 centre = (lo + hi) * 0.5f;
  const float radius = std::max(glm::length(hi - lo) * 0.5f, 1e-6f);
  const float half_v = glm::radians(camera.fov_y_degrees) * 0.5f;
  const float half_h = std::atan(std::tan(half_v) * (aspect > 0.0f ? aspect : 1.0f));
  const float distance = radius / std::sin(std::min(half_v, half_h)) * 1.05f;
  const glm::vec3 direction = glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f));
  camera.target = centre;
  camera.eye = centre + direction * distance;
  camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
  camera.near_plane = std::max(distance - radius * 1.5f, radius * 0.01f);
  camera.far_plane = distance + radius * 1.5f;
  return camera;
}

void load_scene_textures(Scene& scene, std::optional<TextureFormat> format) {
  std::map<std::tuple<int, std::string, int, int, TextureFormat>, int> loaded;
  std::uint64_t procedural_bytes = 0;
  for (SceneObject& object : scene.objects)
    for (Material& material : object.mesh.materials) {
      TextureSource& source = material.texture_source;
      if (format) source.format = *format;
      if (source.kind == TextureSource::Kind::None) {
        material.texture = -1;
        continue;
      }
      const auto key =
          std::make_tuple(static_cast<int>(source.kind), source.path, source.size, source.checks, source.format);
      auto it = loaded.find(key);
      if (it == loaded.end()) {
        if (source.kind != TextureSource::Kind::File) {
          // RGBA8 texels and a mip chain (4/3 of the base level), summed over the scene's textures.
          procedural_bytes += std::uint64_t(source.size) * std::uint64_t(source.size) * 4 * 4 / 3;
          checked_bytes(procedural_bytes, 1, scene.name + ": procedural textures");
        }
        scene.textures.push_back(load_texture(source));
        it = loaded.emplace(key, static_cast<int>(scene.textures.size()) - 1).first;
      }
      material.texture = it->second;
    }
}

Scene load_scene(const std::string& spec, std::optional<TextureFormat> texture_format) {
  if (spec.starts_with("builtin:")) return make_builtin_scene(spec.substr(8), texture_format);
  std::string extension = fs::path(spec).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".json") return load_json_scene(spec, texture_format);
  Scene scene;
  scene.name = spec;
  scene.objects.push_back(SceneObject{load_mesh(spec), glm::mat4(1.0f)});
  const BoundingBox box = bounding_box(scene);
  scene.camera = frame_bounds(box.lo, box.hi, static_cast<float>(scene.width) / static_cast<float>(scene.height));
  load_scene_textures(scene, texture_format);
  return scene;
}

}  // namespace rastrace
