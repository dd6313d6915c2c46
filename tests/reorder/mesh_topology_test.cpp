#include "reorder/mesh_topology.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "scenes/procedural.h"
#include "tests/support/pathological_meshes.h"

namespace rastrace {
namespace {

Mesh mesh_of(std::vector<std::uint32_t> indices, std::size_t vertices) {
  Mesh mesh;
  mesh.name = "test";
  mesh.positions.resize(vertices);
  mesh.indices = std::move(indices);
  return mesh;
}

TEST(MeshTopology, GridCountsMatchEulerAndNeighboursAreSymmetric) {
  const Mesh grid = make_grid(16, 16);
  const MeshTopology t = build_mesh_topology(grid);
  EXPECT_EQ(t.vertex_count, 289u);
  EXPECT_EQ(t.face_count, 512u);
  // V - E + F = 1 for a disc.
  EXPECT_EQ(t.edge_count(), 289u + 512u - 1u);
  std::size_t interior = 0;
  for (std::uint32_t f = 0; f < t.face_count; ++f)
    for (unsigned i = 0; i < 3; ++i) {
      const std::uint32_t g = t.neighbor(f, i);
      if (g == kNoFace) continue;
      ++interior;
      const std::uint32_t e = t.face_edges[3 * f + i];
      bool back = false;
      for (unsigned j = 0; j < 3; ++j) back |= t.neighbor(g, j) == f && t.face_edges[3 * g + j] == e;
      EXPECT_TRUE(back) << "face " << f << " edge " << i;
    }
  // 2 * interior edges; boundary edges = 4 * 16.
  EXPECT_EQ(interior, 2 * (t.edge_count() - 64u));
  EXPECT_EQ(t.vertex_faces.size(), 3u * 512u);
  // Interior vertex (x=5, y=5) of Castano's grid touches 6 triangles.
  EXPECT_EQ(t.faces_of_vertex(17 * 5 + 5).size(), 6u);
  EXPECT_EQ(t.faces_of_vertex(0).size(), 1u);
}

TEST(MeshTopology, FindEdgeIsOrderIndependentAndRejectsNonEdges) {
  const Mesh m = mesh_of({0, 1, 2, 2, 1, 3}, 5);
  const MeshTopology t = build_mesh_topology(m);
  EXPECT_EQ(t.edge_count(), 5u);
  const std::uint32_t e = t.find_edge(1, 2);
  ASSERT_NE(e, kNoEdge);
  EXPECT_EQ(t.find_edge(2, 1), e);
  EXPECT_EQ(t.faces_of_edge(e).size(), 2u);
  EXPECT_EQ(t.find_edge(0, 3), kNoEdge);
  EXPECT_EQ(t.find_edge(4, 0), kNoEdge);
  EXPECT_EQ(t.find_edge(1, 1), kNoEdge);
  // Face 0's edge 1 is (1, 2); face 1 lies across it.
  EXPECT_EQ(t.neighbor(0, 1), 1u);
  EXPECT_EQ(t.neighbor(1, 0), 0u);
  EXPECT_EQ(t.neighbor_count(0), 1u);
}

TEST(MeshTopology, InconsistentlyOrientedFacesAreNotNeighbours) {
  // Face 1 repeats edge (1, 2) in the same direction: a strip could not join them.
  const MeshTopology t = build_mesh_topology(mesh_of({0, 1, 2, 1, 2, 3}, 4));
  EXPECT_EQ(t.neighbor_count(0), 0u);
  EXPECT_EQ(t.neighbor_count(1), 0u);
  EXPECT_EQ(t.faces_of_edge(t.find_edge(1, 2)).size(), 2u);
}

TEST(MeshTopology, NonManifoldEdgePairsFacesOnceAndSymmetrically) {
  // Three faces on edge (0, 1): 0->1 in face 0, 1->0 in faces 1 and 2.
  const MeshTopology t = build_mesh_topology(mesh_of({0, 1, 2, 1, 0, 3, 1, 0, 4}, 5));
  EXPECT_EQ(t.faces_of_edge(t.find_edge(0, 1)).size(), 3u);
  EXPECT_EQ(t.neighbor(0, 0), 1u);
  EXPECT_EQ(t.neighbor(1, 0), 0u);
  EXPECT_EQ(t.neighbor(2, 0), kNoFace);
}

TEST(MeshTopology, DegenerateFaceHasNoEdgeAcrossItsCollapsedSide) {
  const MeshTopology t = build_mesh_topology(mesh_of({0, 0, 1, 0, 2, 1}, 3));
  EXPECT_EQ(t.face_edges[0], kNoEdge);
  EXPECT_EQ(t.faces_of_vertex(0).size(), 2u);
  // (0, 1) in face 0 is edge 1 (0 -> 1); face 1 has 1 -> 0.
  EXPECT_EQ(t.neighbor(0, 1), 1u);
}

TEST(MeshTopology, OutOfRangeIndexIsAnInputErrorNamingTheFace) {
  try {
    build_mesh_topology(mesh_of({0, 1, 2, 0, 2, 7}, 3));
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("face 1: vertex index 7 >= vertex count 3"), std::string::npos)
        << error.what();
  }
}

// The rule face_neighbors documents, checked by its definition: for every edge, each unpaired
// half-edge in face order takes the first later unpaired half-edge of the opposite direction in
// another face. The builder pairs by a linear sweep; here the quadratic search is the reference,
// on meshes whose edges are shared by thousands of faces, by duplicated faces and by faces that
// use an edge twice.
TEST(MeshTopology, NonManifoldEdgesArePairedGreedilyInFaceOrder) {
  auto meshes = testing::pathological_meshes(3000);
  meshes.emplace_back("edge-used-twice", mesh_of({0, 1, 0, 1, 0, 2, 0, 1, 3, 1, 0, 1, 2, 1, 0, 0, 1, 4}, 5));
  for (const auto& [name, mesh] : meshes) {
    const MeshTopology t = build_mesh_topology(mesh);
    std::vector<std::uint32_t> expected(3 * std::size_t(t.face_count), kNoFace);
    std::vector<std::vector<std::uint32_t>> slots_of_edge(t.edge_count());
    for (std::uint32_t s = 0; s < 3 * t.face_count; ++s)
      if (t.face_edges[s] != kNoEdge) slots_of_edge[t.face_edges[s]].push_back(s);
    const auto forward = [&](std::uint32_t s) {
      return mesh.indices[s] < mesh.indices[s % 3 == 2 ? s - 2 : s + 1];
    };
    for (const std::vector<std::uint32_t>& slots : slots_of_edge) {
      std::vector<bool> paired(slots.size(), false);
      for (std::size_t a = 0; a < slots.size(); ++a) {
        if (paired[a]) continue;
        for (std::size_t b = a + 1; b < slots.size(); ++b) {
          if (paired[b] || slots[a] / 3 == slots[b] / 3 || forward(slots[a]) == forward(slots[b])) continue;
          expected[slots[a]] = slots[b] / 3;
          expected[slots[b]] = slots[a] / 3;
          paired[a] = paired[b] = true;
          break;
        }
      }
    }
    EXPECT_EQ(t.face_neighbors, expected) << name;
  }
}

}  // namespace
}  // namespace rastrace
