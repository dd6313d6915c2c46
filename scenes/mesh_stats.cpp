#include "scenes/mesh_stats.h"

#include <algorithm>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

#include "core/error.h"
#include "scenes/bounding_box.h"

namespace rastrace {

MeshStats compute_mesh_stats(const Mesh& mesh) {
  MeshStats stats;
  stats.vertices = mesh.vertex_count();
  stats.faces = mesh.face_count();
  stats.materials = mesh.materials.size();
  std::vector<std::tuple<int, std::string, int, int>> sources;
  for (const Material& m : mesh.materials)
    if (m.texture_source.kind != TextureSource::Kind::None)
      sources.emplace_back(static_cast<int>(m.texture_source.kind), m.texture_source.path, m.texture_source.size,
                           m.texture_source.checks);
  std::sort(sources.begin(), sources.end());
  stats.textures = static_cast<std::size_t>(std::unique(sources.begin(), sources.end()) - sources.begin());
  const BoundingBox box = bounding_box(mesh.positions);
  stats.bounds_min = box.lo;
  stats.bounds_max = box.hi;

  // Undirected edges as sorted 64-bit keys; runs of equal keys give each edge's face count.
  std::vector<std::uint64_t> edges;
  edges.reserve(mesh.indices.size());
  std::vector<std::uint32_t> parent(mesh.vertex_count());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto find = [&parent](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= mesh.vertex_count())
      throw InputError(mesh.name + ": face " + std::to_string(i / 3) + " index " + std::to_string(mesh.indices[i]) +
                       " >= vertex count " + std::to_string(mesh.vertex_count()));
  std::vector<bool> referenced(mesh.vertex_count(), false);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::uint32_t* t = &mesh.indices[f * 3];
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) ++stats.degenerate_faces;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      referenced[a] = true;
      if (a != b) edges.push_back((std::uint64_t{std::min(a, b)} << 32) | std::max(a, b));
      const std::uint32_t ra = find(a), rb = find(b);
      if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    ++stats.edges;
    if (j - i == 1) ++stats.boundary_edges;
    if (j - i >= 3) ++stats.non_manifold_edges;
    i = j;
  }
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
    if (!referenced[v])
      ++stats.unreferenced_vertices;
    else if (find(v) == v)
      ++stats.connected_components;
  }
  return stats;
}

}  // namespace rastrace
