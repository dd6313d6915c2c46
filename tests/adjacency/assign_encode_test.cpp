#include <algorithm>
#include <array>
#include <map>

#include <gtest/gtest.h>

#include "adjacency_fixture.h"
#include "reorder/adjacency/assign.h"
#include "reorder/adjacency/encode.h"
#include "reorder/mesh_topology.h"
#include "scenes/procedural.h"

namespace rastrace {
namespace {

using Triple = std::array<std::uint32_t, 3>;
Triple sorted(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  Triple t{a, b, c};
  std::sort(t.begin(), t.end());
  return t;
}

// Decodes every primitive as a geometry shader would and counts how often each mesh face (by its
// vertices) and each mesh edge (by its two vertices) is processed.
void expect_every_face_and_edge_once(const Mesh& mesh, const AdjacencyPrimitives& primitives) {
  const MeshTopology topology = build_mesh_topology(mesh);
  std::map<Triple, int> faces;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    faces[sorted(mesh.indices[3 * f], mesh.indices[3 * f + 1], mesh.indices[3 * f + 2])] = 0;
  std::vector<int> edges(topology.edge_count(), 0);
  for (std::size_t p = 0; p < primitives.size(); ++p) {
    const std::uint32_t* six = primitives.indices.data() + 6 * p;
    const DecodedPrimitive d = decode_adjacency_primitive(six);
    ++faces.at(sorted(six[0], six[2], six[4]));
    if (d.has_assigned) {
      ASSERT_NE(primitives.assigned_face[p], kNoFace);
      ++faces.at(sorted(six[0], six[1], six[2]));
      // The assigned face keeps the mesh's winding.
      const std::uint32_t* a = mesh.indices.data() + 3 * std::size_t{primitives.assigned_face[p]};
      const bool same = (a[0] == six[0] && a[1] == six[1] && a[2] == six[2]) ||
                        (a[1] == six[0] && a[2] == six[1] && a[0] == six[2]) ||
                        (a[2] == six[0] && a[0] == six[1] && a[1] == six[2]);
      EXPECT_TRUE(same) << "primitive " << p;
    } else {
      EXPECT_EQ(primitives.assigned_face[p], kNoFace);
    }
    for (unsigned e = 0; e < 3; ++e) {
      if (d.role[e] == EdgeRole::Skipped) continue;
      const std::uint32_t id = topology.find_edge(six[2 * e], six[(2 * e + 2) % 6]);
      ASSERT_NE(id, kNoEdge);
      ++edges[id];
      // An interior edge is processed with the real face across it.
      if (d.role[e] == EdgeRole::Interior) {
        EXPECT_EQ(faces.count(sorted(six[2 * e], six[2 * e + 1], six[(2 * e + 2) % 6])), 1u);
      }
    }
  }
  std::size_t wrong_faces = 0, wrong_edges = 0;
  for (const auto& [key, count] : faces) wrong_faces += count != 1;
  for (const int count : edges) wrong_edges += count != 1;
  EXPECT_EQ(wrong_faces, 0u);
  EXPECT_EQ(wrong_edges, 0u);
}

class AssignmentOnPaperMeshes : public ::testing::TestWithParam<const char*> {};

TEST_P(AssignmentOnPaperMeshes, IsPerfectAndRestricted) {
  const auto& built = testing::built_mesh(GetParam());
  const AdjacencyBuild& b = built.build;
  EXPECT_TRUE(is_perfect_restricted_assignment(b.dual, b.cover.in_cover, b.assignment));
  // Hopcroft-Karp alone leaves some components without an assigned face: Lemma 1's alternating
  // paths were needed and worked.
  EXPECT_GT(b.assignment.repaired_components, 0u);
  std::uint32_t assigned = 0;
  for (std::uint32_t f = 0; f < b.dual.face_count; ++f)
    assigned += b.cover.in_cover[f] && b.assignment.partner[f] != kNoFace;
  EXPECT_EQ(assigned, b.dual.face_count - b.cover.size);
}

TEST_P(AssignmentOnPaperMeshes, PrimitivesProcessEveryFaceAndEveryEdgeExactlyOnce) {
  const auto& built = testing::built_mesh(GetParam());
  const AdjacencyPrimitives& primitives = built.build.primitives;
  EXPECT_EQ(primitives.size(), built.build.cover.size);
  EXPECT_EQ(primitives.indices.size(), 6 * primitives.size());
  expect_every_face_and_edge_once(built.mesh, primitives);
  // Closed meshes use the six configurations of Figure 4 and nothing else; most primitives are
  // the full one (assigned face, three edges).
  std::array<std::size_t, 6> histogram{};
  for (std::size_t p = 0; p < primitives.size(); ++p)
    ++histogram[decode_adjacency_primitive(primitives.indices.data() + 6 * p).configuration()];
  EXPECT_GT(histogram[0], primitives.size() / 2);
  for (std::size_t p = 0; p < primitives.size(); ++p) {
    const DecodedPrimitive d = decode_adjacency_primitive(primitives.indices.data() + 6 * p);
    for (unsigned e = 0; e < 3; ++e) ASSERT_NE(d.role[e], EdgeRole::Boundary);  // closed meshes
  }
}

INSTANTIATE_TEST_SUITE_P(Sander2008, AssignmentOnPaperMeshes,
                         ::testing::Values("fandisk.off", "triceratops.off", "bunny00.off"), [](const auto& info) {
                           std::string name = info.param;
                           return name.substr(0, name.find('.'));
                         });

TEST(AdjacencyEncoding, BoundaryEdgesAreProcessedOnceAndMarkedByTheirStartVertex) {
  for (const bool grid : {true, false}) {
    const Mesh mesh = grid ? make_grid(12, 9) : testing::cached_mesh("elephant-with-holes.off");
    const AdjacencyBuild b = build_adjacency_primitives(mesh);
    EXPECT_TRUE(is_perfect_restricted_assignment(b.dual, b.cover.in_cover, b.assignment));
    expect_every_face_and_edge_once(mesh, b.primitives);
    std::uint64_t boundary = 0;
    for (std::size_t p = 0; p < b.primitives.size(); ++p) {
      const std::uint32_t* six = b.primitives.indices.data() + 6 * p;
      const DecodedPrimitive d = decode_adjacency_primitive(six);
      for (unsigned e = 0; e < 3; ++e)
        if (d.role[e] == EdgeRole::Boundary) {
          ++boundary;
          EXPECT_EQ(six[2 * e + 1], six[2 * e]);
        }
    }
    EXPECT_EQ(boundary, b.dual.boundary_slot_count);
    EXPECT_EQ(boundary, grid ? 2u * (12 + 9) : 1353u);
  }
}

TEST(AdjacencyEncoding, DegenerateFacesGetAPrimitiveAndNoEdges) {
  Mesh mesh = make_grid(4, 4);
  mesh.indices.insert(mesh.indices.end(), {0, 0, 1});  // a degenerate face on the border
  const AdjacencyBuild b = build_adjacency_primitives(mesh);
  EXPECT_EQ(b.dual.degenerate_face_count, 1u);
  EXPECT_TRUE(b.cover.in_cover[32]);
  EXPECT_TRUE(is_perfect_restricted_assignment(b.dual, b.cover.in_cover, b.assignment));
  std::size_t found = 0;
  for (std::size_t p = 0; p < b.primitives.size(); ++p)
    if (b.primitives.cover_face[p] == 32) {
      ++found;
      const DecodedPrimitive d = decode_adjacency_primitive(b.primitives.indices.data() + 6 * p);
      for (unsigned e = 0; e < 3; ++e) EXPECT_EQ(d.role[e], EdgeRole::Skipped);
    }
  EXPECT_EQ(found, 1u);
}

TEST(AdjacencyEncoding, AFaceLeftUnpairedAtANonManifoldEdgeTreatsItAsBoundary) {
  // Three faces on edge (0, 1): faces 0 and 1 pair up (opposite directions); face 2 cannot.
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -1, 0}, {0.5f, 0, 1}};
  mesh.indices = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  const AdjacencyBuild b = build_adjacency_primitives(mesh);
  EXPECT_EQ(b.dual.dual_edge_count, 1u);
  EXPECT_EQ(b.dual.boundary_slot_count, 7u);
  EXPECT_EQ(b.cover.size, 3u);  // every face touches the boundary
  EXPECT_TRUE(is_perfect_restricted_assignment(b.dual, b.cover.in_cover, b.assignment));
  const MeshTopology topology = build_mesh_topology(mesh);
  std::vector<int> edges(topology.edge_count(), 0);
  for (std::size_t p = 0; p < b.primitives.size(); ++p) {
    const std::uint32_t* six = b.primitives.indices.data() + 6 * p;
    const DecodedPrimitive d = decode_adjacency_primitive(six);
    for (unsigned e = 0; e < 3; ++e)
      if (d.role[e] != EdgeRole::Skipped) ++edges[topology.find_edge(six[2 * e], six[(2 * e + 2) % 6])];
  }
  for (std::uint32_t e = 0; e < topology.edge_count(); ++e)
    EXPECT_EQ(edges[e], topology.find_edge(0, 1) == e ? 2 : 1) << e;  // once as a pair, once as a rim
}

TEST(AdjacencyEncoding, OnePrimitivePerFaceHasTwiceTheIndicesOfTheCover) {
  const auto& built = testing::built_mesh("fandisk.off");
  const AdjacencyPrimitives naive = encode_one_primitive_per_face(built.mesh, built.build.dual);
  EXPECT_EQ(naive.size(), built.mesh.face_count());
  const double ratio = double(naive.size()) / double(built.build.primitives.size());
  EXPECT_GT(ratio, 1.85);  // 12946 / 6847 = 1.891
  EXPECT_LT(ratio, 1.92);
}

TEST(AdjacencyEncoding, AssignmentRejectsANonCover) {
  const Mesh mesh = make_grid(3, 3);
  const AdjacencyDual dual = build_adjacency_dual(mesh);
  std::vector<std::uint8_t> nothing(dual.face_count, 0);
  EXPECT_THROW(assign_uncovered_faces(dual, nothing), std::logic_error);
}

}  // namespace
}  // namespace rastrace
