#include "reorder/meshlets/meshlet_stats.h"

#include <algorithm>
#include <vector>

#include "cache_sim/vertex_cache.h"

namespace rastrace {

MeshletStats meshlet_stats(const MeshletSet& set, const MeshletLimits& limits, const VertexCacheSpec& local_cache) {
  MeshletStats stats;
  stats.meshlets = set.meshlets.size();
  stats.triangles = set.triangle_count();
  stats.vertices = set.vertices.size();
  VertexCache cache(local_cache.policy, local_cache.entries);
  std::vector<std::uint32_t> edges;  // a meshlet's edges as (low local index << 8 | high)
  for (const Meshlet& meshlet : set.meshlets) {
    cache.clear();
    edges.clear();
    for (std::uint32_t t = 0; t < meshlet.triangle_count; ++t) {
      const std::uint8_t* corners = &set.triangles[3 * (std::size_t{meshlet.triangle_offset} + t)];
      for (int k = 0; k < 3; ++k) {
        stats.local_misses += !cache.access(corners[k]);
        const std::uint32_t a = corners[k], b = corners[(k + 1) % 3];
        if (a != b) edges.push_back(std::min(a, b) << 8 | std::max(a, b));
      }
    }
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i < edges.size();) {
      std::size_t j = i;
      while (j < edges.size() && edges[j] == edges[i]) ++j;
      stats.perimeter_edges += j - i == 1;
      i = j;
    }
  }
  if (stats.triangles) {
    const double triangles = double(stats.triangles);
    stats.vertices_per_triangle = double(stats.vertices) / triangles;
    stats.bytes_per_triangle = (4.0 * double(stats.vertices) + 3.0 * triangles) / triangles;
    stats.acmr = double(stats.local_misses) / triangles;
  }
  if (stats.meshlets) {
    stats.vertex_fill = double(stats.vertices) / (double(stats.meshlets) * limits.max_vertices);
    stats.triangle_fill = double(stats.triangles) / (double(stats.meshlets) * limits.max_triangles);
  }
  return stats;
}

}  // namespace rastrace
