// The order of the vertex buffer. Faces decide the post-transform cache; the vertex order decides
// how far apart in memory the vertices of nearby triangles lie, i.e. the vertex-fetch traffic
// (cache_sim/vertex_fetch.h).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "scenes/mesh.h"

namespace rastrace {

// Vertices numbered in the order the index stream first uses them, as meshoptimizer's
// meshopt_optimizeVertexFetchRemap does: remap[old] = new. Vertices no index uses follow, in their
// original order, so the result is a permutation and no attribute is lost. Indices must be
// < vertex_count (InputError otherwise).
std::vector<std::uint32_t> first_use_vertex_remap(std::span<const std::uint32_t> indices, std::size_t vertex_count);

// Moves every per-vertex attribute (positions, normals, UVs) of the mesh to remap[old] and
// rewrites its indices; a make_grid grid loses its grid shape (its numbering no longer holds).
// `remap` must be a permutation of the mesh's vertices.
void remap_vertices(Mesh& mesh, std::span<const std::uint32_t> remap);

}  // namespace rastrace
