// The progressive-mesh builder: every LoD is a manifold without flipped triangles and every
// step is a half-edge collapse (on a grid, triceratops, and sampled on fandisk and bunny00),
// the vanilla numbering, determinism and seeding, speed, and bad input.
#include "lod/progressive_mesh.h"

#include <algorithm>
#include <cmath>
#include <ctime>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include "core/error.h"
#include "scenes/mesh_io.h"
#include "scenes/procedural.h"
#include "tests/lod/lod_checks.h"
#include "tests/support/test_data.h"

namespace rastrace {
namespace {

void expect_valid(const Mesh& mesh, std::size_t full_every, const ProgressiveMeshParams& params = {}) {
  const ProgressiveMesh pm = build_progressive_mesh(mesh, params);
  const Mesh reordered = reordered_mesh(mesh, pm);
  testing::expect_valid_sequence(pm, reordered.positions, full_every, mesh.name);
}

TEST(ProgressiveMesh, GridEveryLodIsManifoldWithoutFlips) {
  const Mesh grid = make_grid(16, 16);
  const ProgressiveMesh pm = build_progressive_mesh(grid, {});
  // 512 faces: the default floor of 16 triangles; a flat grid has no other limit.
  EXPECT_EQ(pm.triangles.size(), 512u);
  EXPECT_EQ(pm.vertex_order.size(), 289u);
  EXPECT_LE(pm.triangle_counts.back(), 16u);
  EXPECT_GE(pm.triangle_counts.back(), 14u);
  expect_valid(grid, 1);
}

TEST(ProgressiveMesh, TriceratopsEveryLodIsManifoldWithoutFlips) {
  const Mesh mesh = load_mesh(testing::data_file("meshes/triceratops.off"));
  const ProgressiveMesh pm = build_progressive_mesh(mesh, {});
  EXPECT_EQ(pm.triangles.size(), 5660u);
  EXPECT_LE(pm.triangle_counts.back(), 113u);  // 2% of 5660
  expect_valid(mesh, 1);
}

TEST(ProgressiveMesh, FandiskSampledLodsAreManifoldWithoutFlips) {
  expect_valid(load_mesh(testing::data_file("meshes/fandisk.off")), 257);
}

TEST(ProgressiveMesh, Bunny00SampledLodsAreManifoldWithoutFlipsAndBuildInSeconds) {
  const Mesh mesh = load_mesh(testing::data_file("meshes/bunny00.off"));
  // Processor time, not wall time: the machine may be shared. About 1 s in a Release build;
  // the bound leaves room for the sanitizer build (minutes would mean a broken queue).
  const std::clock_t start = std::clock();
  const ProgressiveMesh pm = build_progressive_mesh(mesh, {});
  const double seconds = double(std::clock() - start) / CLOCKS_PER_SEC;
  EXPECT_LT(seconds, 60.0);
  EXPECT_LE(pm.triangle_counts.back(), 1508u);  // 2% of 75408
  testing::expect_valid_sequence(pm, reordered_mesh(mesh, pm).positions, 2999, mesh.name);
}

double area(const std::vector<std::array<std::uint32_t, 3>>& triangles, const std::vector<glm::vec3>& p) {
  double sum = 0;
  for (const auto& t : triangles) sum += 0.5 * glm::length(testing::normal_of(p, t[0], t[1], t[2]));
  return sum;
}

TEST(ProgressiveMesh, BoundaryPlanesKeepAFlatGridsOutline) {
  // Every face plane of a flat grid is the same plane: only the boundary planes stop its border
  // from being eaten. With them, every collapse costs nothing and the square keeps its area.
  const Mesh grid = make_grid(16, 16);
  const ProgressiveMesh pm = build_progressive_mesh(grid, {});
  const Mesh reordered = reordered_mesh(grid, pm);
  const double full = area(pm.triangles, reordered.positions);
  for (const std::size_t n : {pm.collapses.size() / 2, pm.collapses.size()})
    EXPECT_NEAR(area(triangles_at_lod(pm, n), reordered.positions), full, 1e-9 * full) << "LoD " << n;
  for (const CollapseRecord& c : pm.collapses) EXPECT_LE(c.error, 1e-9 * full * full);
  // Without them (weight 0), the outline shrinks.
  ProgressiveMeshParams none;
  none.boundary_weight = 0;
  const ProgressiveMesh eaten = build_progressive_mesh(grid, none);
  EXPECT_LT(area(triangles_at_lod(eaten, eaten.collapses.size()), reordered_mesh(grid, eaten).positions), 0.99 * full);
}

TEST(ProgressiveMesh, DeterministicAndSeeded) {
  const Mesh mesh = load_mesh(testing::data_file("meshes/triceratops.off"));
  const ProgressiveMesh a = build_progressive_mesh(mesh, {}), b = build_progressive_mesh(mesh, {});
  ASSERT_EQ(a.collapses.size(), b.collapses.size());
  EXPECT_EQ(a.vertex_order, b.vertex_order);
  EXPECT_EQ(a.triangles, b.triangles);
  for (std::size_t i = 0; i < a.collapses.size(); ++i) {
    EXPECT_EQ(a.collapses[i].kept, b.collapses[i].kept);
    EXPECT_EQ(a.collapses[i].changed_corners, b.collapses[i].changed_corners);
    EXPECT_EQ(a.collapses[i].error, b.collapses[i].error);
  }
  // On a flat grid every interior collapse costs zero: the seed alone picks among them.
  const Mesh grid = make_grid(8, 8);
  ProgressiveMeshParams other;
  other.seed = 2;
  EXPECT_NE(build_progressive_mesh(grid, {}).vertex_order, build_progressive_mesh(grid, other).vertex_order);
}

TEST(ProgressiveMesh, ErrorsGrowOnAverage) {
  // Greedy QEM is not monotone collapse by collapse, but the late collapses cost more.
  const ProgressiveMesh pm = build_progressive_mesh(load_mesh(testing::data_file("meshes/fandisk.off")), {});
  const std::size_t n = pm.collapses.size();
  double first = 0, last = 0;
  for (std::size_t i = 0; i < n / 10; ++i) first += pm.collapses[i].error, last += pm.collapses[n - 1 - i].error;
  EXPECT_GT(last, 100 * first);
}

TEST(ProgressiveMesh, CursorJumpsMatchTheReference) {
  const Mesh mesh = load_mesh(testing::data_file("meshes/fandisk.off"));
  const ProgressiveMesh pm = build_progressive_mesh(mesh, {});
  ProgressiveMeshCursor cursor(pm);
  for (const std::size_t n :
       {std::size_t(5000), std::size_t(17), pm.collapses.size() + 9, std::size_t(3000), std::size_t(0)}) {
    cursor.set_lod(n);
    const std::size_t at = std::min(n, pm.collapses.size());
    ASSERT_EQ(cursor.lod(), at);
    const auto reference = triangles_at_lod(pm, at);
    ASSERT_EQ(cursor.indices().size(), 3 * reference.size());
    for (std::size_t t = 0; t < reference.size(); ++t)
      ASSERT_TRUE(std::equal(reference[t].begin(), reference[t].end(), cursor.indices().begin() + 3 * t)) << n;
    EXPECT_EQ(cursor.vertex_count(), pm.vertex_count_at(at));
  }
  EXPECT_FALSE(cursor.split());
}

TEST(ProgressiveMesh, ReorderedMeshKeepsEveryVertexAndFace) {
  Mesh mesh = load_mesh(testing::data_file("meshes/triceratops.off"));
  mesh.face_material.resize(mesh.face_count());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) mesh.face_material[f] = std::uint32_t(f % 3);
  const ProgressiveMesh pm = build_progressive_mesh(mesh, {});
  const Mesh out = reordered_mesh(mesh, pm);
  ASSERT_EQ(out.vertex_count(), mesh.vertex_count());  // triceratops uses every vertex
  ASSERT_EQ(out.face_count(), mesh.face_count());
  for (std::size_t t = 0; t < out.face_count(); ++t) {
    const std::uint32_t f = pm.triangle_origin[t];
    EXPECT_EQ(out.face_material[t], mesh.face_material[f]);
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(out.positions[out.indices[3 * t + i]], mesh.positions[mesh.indices[3 * f + i]]);
  }
}

TEST(ProgressiveMesh, LodForTriangleCount) {
  const ProgressiveMesh pm = build_progressive_mesh(make_grid(8, 8), {});
  EXPECT_EQ(pm.lod_for_triangle_count(128), 0u);
  const std::size_t n = pm.lod_for_triangle_count(64);
  EXPECT_LE(pm.triangle_count_at(n), 64u);
  EXPECT_GT(pm.triangle_count_at(n - 1), 64u);
  EXPECT_EQ(pm.lod_for_triangle_count(0), pm.collapses.size());
}

Mesh triangles_mesh(std::vector<std::uint32_t> indices, std::size_t vertices) {
  Mesh m;
  m.name = "bad.off";
  for (std::size_t v = 0; v < vertices; ++v) m.positions.emplace_back(float(v), float(v * v % 7), float(v % 3));
  m.indices = std::move(indices);
  return m;
}

void expect_input_error(const Mesh& mesh, const ProgressiveMeshParams& params, const std::string& expected) {
  try {
    build_progressive_mesh(mesh, params);
    ADD_FAILURE() << "no InputError for " << expected;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.off"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

TEST(ProgressiveMesh, BadInputIsAnInputError) {
  expect_input_error(triangles_mesh({}, 0), {}, "no triangles");
  // Three faces on edge 0-1.
  expect_input_error(triangles_mesh({0, 1, 2, 1, 0, 3, 0, 1, 4}, 5), {}, "non-manifold edge");
  // Two fans touching at vertex 0.
  expect_input_error(triangles_mesh({0, 1, 2, 0, 3, 4}, 5), {}, "vertex 0");
  // Face 1 wound against face 0.
  expect_input_error(triangles_mesh({0, 1, 2, 0, 1, 3}, 4), {}, "inconsistent winding");
  expect_input_error(triangles_mesh({0, 1, 1}, 3), {}, "repeats a vertex");
  expect_input_error(triangles_mesh({0, 1, 7}, 3), {}, "vertex index 7");
  Mesh nan = triangles_mesh({0, 1, 2}, 3);
  nan.positions[2].y = std::nanf("");
  expect_input_error(nan, {}, "vertex 2 has a non-finite position");
  ProgressiveMeshParams big;
  big.min_triangles = 3;
  expect_input_error(triangles_mesh({0, 1, 2, 0, 2, 3}, 4), big, "--min-triangles 3");
}

}  // namespace
}  // namespace rastrace
