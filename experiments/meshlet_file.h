// Meshlets as a file (`rastrace meshlets -o FILE`), for an engine or a script to load.
// FILE ending in .json: one object
//   {"format": "rastrace-meshlets", "version": 1, "mesh": ..., "order": ..., "builder": ...,
//    "max_vertices": 64, "max_triangles": 124,
//    "meshlets": [{"vertices": [mesh vertex ids], "triangles": [a, b, c, ...]}, ...]}
// where a, b, c index the meshlet's "vertices". Any other name: the binary layout, little-endian,
//   char[8]  "RTMSHLT\0"
//   u32      version (1), max_vertices, max_triangles, meshlet count M, vertex index count V,
//            triangle count T
//   M x u32[4]  vertex_offset, triangle_offset (in triangles), vertex_count, triangle_count
//   V x u32     mesh vertex ids, meshlet after meshlet
//   T x u8[3]   local vertex indices, meshlet after meshlet, no padding
// The file appears whole or not at all (core/atomic_file.h).
#pragma once

#include <string>

#include "reorder/meshlets/meshlet.h"

namespace rastrace {

struct MeshletFileInfo {
  std::string mesh;
  std::string order;
  std::string builder;
  MeshletLimits limits;
};

void write_meshlets(const std::string& path, const MeshletSet& set, const MeshletFileInfo& info);

}  // namespace rastrace
