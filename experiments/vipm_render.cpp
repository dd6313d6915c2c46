#include "experiments/vipm_render.h"

#include <algorithm>
#include <charconv>
#include <limits>

#include "core/error.h"
#include "experiments/vipm_experiment.h"
#include "lod/progressive_mesh.h"
#include "lod/sliding_window_relax.h"
#include "lod/vipm_measure_methods.h"

namespace rastrace {

namespace {

// The faces of `material` as a mesh of their own, vertices renumbered in first-use order.
Mesh material_part(const Mesh& mesh, std::uint32_t material) {
  Mesh part;
  part.name =
      mesh.name + "#" +
      (material < mesh.materials.size() && !mesh.materials[material].name.empty() ? mesh.materials[material].name
                                                                                  : std::to_string(material));
  part.materials = mesh.materials;
  constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> renumbered(mesh.vertex_count(), kUnused);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.material_of(f) != material) continue;
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = mesh.indices[3 * f + c];
      if (renumbered[v] == kUnused) {
        renumbered[v] = static_cast<std::uint32_t>(part.positions.size());
        part.positions.push_back(mesh.positions[v]);
        if (!mesh.normals.empty()) part.normals.push_back(mesh.normals[v]);
        if (!mesh.uvs.empty()) part.uvs.push_back(mesh.uvs[v]);
      }
      part.indices.push_back(renumbered[v]);
    }
  }
  return part;
}

std::vector<std::uint32_t> materials_in_use(const Mesh& mesh) {
  std::vector<std::uint32_t> out;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    if (std::find(out.begin(), out.end(), mesh.material_of(f)) == out.end()) out.push_back(mesh.material_of(f));
  return out;
}

}  // namespace

VipmScene build_vipm_scene(const Scene& scene, const VipmSceneSpec& spec) {
  const std::string representation = vipm_representation_of(spec.method, "--vipm");
  VipmScene out;
  out.scene = scene;
  out.scene.objects.clear();
  VipmMethodsParams params;
  params.tolerance = spec.tolerance;
  ProgressiveMeshParams pm_params;
  pm_params.min_triangles = spec.min_triangles;

  for (const SceneObject& object : scene.objects) {
    const std::vector<std::uint32_t> materials = materials_in_use(object.mesh);
    for (const std::uint32_t material : materials) {
      Mesh part = materials.size() == 1 ? object.mesh : material_part(object.mesh, material);
      part.face_material.clear();
      ProgressiveMesh pm;
      try {
        pm = build_progressive_mesh(part, pm_params);
      } catch (const InputError& e) {
        throw InputError("--vipm: " + scene.name + ", object " + object.mesh.name +
                         (materials.size() > 1 ? ", material " + std::to_string(material) : std::string()) + ": " +
                         e.what());
      }
      if (representation == "sliding-window") pm = relax_for_sliding_window(pm, spec.tolerance).pm;
      SceneObject drawn{reordered_mesh(part, pm), object.transform};
      std::unique_ptr<VipmRepresentation> vipm = build_vipm_representation(representation, pm, drawn.mesh, params);
      vipm->set_lod(spec.lod);

      const auto index = static_cast<std::uint32_t>(out.scene.objects.size());
      VipmPartLod lod{part.name, vipm->lod(), vipm->lod_count() - 1, static_cast<std::uint32_t>(pm.triangles.size()),
                      0};
      for (const VipmDraw& d : vipm->draws()) {
        DrawCall call;
        call.indices = d.indices;
        call.type = d.type;
        call.restart_index = d.restart_index;
        call.material = material;
        out.draws.push_back(call);
        out.draw_objects.push_back(index);
        ++lod.draws;
      }
      out.parts.push_back(lod);
      out.scene.objects.push_back(std::move(drawn));
      out.representations.push_back(std::move(vipm));
    }
  }
  return out;
}

std::uint32_t parse_vipm_lod(const std::string& text) {
  std::uint32_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || text[0] == '+')
    throw InputError("--lod '" + text.substr(0, 32) + (text.size() > 32 ? "...'" : "'") +
                     ": expected a number of collapses, 0 to 4294967295");
  return value;
}

std::string describe_vipm_lods(std::span<const VipmPartLod> parts) {
  std::string out;
  for (const VipmPartLod& p : parts)
    out += (out.empty() ? "" : "; ") + p.name + " " + std::to_string(p.lod) + "/" + std::to_string(p.last_lod) + " (" +
           std::to_string(p.draws) + (p.draws == 1 ? " draw)" : " draws)");
  return out;
}

}  // namespace rastrace
