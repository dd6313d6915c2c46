#include "experiments/miss_image.h"

#include <algorithm>
#include <array>
#include <map>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/index_stream.h"
#include "pipeline/render_scene.h"
#include "scenes/bounding_box.h"
#include "scenes/scene_io.h"

namespace rastrace {

const float kMissColours[4][3] = {
    {0.20f, 0.70f, 0.30f},  // 0: every vertex was in the cache
    {0.95f, 0.85f, 0.20f},  // 1: the one new vertex a strip or a good list pays for
    {0.95f, 0.50f, 0.10f},  // 2
    {0.85f, 0.10f, 0.10f},  // 3: the face started from scratch
};

std::vector<std::uint8_t> face_miss_counts(const Mesh& mesh, const Ordering& ordering, VertexCachePolicy policy,
                                           unsigned entries) {
  // Faces by their vertex set (sorted): a strip draws odd faces with the other winding, and a
  // mesh may hold the same triangle twice (each copy is charged once, in drawing order).
  std::map<std::array<std::uint32_t, 3>, std::vector<std::uint32_t>> faces_of;
  const auto key = [](std::array<std::uint32_t, 3> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f)
    faces_of[key({mesh.indices[3 * f], mesh.indices[3 * f + 1], mesh.indices[3 * f + 2]})].push_back(f);
  std::vector<std::uint8_t> counts(mesh.face_count(), 0);
  VertexCache cache(policy, entries);
  unsigned pending = 0;
  walk_index_stream(
      ordering.indices, ordering.type, ordering.restart_index,
      [&](std::size_t position, bool) { pending += cache.access(ordering.indices[position]) ? 0u : 1u; },
      [&](const AssembledTriangle& triangle) {
        if (triangle.degenerate()) return;
        auto found = faces_of.find(key(triangle.vertices));
        if (found == faces_of.end() || found->second.empty())
          throw InputError(mesh.name + ": the ordering draws triangle (" + std::to_string(triangle.vertices[0]) + ", " +
                           std::to_string(triangle.vertices[1]) + ", " + std::to_string(triangle.vertices[2]) +
                           ") more often than the mesh has it");
        const std::uint32_t face = found->second.front();
        found->second.erase(found->second.begin());
        counts[face] = static_cast<std::uint8_t>(std::min(pending, 3u));
        pending = 0;
      });
  return counts;
}

namespace {

// Area-weighted face normals summed at the vertices: enough shading to see the shape.
std::vector<glm::vec3> vertex_normals(const Mesh& mesh) {
  std::vector<glm::vec3> normals(mesh.vertex_count(), glm::vec3(0.0f));
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::uint32_t a = mesh.indices[3 * f], b = mesh.indices[3 * f + 1], c = mesh.indices[3 * f + 2];
    const glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    normals[a] += n;
    normals[b] += n;
    normals[c] += n;
  }
  for (glm::vec3& n : normals) n = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 0.0f, 1.0f);
  return normals;
}

}  // namespace

void write_miss_image(const Mesh& mesh, const std::vector<std::uint8_t>& counts, const std::string& path,
                      const MissImageSpec& spec) {
  if (counts.size() != mesh.face_count())
    throw InputError("miss image of " + mesh.name + ": " + std::to_string(counts.size()) + " miss counts for " +
                     std::to_string(mesh.face_count()) + " faces");
  Scene scene;
  scene.name = mesh.name;
  scene.width = spec.width;
  scene.height = spec.height;
  scene.background = glm::vec4(1.0f);
  Mesh coloured;
  coloured.name = mesh.name;
  coloured.positions = mesh.positions;
  coloured.normals = mesh.normals.size() == mesh.positions.size() ? mesh.normals : vertex_normals(mesh);
  coloured.indices = mesh.indices;
  for (int misses = 0; misses < 4; ++misses) {
    Material material;
    material.name = std::to_string(misses) + " misses";
    material.diffuse = glm::vec4(kMissColours[misses][0], kMissColours[misses][1], kMissColours[misses][2], 1.0f);
    coloured.materials.push_back(material);
  }
  coloured.face_material.resize(counts.size());
  for (std::size_t f = 0; f < counts.size(); ++f) coloured.face_material[f] = std::min<std::uint32_t>(counts[f], 3u);
  scene.objects.push_back(SceneObject{std::move(coloured), glm::mat4(1.0f)});
  const BoundingBox box = bounding_box(scene);
  scene.camera = frame_bounds(box.lo, box.hi, static_cast<float>(scene.width) / static_cast<float>(scene.height));
  RenderOptions options;
  options.pipeline.lighting.enabled = true;
  options.pipeline.lighting.ambient = 0.35f;
  render_scene(scene, options, nullptr).framebuffer.write_colour(path);
}

}  // namespace rastrace
