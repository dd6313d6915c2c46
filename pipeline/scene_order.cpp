#include "pipeline/scene_order.h"

namespace rastrace {

OrderedDraws order_scene(const Scene& scene, const std::string& order, const ReorderParams& params) {
  OrderedDraws out;
  if (order == "original") return out;
  const ReorderAlgorithm& algorithm = find_reorder_algorithm(order);
  out.indices.resize(scene.objects.size());
  out.materials.resize(scene.objects.size());
  out.draws.resize(scene.objects.size());
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const Mesh& mesh = scene.objects[o].mesh;
    Ordering ordering = algorithm.run(mesh, params);
    out.draws[o].type = ordering.type;
    out.draws[o].restart_index = ordering.restart_index;
    if (mesh.materials.size() > 1 && !mesh.face_material.empty())
      out.materials[o] = primitive_materials(mesh, ordering);
    out.indices[o] = std::move(ordering.indices);
    out.draws[o].indices = out.indices[o];
    out.draws[o].primitive_materials = out.materials[o];
  }
  return out;
}

}  // namespace rastrace
