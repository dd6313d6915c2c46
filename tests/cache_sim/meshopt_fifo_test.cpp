// rastrace's FIFO vertex cache against meshoptimizer's meshopt_analyzeVertexCache (a pure FIFO
// with warp and primitive-group limits off) on the CGAL meshes, in file order and after
// meshoptimizer's two reorderings: the miss counts must be identical for k = 4..64.
#include <meshoptimizer.h>

#include <gtest/gtest.h>

#include "cache_sim/live_bank_sink.h"
#include "cache_sim/vertex_cache.h"
#include "tests/support/test_data.h"
#include "tests/support/test_meshes.h"

namespace rastrace {
namespace {

TEST(MeshoptFifo, MissesEqualMeshoptAnalyzeVertexCacheOnCgalMeshesInEveryOrder) {
  int compared = 0;
  for (const char* name : {"fandisk.off", "triceratops.off", "elephant.off", "bunny00.off", "cow.off"}) {
    const Mesh& mesh = testing::cached_mesh(name);
    ASSERT_FALSE(mesh.indices.empty()) << name;
    const std::size_t n = mesh.indices.size(), vertices = mesh.positions.size();
    std::vector<std::uint32_t> forsyth(n), tipsy(n);
    meshopt_optimizeVertexCache(forsyth.data(), mesh.indices.data(), n, vertices);
    meshopt_optimizeVertexCacheFifo(tipsy.data(), mesh.indices.data(), n, vertices, 16);
    for (const std::vector<std::uint32_t>* order :
         std::initializer_list<const std::vector<std::uint32_t>*>{&mesh.indices, &forsyth, &tipsy})
      for (unsigned k : {4u, 5u, 8u, 12u, 16u, 20u, 24u, 32u, 48u, 64u}) {
        const VertexStreamStats ours =
            simulate_vertex_stream(*order, PrimitiveType::TriangleList, VertexCachePolicy::Fifo, k);
        const meshopt_VertexCacheStatistics theirs = meshopt_analyzeVertexCache(order->data(), n, vertices, k, 0, 0);
        ASSERT_EQ(ours.misses, theirs.vertices_transformed) << name << " k=" << k;
        ++compared;
      }
  }
  EXPECT_EQ(compared, 5 * 3 * 10);
}

TEST(MeshoptFifo, ReorderedFandiskHasTheAcmrMeshoptimizerReports) {
  // The ACMR that meshopt_analyzeVertexCache reports, reproduced through the live bank (the
  // renderer's path) to three decimals.
  const Mesh& mesh = testing::cached_mesh("fandisk.off");
  std::vector<std::uint32_t> tipsy(mesh.indices.size());
  meshopt_optimizeVertexCacheFifo(tipsy.data(), mesh.indices.data(), tipsy.size(), mesh.positions.size(), 16);
  const meshopt_VertexCacheStatistics theirs =
      meshopt_analyzeVertexCache(tipsy.data(), tipsy.size(), mesh.positions.size(), 16, 0, 0);
  CacheBankConfig config;
  config.vertex.push_back(vertex_cache_spec(VertexCachePolicy::Fifo, 16));
  LiveBankSink bank(config, {});
  bank.begin_draw({0, PrimitiveType::TriangleList, kNoRestart});
  std::vector<VertexFetch> fetches;
  for (std::size_t i = 0; i < tipsy.size(); ++i) fetches.push_back({tipsy[i], i % 3 == 0});
  bank.vertex_fetches(fetches);
  bank.end_draw();
  bank.finish();
  const VertexStreamStats& stats = bank.vertex_stats()[0];
  EXPECT_EQ(stats.triangles, 12946u);
  EXPECT_EQ(stats.misses, theirs.vertices_transformed);
  EXPECT_NEAR(stats.acmr(), theirs.acmr, 0.0005);
}

}  // namespace
}  // namespace rastrace
