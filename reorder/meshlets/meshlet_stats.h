// What a set of meshlets costs a mesh-shader pipeline (docs/DESIGN.md, Metrics):
//   meshlets                 how many (one mesh-shader workgroup each)
//   vertices_per_triangle    sum of meshlet vertex counts / triangles: the transform cost; about
//                            0.5 would be every vertex shaded once, 3 one shading per corner
//   perimeter_edges          edges used by exactly one triangle of their meshlet, summed over
//                            meshlets: each meshlet's boundary, whose vertices are shaded again
//   vertex_fill, triangle_fill  mean vertex and triangle count over the limits
//   bytes_per_triangle       meshlet data: 4-byte vertex indices plus 3 bytes per triangle
//   acmr                     post-transform misses per triangle of each meshlet's own triangle
//                            list replayed through a small vertex cache emptied at every meshlet:
//                            the locality the primitive assembler and rasterizer see inside it
#pragma once

#include <cstdint>

#include "cache_sim/live_bank_sink.h"
#include "reorder/meshlets/meshlet.h"

namespace rastrace {

struct MeshletStats {
  std::uint64_t meshlets = 0;
  std::uint64_t triangles = 0;
  std::uint64_t vertices = 0;  // sum of meshlet vertex counts
  std::uint64_t perimeter_edges = 0;
  std::uint64_t local_misses = 0;  // in-meshlet vertex-cache misses
  double vertices_per_triangle = 0.0;
  double vertex_fill = 0.0;
  double triangle_fill = 0.0;
  double bytes_per_triangle = 0.0;
  double acmr = 0.0;
};

MeshletStats meshlet_stats(const MeshletSet& set, const MeshletLimits& limits, const VertexCacheSpec& local_cache);

}  // namespace rastrace
