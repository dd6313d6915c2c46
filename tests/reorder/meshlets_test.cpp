// Meshlet builders (reorder/meshlets/): every triangle in exactly one meshlet within the limits,
// the scan builder equal to meshopt_buildMeshletsScan, the greedy builder at or below
// meshopt_buildMeshlets' vertices per triangle, and the statistics on a hand-made case.
#include <algorithm>
#include <array>

#include <gtest/gtest.h>

#include "core/error.h"
#include "reorder/meshlets/meshlet.h"
#include "reorder/meshlets/meshlet_peer.h"
#include "reorder/meshlets/meshlet_stats.h"
#include "reorder/ordering.h"
#include "support/test_meshes.h"

namespace rastrace {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

std::vector<Triangle> triangles_of(std::span<const std::uint32_t> indices) {
  std::vector<Triangle> list;
  for (std::size_t i = 0; i < indices.size(); i += 3) list.push_back({indices[i], indices[i + 1], indices[i + 2]});
  return list;
}

// Every input triangle, corners in their order, in exactly one meshlet; limits respected; local
// indices inside their meshlet; offsets contiguous.
void expect_partition(const MeshletSet& set, std::span<const std::uint32_t> indices, const MeshletLimits& limits,
                      const std::string& what) {
  std::vector<Triangle> built;
  std::uint32_t vertex_offset = 0, triangle_offset = 0;
  for (const Meshlet& m : set.meshlets) {
    ASSERT_EQ(m.vertex_offset, vertex_offset) << what;
    ASSERT_EQ(m.triangle_offset, triangle_offset) << what;
    ASSERT_GE(m.triangle_count, 1u) << what;
    ASSERT_LE(m.vertex_count, limits.max_vertices) << what;
    ASSERT_LE(m.triangle_count, limits.max_triangles) << what;
    for (std::uint32_t t = 0; t < m.triangle_count; ++t) {
      for (int k = 0; k < 3; ++k) ASSERT_LT(set.triangles[3 * (m.triangle_offset + t) + k], m.vertex_count) << what;
      built.push_back({set.corner(m, t, 0), set.corner(m, t, 1), set.corner(m, t, 2)});
    }
    // No vertex listed twice in a meshlet.
    std::vector<std::uint32_t> vertices(set.vertices.begin() + m.vertex_offset,
                                        set.vertices.begin() + m.vertex_offset + m.vertex_count);
    std::sort(vertices.begin(), vertices.end());
    ASSERT_EQ(std::adjacent_find(vertices.begin(), vertices.end()), vertices.end()) << what;
    vertex_offset += m.vertex_count;
    triangle_offset += m.triangle_count;
  }
  EXPECT_EQ(vertex_offset, set.vertices.size()) << what;
  std::vector<Triangle> expected = triangles_of(indices);
  std::sort(built.begin(), built.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(built, expected) << what;
}

TEST(Meshlets, EveryTriangleInExactlyOneMeshletWithinTheLimits) {
  for (const char* name : {"fandisk.off", "triceratops.off", "elephant-with-holes.off"}) {
    const Mesh& mesh = testing::cached_mesh(name);
    const std::vector<std::uint32_t> random = reorder_random(mesh, ReorderParams{}).indices;
    for (const MeshletLimits limits : {MeshletLimits{64, 124}, MeshletLimits{64, 64}, MeshletLimits{3, 1},
                                       MeshletLimits{32, 126}, MeshletLimits{256, 512}})
      for (const std::vector<std::uint32_t>* indices : {&mesh.indices, &random}) {
        const std::string what = std::string(name) + " " + std::to_string(limits.max_vertices) + "/" +
                                 std::to_string(limits.max_triangles);
        expect_partition(build_meshlets_scan(*indices, mesh.vertex_count(), limits), *indices, limits, what + " scan");
        expect_partition(build_meshlets_greedy(*indices, mesh.positions, limits), *indices, limits, what + " greedy");
        expect_partition(build_meshlets_spatial(*indices, mesh.positions, limits), *indices, limits, what + " spatial");
      }
  }
}

TEST(Meshlets, ScanEqualsMeshoptBuildMeshletsScan) {
  for (const char* name : {"fandisk.off", "bunny00.off"}) {
    const Mesh& mesh = testing::cached_mesh(name);
    const std::vector<std::uint32_t> tipsy = reorder_tipsy(mesh, ReorderParams{}).indices;
    for (const MeshletLimits limits : {MeshletLimits{64, 124}, MeshletLimits{64, 64}, MeshletLimits{128, 256}}) {
      const MeshletSet ours = build_meshlets_scan(tipsy, mesh.vertex_count(), limits);
      const MeshletSet theirs = meshopt_build_meshlets_scan(tipsy, mesh.vertex_count(), limits);
      ASSERT_EQ(ours.meshlets.size(), theirs.meshlets.size()) << name;
      EXPECT_EQ(ours.vertices, theirs.vertices) << name;
      EXPECT_EQ(ours.triangles, theirs.triangles) << name;
    }
  }
}

TEST(Meshlets, GreedyAtMostMeshoptVerticesPerTriangleOnFandiskTriceratopsBunny) {
  // Sum of meshlet vertex counts per triangle, file order, cone weight 0 for meshoptimizer.
  struct Case {
    const char* mesh;
    MeshletLimits limits;
    double greedy, meshopt;
  };
  for (const Case& c : {Case{"fandisk.off", {64, 124}, 0.6664, 0.6766}, Case{"fandisk.off", {64, 64}, 0.7131, 0.7253},
                        Case{"triceratops.off", {64, 124}, 0.6648, 0.6809},
                        Case{"triceratops.off", {64, 64}, 0.7141, 0.7286},
                        Case{"bunny00.off", {64, 124}, 0.6589, 0.6619}, Case{"bunny00.off", {64, 64}, 0.7061, 0.7118}}) {
    const Mesh& mesh = testing::cached_mesh(c.mesh);
    const MeshletLimits limits = c.limits;
    const MeshletStats greedy =
        meshlet_stats(build_meshlets_greedy(mesh.indices, mesh.positions, limits), limits, {VertexCachePolicy::Fifo, 8});
    const MeshletStats meshopt = meshlet_stats(meshopt_build_meshlets(mesh.indices, mesh.positions, limits), limits,
                                               {VertexCachePolicy::Fifo, 8});
    const std::string what = std::string(c.mesh) + " " + std::to_string(limits.max_triangles);
    EXPECT_NEAR(greedy.vertices_per_triangle, c.greedy, 0.00005) << what;
    EXPECT_NEAR(meshopt.vertices_per_triangle, c.meshopt, 0.00005) << what;
    EXPECT_LE(greedy.vertices, meshopt.vertices) << what;
  }
}

TEST(Meshlets, StatisticsOfAQuadAndATriangle) {
  // A quad (0 1 2, 0 2 3) and a separate triangle (4 5 6), limits 4 vertices / 2 triangles: the
  // scan puts the quad in one meshlet (4 vertices, perimeter 4) and the triangle in another
  // (3 vertices, perimeter 3).
  const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 2, 3, 4, 5, 6};
  const MeshletLimits limits{4, 2};
  const MeshletSet set = build_meshlets_scan(indices, 7, limits);
  const MeshletStats stats = meshlet_stats(set, limits, {VertexCachePolicy::Fifo, 8});
  EXPECT_EQ(stats.meshlets, 2u);
  EXPECT_EQ(stats.vertices, 7u);
  EXPECT_DOUBLE_EQ(stats.vertices_per_triangle, 7.0 / 3.0);
  EXPECT_EQ(stats.perimeter_edges, 7u);
  EXPECT_DOUBLE_EQ(stats.vertex_fill, 7.0 / 8.0);
  EXPECT_DOUBLE_EQ(stats.triangle_fill, 3.0 / 4.0);
  EXPECT_DOUBLE_EQ(stats.bytes_per_triangle, (4.0 * 7 + 3.0 * 3) / 3.0);
  EXPECT_EQ(stats.local_misses, 7u);  // a cache of 8 misses each vertex once per meshlet
  // A FIFO of 2 inside the quad: 0 1 2 leaves {1, 2}; 0 misses, 2 hits, 3 misses: 5, and 3 for
  // the triangle.
  EXPECT_EQ(meshlet_stats(set, limits, {VertexCachePolicy::Fifo, 2}).local_misses, 8u);
  EXPECT_EQ(meshlet_stats(set, limits, {VertexCachePolicy::Fifo, 1}).local_misses, 9u);
}

TEST(Meshlets, BadLimitsAndIndicesAreInputErrors) {
  const std::vector<std::uint32_t> indices = {0, 1, 2};
  const std::vector<glm::vec3> positions(3);
  EXPECT_THROW(build_meshlets_scan(indices, 3, {2, 124}), InputError);
  EXPECT_THROW(build_meshlets_greedy(indices, positions, {257, 124}), InputError);
  EXPECT_THROW(build_meshlets_spatial(indices, positions, {64, 0}), InputError);
  EXPECT_THROW(build_meshlets_scan(indices, 2, {64, 124}), InputError);
  EXPECT_THROW(build_meshlets_scan(std::vector<std::uint32_t>{0, 1}, 3, {64, 124}), InputError);
  EXPECT_FALSE(meshopt_builds_meshlets({64, 126}));
  EXPECT_THROW(meshopt_build_meshlets(indices, positions, {64, 126}), InputError);
  EXPECT_THROW(meshopt_build_meshlets_scan(indices, 3, {256, 124}), InputError);
}

}  // namespace
}  // namespace rastrace
