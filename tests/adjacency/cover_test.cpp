#include <gtest/gtest.h>

#include "adjacency_fixture.h"
#include "reorder/adjacency/bound.h"
#include "reorder/adjacency/cover.h"
#include "scenes/procedural.h"

namespace rastrace {
namespace {

using testing::built_mesh;

Mesh tetrahedron() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  return m;
}

Mesh octahedron() {
  Mesh m;
  m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.indices = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  return m;
}

struct PaperMesh {
  const char* file;
  std::uint64_t dual_edges;
  std::uint64_t join;  // minimum V_odd-join: exact, the matching optimum is unique in value
};

class CoverOnPaperMeshes : public ::testing::TestWithParam<PaperMesh> {};

TEST_P(CoverOnPaperMeshes, IsMinimalCoversHalfTheFacesAndIsWithinFourPercentOfTheLowerBound) {
  const auto& built = built_mesh(GetParam().file);
  const AdjacencyDual& dual = built.build.dual;
  const CoverResult& cover = built.build.cover;
  EXPECT_TRUE(is_edge_cover(dual, cover.in_cover));
  EXPECT_TRUE(is_minimal_cover(dual, cover.in_cover));
  const double fraction = double(cover.size) / dual.face_count;
  EXPECT_GE(fraction, 0.52);
  EXPECT_LE(fraction, 0.57);
  EXPECT_LT(cover.size, cover.greedy_size);  // the local search improves on the greedy start

  const CoverBound bound = adjacency_cover_lower_bound(built.mesh, dual);
  EXPECT_EQ(bound.dual_edges, GetParam().dual_edges);
  EXPECT_EQ(bound.join_edges, GetParam().join);
  const double c_over_b = cover.size / bound.bound;
  EXPECT_GE(c_over_b, 1.0);
  EXPECT_LE(c_over_b, 1.04);
}

INSTANTIATE_TEST_SUITE_P(Sander2008, CoverOnPaperMeshes,
                         ::testing::Values(PaperMesh{"fandisk.off", 19419, 697},
                                           PaperMesh{"triceratops.off", 8490, 637},
                                           PaperMesh{"bunny00.off", 113112, 9392}),
                         [](const auto& info) {
                           std::string name = info.param.file;
                           return name.substr(0, name.find('.'));
                         });

TEST(AdjacencyCover, TetrahedronNeedsThreeFacesAndItsBoundIsEightThirds) {
  const Mesh mesh = tetrahedron();
  const AdjacencyDual dual = build_adjacency_dual(mesh);
  const CoverResult cover = find_adjacency_cover(dual);
  EXPECT_EQ(cover.size, 3u);
  EXPECT_TRUE(is_minimal_cover(dual, cover.in_cover));
  const CoverBound bound = adjacency_cover_lower_bound(mesh, dual);
  EXPECT_EQ(bound.odd_vertices, 4u);  // every vertex has degree 3
  EXPECT_EQ(bound.join_edges, 2u);
  EXPECT_NEAR(bound.bound, 8.0 / 3.0, 1e-12);
}

TEST(AdjacencyCover, OctahedronReachesTheBoundOfFourFaces) {
  const Mesh mesh = octahedron();
  const AdjacencyDual dual = build_adjacency_dual(mesh);
  const CoverResult cover = find_adjacency_cover(dual);
  const CoverBound bound = adjacency_cover_lower_bound(mesh, dual);
  EXPECT_EQ(bound.join_edges, 0u);  // all degrees even
  EXPECT_DOUBLE_EQ(bound.bound, 4.0);
  EXPECT_EQ(cover.size, 4u);  // optimal: half the faces, as in a regular region
}

TEST(AdjacencyCover, PruningIllegalPathsKeepsTheMatchingOptimum) {
  for (const char* file : {"eight.off", "blob-closed.off", "dragknob.off"}) {
    const Mesh& mesh = testing::cached_mesh(file);
    const AdjacencyDual dual = build_adjacency_dual(mesh);
    const CoverBound pruned = adjacency_cover_lower_bound(mesh, dual, true);
    const CoverBound full = adjacency_cover_lower_bound(mesh, dual, false);
    EXPECT_EQ(pruned.join_edges, full.join_edges) << file;
    EXPECT_LT(pruned.pruned_edges, full.pruned_edges) << file;
    EXPECT_EQ(full.pruned_edges, full.odd_vertices * (full.odd_vertices - 1) / 2) << file;
  }
}

TEST(AdjacencyCover, BoundaryFacesAreForcedAndTheBoundUsesTheBoundarySink) {
  const Mesh& mesh = testing::cached_mesh("elephant-with-holes.off");
  const AdjacencyDual dual = build_adjacency_dual(mesh);
  EXPECT_EQ(dual.boundary_slot_count, 1353u);
  CoverParams params;
  params.seed = 3;
  const CoverResult cover = find_adjacency_cover(dual, params);
  EXPECT_EQ(cover.forced, dual.boundary_face_count);
  for (std::uint32_t f = 0; f < dual.face_count; ++f)
    if (dual.kind[f] == DualFaceKind::Boundary) {
      ASSERT_TRUE(cover.in_cover[f]) << f;
    }
  EXPECT_TRUE(is_minimal_cover(dual, cover.in_cover));
  const CoverBound bound = adjacency_cover_lower_bound(mesh, dual);
  EXPECT_GE(cover.size, bound.bound);
  EXPECT_EQ(bound.odd_vertices % 2, 0u);
}

TEST(AdjacencyCover, GridCoverIsHalfTheInteriorPlusTheBoundaryRing) {
  const Mesh mesh = make_grid(16, 16);
  const AdjacencyDual dual = build_adjacency_dual(mesh);
  const CoverResult cover = find_adjacency_cover(dual);
  EXPECT_TRUE(is_minimal_cover(dual, cover.in_cover));
  EXPECT_EQ(dual.boundary_slot_count, 64u);
  EXPECT_GE(cover.size, adjacency_cover_lower_bound(mesh, dual).bound);
}

TEST(AdjacencyCover, SameSeedSameCoverOtherSeedStillMinimal) {
  const Mesh& mesh = testing::cached_mesh("triceratops.off");
  const AdjacencyDual dual = build_adjacency_dual(mesh);
  CoverParams params;
  params.max_iterations = 20000;
  const CoverResult a = find_adjacency_cover(dual, params);
  const CoverResult b = find_adjacency_cover(dual, params);
  EXPECT_EQ(a.in_cover, b.in_cover);
  params.seed = 7;
  const CoverResult c = find_adjacency_cover(dual, params);
  EXPECT_TRUE(is_minimal_cover(dual, c.in_cover));
  EXPECT_NE(a.in_cover, c.in_cover);
}

TEST(AdjacencyCover, ZeroIterationsGivesTheMinimalGreedyCover) {
  const Mesh& mesh = testing::cached_mesh("triceratops.off");
  const AdjacencyDual dual = build_adjacency_dual(mesh);
  CoverParams params;
  params.max_iterations = 0;
  const CoverResult cover = find_adjacency_cover(dual, params);
  EXPECT_EQ(cover.size, cover.greedy_size);
  EXPECT_EQ(cover.size, 3191u);
  EXPECT_TRUE(is_minimal_cover(dual, cover.in_cover));
}

}  // namespace
}  // namespace rastrace
