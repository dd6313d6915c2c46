// The scan builder: triangles in the order the index stream sends them, a new meshlet whenever
// the next triangle would exceed a limit, as meshoptimizer's meshopt_buildMeshletsScan does. Its
// quality is the ordering's: a vertex-cache order (Tipsy, Forsyth) keeps consecutive triangles on
// shared vertices, a random order fills each meshlet with unrelated corners.
#include "reorder/meshlets/meshlet.h"

namespace rastrace {

MeshletSet build_meshlets_scan(std::span<const std::uint32_t> triangles, std::size_t vertex_count,
                               const MeshletLimits& limits) {
  validate_triangle_list(triangles, vertex_count);
  MeshletAccumulator meshlets(vertex_count, limits);
  for (std::size_t i = 0; i < triangles.size(); i += 3) {
    const std::uint32_t a = triangles[i], b = triangles[i + 1], c = triangles[i + 2];
    if (!meshlets.fits(a, b, c)) meshlets.close();
    meshlets.append(a, b, c);
  }
  return meshlets.finish();
}

}  // namespace rastrace
