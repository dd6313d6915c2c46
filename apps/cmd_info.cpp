// `rastrace info FILE|SCENE [--json]`: what a mesh or scene holds (counts, bounds, topology).
#include <iostream>
#include <string>

#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "core/table.h"
#include "scenes/bounding_box.h"
#include "scenes/mesh_stats.h"
#include "scenes/scene_io.h"
#include "scenes/text_parse.h"

namespace rastrace {

namespace {

struct ObjectInfo {
  std::string name;
  MeshStats stats;
  glm::vec3 lo{0.0f}, hi{0.0f};  // world space
};

std::string format_vec3(const glm::vec3& v) {
  std::string out = "[";
  for (int i = 0; i < 3; ++i) {
    if (i) out += ", ";
    append_number(out, v[i]);
  }
  return out + "]";
}

// Floats as the shortest decimal that reads back exactly (7.416328, not 7.416327953338623).
double shortest(float value) {
  std::string text;
  append_number(text, value);
  return std::stod(text);
}

nlohmann::json vec3_json(const glm::vec3& v) {
  return nlohmann::json::array({shortest(v.x), shortest(v.y), shortest(v.z)});
}

nlohmann::json stats_json(const MeshStats& s, const glm::vec3& lo, const glm::vec3& hi) {
  return {{"vertices", s.vertices},
          {"faces", s.faces},
          {"materials", s.materials},
          {"textures", s.textures},
          {"bounds", {{"min", vec3_json(lo)}, {"max", vec3_json(hi)}}},
          {"edges", s.edges},
          {"boundary_edges", s.boundary_edges},
          {"non_manifold_edges", s.non_manifold_edges},
          {"connected_components", s.connected_components},
          {"degenerate_faces", s.degenerate_faces},
          {"unreferenced_vertices", s.unreferenced_vertices}};
}

void run_info(const std::string& spec, bool as_json) {
  const Scene scene = load_scene(spec);
  std::vector<ObjectInfo> objects;
  MeshStats total;
  glm::vec3 lo(0.0f), hi(0.0f);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& object = scene.objects[i];
    ObjectInfo info;
    info.name = object.mesh.name;
    info.stats = compute_mesh_stats(object.mesh);
    const BoundingBox box = bounding_box(object.mesh.positions, object.transform);
    info.lo = box.lo;
    info.hi = box.hi;
    lo = i == 0 ? info.lo : glm::min(lo, info.lo);
    hi = i == 0 ? info.hi : glm::max(hi, info.hi);
    total.vertices += info.stats.vertices;
    total.faces += info.stats.faces;
    total.materials += info.stats.materials;
    total.edges += info.stats.edges;
    total.boundary_edges += info.stats.boundary_edges;
    total.non_manifold_edges += info.stats.non_manifold_edges;
    total.connected_components += info.stats.connected_components;
    total.degenerate_faces += info.stats.degenerate_faces;
    total.unreferenced_vertices += info.stats.unreferenced_vertices;
    objects.push_back(std::move(info));
  }
  total.textures = scene.textures.size();  // distinct textures across the scene

  if (as_json) {
    nlohmann::json out = stats_json(total, lo, hi);
    out["scene"] = scene.name;
    out["viewport"] = {{"width", scene.width}, {"height", scene.height}};
    out["camera"] = {{"eye", vec3_json(scene.camera.eye)},        {"target", vec3_json(scene.camera.target)},
                     {"up", vec3_json(scene.camera.up)},          {"fov_y", shortest(scene.camera.fov_y_degrees)},
                     {"near", shortest(scene.camera.near_plane)}, {"far", shortest(scene.camera.far_plane)}};
    nlohmann::json list = nlohmann::json::array();
    for (const ObjectInfo& o : objects) {
      nlohmann::json entry = stats_json(o.stats, o.lo, o.hi);
      entry["name"] = o.name;
      list.push_back(std::move(entry));
    }
    out["objects"] = std::move(list);
    std::cout << out.dump(2) << "\n";
    return;
  }

  Table table;
  table.title = "Scene " + scene.name;
  table.parameters = {{"scene", scene.name},
                      {"objects", static_cast<std::int64_t>(scene.objects.size())},
                      {"textures", static_cast<std::int64_t>(scene.textures.size())},
                      {"viewport", std::to_string(scene.width) + "x" + std::to_string(scene.height)},
                      {"camera eye", format_vec3(scene.camera.eye)},
                      {"camera target", format_vec3(scene.camera.target)}};
  table.columns = {{"object", "object"},
                   {"vertices", "vertices"},
                   {"faces", "faces"},
                   {"materials", "materials"},
                   {"textures", "textures"},
                   {"bounds_min", "bounds min"},
                   {"bounds_max", "bounds max"},
                   {"boundary_edges", "boundary edges"},
                   {"non_manifold_edges", "non-manifold edges"},
                   {"connected_components", "components"}};
  const auto add = [&table](const std::string& name, const MeshStats& s, const glm::vec3& a, const glm::vec3& b) {
    table.add_row({name, s.vertices, s.faces, s.materials, s.textures, format_vec3(a), format_vec3(b), s.boundary_edges,
                   s.non_manifold_edges, s.connected_components});
  };
  for (const ObjectInfo& o : objects) add(o.name, o.stats, o.lo, o.hi);
  if (objects.size() > 1) add("total", total, lo, hi);
  std::cout << render_table(table, TableFormat::Markdown);
}

}  // namespace

void add_info_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("info", "Describe a mesh file or scene: counts, bounds, topology");
  auto spec = std::make_shared<std::string>();
  auto as_json = std::make_shared<bool>(false);
  command
      ->add_option("input", *spec,
                   "Mesh file (.off .ply .obj .gltf .dae ...), scene (.json) or builtin:grid|bunny|spider")
      ->required();
  command->add_flag("--json", *as_json, "Print one JSON object (totals, and per object under \"objects\")");
  command->footer(
      "Examples:\n"
      "  rastrace info data/meshes/fandisk.off\n"
      "  rastrace info builtin:bunny --json\n"
      "  rastrace info docs/example_scene.json");
  command->callback([spec, as_json] { run_info(*spec, *as_json); });
}

}  // namespace rastrace
