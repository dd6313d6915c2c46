// Texture map-based ordering (Yang, Mitra, Huang, "Improving Rendering by Texture Map-Based
// Triangle Strips"): one level above any vertex-cache ordering. Faces are grouped by the texture
// region they sample, each group is ordered by a base algorithm, and the groups are drawn one
// after another so the texture cache sees one region at a time.
//
// Regions, within one texture (faces of materials with the same texture source share it):
//   quadrant  the quadrant of the face's UV centroid (the four-colour map of the paper: 4 bins)
//   chart     a UV chart: a set of faces connected across edges (a loader splits vertices at UV
//             seams, so edge-connected faces with shared vertices share UVs)
//   texture   the whole texture is one region (grouping by material texture only)
//   auto      quadrant for the procedural four-colour texture, chart otherwise
// Group order: textures in order of first appearance in the file; inside a texture, a greedy
// chain starting at the region of the texture's first face and moving each time to the region
// that shares the most vertices with the one just drawn (ties: the lower region id), so
// consecutive groups are neighbours on the mesh and the transitions cost few vertex misses.
// Expect a texture-miss reduction of 10-15% on a one-component mesh with four regions and much
// more on a mesh of separate parts, for about 1% (one part) to 10% (many) more vertex misses.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "reorder/ordering.h"

namespace rastrace {

struct TextureGroups {
  std::vector<std::uint32_t> group_of_face;  // one per face
  std::vector<std::string> labels;           // one per group: "SpiderTex.jpg chart 3"
  // Groups in drawing order.
  std::vector<std::uint32_t> order;
};

// mode: auto, quadrant, chart or texture; InputError otherwise.
TextureGroups find_texture_groups(const Mesh& mesh, const std::string& mode);

// ReorderParams::texgroup_base names the base algorithm (strip, greedy, tipsy, ...), and
// ReorderParams::texgroup_regions the region mode.
Ordering reorder_texgroup(const Mesh& mesh, const ReorderParams& params);

}  // namespace rastrace
