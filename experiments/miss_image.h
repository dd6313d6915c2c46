// Where an ordering loses: each face of the mesh coloured by how many of its vertices missed the
// post-transform cache when it was drawn (0, 1, 2, 3), rendered from a fixed camera
// (`rastrace vcache --miss-image FILE`). Hoppe 1999's Figure 4 colours triangle corners by hit or
// miss in the same spirit; one colour per face reads better on meshes of 10^4-10^5 faces.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cache_sim/vertex_cache.h"
#include "reorder/ordering.h"
#include "scenes/mesh.h"

namespace rastrace {

// Per mesh face, the cache misses charged to it when the ordering's stream is simulated: every
// fetched index that misses is charged to the next non-degenerate triangle the stream assembles
// (so a strip's swap index and a degenerate triangle's misses go to the face they serve), capped
// at 3. A list's face thus gets exactly the misses among its own three fetches. Faces the stream
// never draws get 0. Throws InputError if the stream draws a triangle that is not a face of the mesh.
std::vector<std::uint8_t> face_miss_counts(const Mesh& mesh, const Ordering& ordering, VertexCachePolicy policy,
                                           unsigned entries);

// The colours of 0, 1, 2 and 3 misses (RGB in [0, 1]): green, yellow, orange, red.
extern const float kMissColours[4][3];

struct MissImageSpec {
  int width = 768;
  int height = 768;
};

// Renders the mesh with each face in kMissColours[counts[face]], lit from the camera (vertex
// normals averaged from the faces when the mesh has none) on a white background, with the camera
// `rastrace render` frames a mesh file with (scenes/scene_io.h frame_bounds: from +z, slightly
// above, the whole bounding box in view). Writes a PNG (or any extension OpenImageIO knows)
// atomically. Throws InputError when counts does not have one entry per face.
void write_miss_image(const Mesh& mesh, const std::vector<std::uint8_t>& counts, const std::string& path,
                      const MissImageSpec& spec = {});

}  // namespace rastrace
