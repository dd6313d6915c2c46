// Encoding cover faces and their assigned faces as 6-index triangle-with-adjacency primitives in
// GL_TRIANGLES_ADJACENCY order (Sander, Nehab, Chlamtac, Hoppe 2008, section 5 and Figure 4).
//
// A primitive is (i0 .. i5): the cover face is (i0, i2, i4) with the mesh's winding; position p
// (0, 1, 2) is the edge from i[2p] to i[2p+2 mod 6] and i[2p+1] the vertex across it:
//   i[2p+1] is a real vertex -> the edge is processed with both its faces;
//   i[2p+1] == i[2p]         -> a boundary edge, processed with its single face;
//   i[2p+1] == i[2p+2 mod 6] -> the edge is covered by another primitive: skipped.
// Face (i0, i1, i2) is the assigned face when i1 is real; a duplicated i1 makes it degenerate, so
// every primitive runs the same steps (cover face, face 0, edges 0-2). A cover face without an
// assigned face therefore cannot process its position-0 edge: it puts there a boundary edge or
// an edge it hands to a neighbouring cover face. Those hand-overs follow a breadth-first forest
// grown inside each cover component from its boundary faces and faces with an assigned face
// (which the restricted matching guarantees), so every edge is processed exactly once.
// The configurations (Figure 4) are: with or without an assigned face, times 0-2 skipped
// edges among positions 1 and 2 (position 0 is the assigned face's edge, a boundary edge or a
// handed-over edge): six in all on a closed mesh.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "reorder/adjacency/assign.h"
#include "reorder/adjacency/dual.h"

namespace rastrace {

struct AdjacencyPrimitives {
  std::vector<std::uint32_t> indices;        // 6 per primitive
  std::vector<std::uint32_t> cover_face;     // per primitive: the mesh face at its centre
  std::vector<std::uint32_t> assigned_face;  // per primitive: kNoFace when none
  std::size_t size() const { return cover_face.size(); }
};

// One primitive per cover face, in increasing cover-face order.
AdjacencyPrimitives encode_adjacency_primitives(const Mesh& mesh, const AdjacencyDual& dual,
                                                const std::vector<std::uint8_t>& in_cover,
                                                const FaceAssignment& assignment);

// The naive scheme of the DirectX samples: one primitive per mesh face with every neighbour
// real (boundary edges marked), each interior edge seen by two primitives.
AdjacencyPrimitives encode_one_primitive_per_face(const Mesh& mesh, const AdjacencyDual& dual);

enum class EdgeRole : std::uint8_t { Interior, Boundary, Skipped };

// What a geometry shader reads from one primitive.
struct DecodedPrimitive {
  std::array<std::uint32_t, 3> cover{};     // i0, i2, i4
  bool has_assigned = false;                // face (i0, i1, i2) is real
  std::array<EdgeRole, 3> role{};           // per position
  std::array<std::uint32_t, 3> opposite{};  // i1, i3, i5
  // Configuration number 0-5: 3 * (no assigned face) + skipped edges among positions 1 and 2.
  unsigned configuration() const {
    return 3u * !has_assigned + (role[1] == EdgeRole::Skipped) + (role[2] == EdgeRole::Skipped);
  }
};

DecodedPrimitive decode_adjacency_primitive(const std::uint32_t* six);

// Permutes the primitives: result[i] = primitives[order[i]].
AdjacencyPrimitives permute_primitives(const AdjacencyPrimitives& primitives, const std::vector<std::uint32_t>& order);

}  // namespace rastrace
