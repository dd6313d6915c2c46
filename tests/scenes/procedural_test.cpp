// Procedural meshes and projected UVs.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "scenes/mesh_stats.h"
#include "scenes/procedural.h"
#include "tests/support/test_data.h"
#include "tests/support/test_meshes.h"

namespace rastrace {
namespace {

double signed_volume(const Mesh& mesh) {
  double volume = 0.0;
  for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
    const glm::dvec3 a(mesh.positions[mesh.indices[i]]), b(mesh.positions[mesh.indices[i + 1]]),
        c(mesh.positions[mesh.indices[i + 2]]);
    volume += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return volume;
}

TEST(Icosphere, CountsFollowTenTimesFourToTheSPlusTwo) {
  for (int s = 0; s <= 3; ++s) {
    const Mesh sphere = make_icosphere(s);
    const std::size_t four = std::size_t{1} << (2 * s);
    EXPECT_EQ(sphere.vertex_count(), 10 * four + 2) << s;
    EXPECT_EQ(sphere.face_count(), 20 * four) << s;
  }
}

TEST(Icosphere, IsClosedManifoldOutwardFacingAndNearlyTheUnitBall) {
  const Mesh sphere = make_icosphere(4);
  const MeshStats stats = compute_mesh_stats(sphere);
  EXPECT_EQ(stats.boundary_edges, 0u);
  EXPECT_EQ(stats.non_manifold_edges, 0u);
  EXPECT_EQ(stats.connected_components, 1u);
  EXPECT_EQ(stats.edges, 7680u);  // 3F/2
  const double volume = signed_volume(sphere);
  EXPECT_GT(volume, 0.0);  // counter-clockwise seen from outside
  EXPECT_NEAR(volume, 4.0 / 3.0 * M_PI, 0.02);
  for (const auto& p : sphere.positions) EXPECT_NEAR(glm::length(p), 1.0f, 1e-6f);
}

TEST(Plane, FacesUpWithUvsUpToRepeatAndACheckerMaterial) {
  const Mesh plane = make_plane(4, 2.0f);
  EXPECT_EQ(plane.vertex_count(), 25u);
  EXPECT_EQ(plane.face_count(), 32u);
  for (std::size_t i = 0; i < plane.indices.size(); i += 3) {
    const glm::vec3 a = plane.positions[plane.indices[i]], b = plane.positions[plane.indices[i + 1]],
                    c = plane.positions[plane.indices[i + 2]];
    EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f);
  }
  EXPECT_EQ(plane.uvs.back(), glm::vec2(2.0f, 2.0f));
  ASSERT_EQ(plane.materials.size(), 1u);
  EXPECT_EQ(plane.materials[0].texture_source.kind, TextureSource::Kind::Checker);
}

TEST(Grid, CastanoLayoutIsUnchanged) {
  const Mesh grid = make_grid(16, 16);
  EXPECT_EQ(grid.vertex_count(), 289u);
  EXPECT_EQ(grid.face_count(), 512u);
  // Quad (1, 2): a = (1,2) = 35, b = (1,3) = 52, c = (2,2) = 36, d = (2,3) = 53.
  const std::size_t quad = 2 * 16 + 1;
  const std::vector<std::uint32_t> first(grid.indices.begin() + static_cast<std::ptrdiff_t>(quad * 6),
                                         grid.indices.begin() + static_cast<std::ptrdiff_t>(quad * 6 + 6));
  EXPECT_EQ(first, (std::vector<std::uint32_t>{35, 52, 36, 36, 52, 53}));
  const MeshStats stats = compute_mesh_stats(grid);
  EXPECT_EQ(stats.boundary_edges, 64u);
  EXPECT_EQ(stats.connected_components, 1u);
}

TEST(UvProjection, PlanarZMapsTheBoundingBoxToTheUnitSquareUpright) {
  Mesh mesh = testing::cached_mesh("triceratops.off");
  project_uvs_planar(mesh, 2);
  ASSERT_EQ(mesh.uvs.size(), mesh.vertex_count());
  glm::vec2 lo(1.0f), hi(0.0f);
  std::size_t top = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    lo = glm::min(lo, mesh.uvs[v]), hi = glm::max(hi, mesh.uvs[v]);
    if (mesh.positions[v].y > mesh.positions[top].y) top = v;
  }
  EXPECT_EQ(lo, glm::vec2(0.0f));
  EXPECT_EQ(hi, glm::vec2(1.0f));
  EXPECT_EQ(mesh.uvs[top].y, 0.0f);  // the highest point is on the image's top row
}

TEST(UvProjection, SphericalGivesLatitudeFromTopToBottom) {
  Mesh sphere = make_icosphere(1);
  project_uvs_spherical(sphere);
  // Icosahedron vertices are not at the poles; check ordering by height instead.
  for (std::size_t v = 0; v < sphere.vertex_count(); ++v) {
    const float expected = std::acos(std::clamp(sphere.positions[v].y, -1.0f, 1.0f)) / static_cast<float>(M_PI);
    EXPECT_NEAR(sphere.uvs[v].y, expected, 1e-3f);  // acos is steep at the poles
    EXPECT_GE(sphere.uvs[v].x, 0.0f);
    EXPECT_LE(sphere.uvs[v].x, 1.0f);
  }
}

TEST(MeshStats, CountsBoundaryNonManifoldEdgesAndComponents) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {5, 5, 5}, {6, 5, 5}, {5, 6, 5}, {9, 9, 9}};
  // Three triangles on edge (0,1) (non-manifold), a separate triangle, an unused vertex 8.
  mesh.indices = {0, 1, 2, 1, 0, 3, 0, 1, 4, 5, 6, 7};
  const MeshStats stats = compute_mesh_stats(mesh);
  EXPECT_EQ(stats.non_manifold_edges, 1u);
  EXPECT_EQ(stats.boundary_edges, 6u + 3u);
  EXPECT_EQ(stats.connected_components, 2u);
  EXPECT_EQ(stats.unreferenced_vertices, 1u);
  EXPECT_EQ(stats.bounds_max, glm::vec3(9, 9, 9));
}

TEST(MeshStats, FandiskIsOneClosedManifoldComponent) {
  const MeshStats stats = compute_mesh_stats(testing::cached_mesh("fandisk.off"));
  EXPECT_EQ(stats.boundary_edges, 0u);
  EXPECT_EQ(stats.non_manifold_edges, 0u);
  EXPECT_EQ(stats.connected_components, 1u);
  EXPECT_EQ(stats.edges, 19419u);  // 3 * 12946 / 2
}

}  // namespace
}  // namespace rastrace
