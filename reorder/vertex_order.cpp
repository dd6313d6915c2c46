#include "reorder/vertex_order.h"

#include <stdexcept>
#include <string>

#include "core/error.h"

namespace rastrace {

std::vector<std::uint32_t> first_use_vertex_remap(std::span<const std::uint32_t> indices, std::size_t vertex_count) {
  constexpr std::uint32_t kUnset = ~std::uint32_t{0};
  std::vector<std::uint32_t> remap(vertex_count, kUnset);
  std::uint32_t next = 0;
  for (std::size_t i = 0; i < indices.size(); ++i) {
    const std::uint32_t v = indices[i];
    if (v >= vertex_count)
      throw InputError("index " + std::to_string(i) + ": vertex " + std::to_string(v) + " >= vertex count " +
                       std::to_string(vertex_count));
    if (remap[v] == kUnset) remap[v] = next++;
  }
  for (std::uint32_t& slot : remap)
    if (slot == kUnset) slot = next++;
  return remap;
}

namespace {
template <typename T>
void permute(std::vector<T>& values, std::span<const std::uint32_t> remap) {
  if (values.empty()) return;
  std::vector<T> moved(values.size());
  for (std::size_t v = 0; v < values.size(); ++v) moved[remap[v]] = values[v];
  values = std::move(moved);
}
}  // namespace

void remap_vertices(Mesh& mesh, std::span<const std::uint32_t> remap) {
  if (remap.size() != mesh.vertex_count())
    throw std::logic_error("remap_vertices: the remap has " + std::to_string(remap.size()) + " entries for " +
                           std::to_string(mesh.vertex_count()) + " vertices");
  permute(mesh.positions, remap);
  permute(mesh.normals, remap);
  permute(mesh.uvs, remap);
  for (std::uint32_t& index : mesh.indices) index = remap[index];
  mesh.grid.reset();
}

}  // namespace rastrace
