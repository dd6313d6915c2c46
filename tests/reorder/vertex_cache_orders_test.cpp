// The general-mesh orders on real meshes: every registered algorithm gives a permutation of the
// faces with their winding; tipsy and forsyth against meshoptimizer 0.18 in the same run.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include "cache_sim/vertex_cache.h"
#include "reorder/ordering.h"
#include "scenes/procedural.h"
#include "tests/support/ordering_checks.h"
#include "tests/support/test_data.h"
#include "tests/support/test_meshes.h"

namespace rastrace {
namespace {

const Mesh& test_mesh(const std::string& name) {
  static const Mesh grid = make_grid(16, 16);
  return name == "grid" ? grid : testing::cached_mesh(name + ".off");
}

ReorderParams params_for(unsigned cache) {
  ReorderParams params;
  params.cache_size = cache;
  params.time_budget_seconds = 0.25;  // iterative algorithms: keep the suite fast (ASan too)
  return params;
}

std::uint64_t fifo_misses(std::span<const std::uint32_t> indices, PrimitiveType type, unsigned cache,
                          RestartIndex restart = kNoRestart) {
  return simulate_vertex_stream(indices, type, VertexCachePolicy::Fifo, cache, restart).misses;
}

TEST(VertexCacheOrders, EveryAlgorithmPermutesFacesKeepingWinding) {
  for (const char* name : {"grid", "fandisk", "triceratops", "bunny00"}) {
    const Mesh& mesh = test_mesh(name);
    for (const ReorderAlgorithm& algorithm : reorder_algorithms()) {
      if (!reorder_algorithm_applies(algorithm, mesh)) continue;
      const Ordering ordering = algorithm.run(mesh, params_for(16));
      testing::expect_permutation_with_winding(mesh, ordering, algorithm.name + " on " + name);
    }
  }
}

// Sander et al.'s algorithm and meshoptimizer's implementation of it make the same choices: the
// orders agree to the miss.
TEST(VertexCacheOrders, TipsyWithinTwoPercentOfMeshoptimizerFifo) {
  for (const char* name : {"fandisk", "triceratops", "bunny00"}) {
    const Mesh& mesh = test_mesh(name);
    const Ordering ours = reorder_tipsy(mesh, params_for(16));
    std::vector<std::uint32_t> peer(mesh.indices.size());
    meshopt_optimizeVertexCacheFifo(peer.data(), mesh.indices.data(), mesh.indices.size(), mesh.vertex_count(), 16);
    const double ratio =
        double(fifo_misses(ours.indices, ours.type, 16)) / double(fifo_misses(peer, PrimitiveType::TriangleList, 16));
    EXPECT_LE(ratio, 1.02) << name;
  }
}

TEST(VertexCacheOrders, ForsythWithinThreePercentOfMeshoptimizer) {
  for (const char* name : {"fandisk", "triceratops", "bunny00"}) {
    const Mesh& mesh = test_mesh(name);
    const Ordering ours = reorder_forsyth(mesh, params_for(16));
    std::vector<std::uint32_t> peer(mesh.indices.size());
    meshopt_optimizeVertexCache(peer.data(), mesh.indices.data(), mesh.indices.size(), mesh.vertex_count());
    const double ratio =
        double(fifo_misses(ours.indices, ours.type, 16)) / double(fifo_misses(peer, PrimitiveType::TriangleList, 16));
    EXPECT_LE(ratio, 1.03) << name;
  }
}

// Pinned figures (FIFO 16, CGAL's fandisk.off: 12,946 faces, 6,475 vertices): a change in any
// algorithm shows up here first.
TEST(VertexCacheOrders, FandiskAcmrAtFifo16) {
  const Mesh& mesh = test_mesh("fandisk");
  ASSERT_EQ(mesh.face_count(), 12946u);
  const auto acmr = [&](const char* algo) {
    const Ordering o = find_reorder_algorithm(algo).run(mesh, params_for(16));
    return simulate_vertex_stream(o.indices, o.type, VertexCachePolicy::Fifo, 16).acmr();
  };
  EXPECT_NEAR(acmr("tipsy"), 0.652, 0.0005);
  EXPECT_NEAR(acmr("forsyth"), 0.706, 0.0005);
  EXPECT_NEAR(acmr("kcache"), 0.601, 0.0005);
  EXPECT_NEAR(acmr("morton"), 0.861, 0.0005);
  EXPECT_NEAR(acmr("hilbert"), 0.865, 0.0005);
}

// Best of ours against meshoptimizer's best: tests/reorder/best_order_test.cpp, on every CGAL mesh.

}  // namespace
}  // namespace rastrace

namespace rastrace {
namespace {

// Awkward but legal input: no faces; degenerate faces; unreferenced vertices; a NaN coordinate;
// several components. Every algorithm still returns a permutation.
TEST(VertexCacheOrders, AwkwardMeshesStillGivePermutations) {
  Mesh empty;
  empty.name = "empty";
  Mesh odd;
  odd.name = "odd";
  for (int i = 0; i < 12; ++i) odd.positions.emplace_back(float(i), float(i % 3), 0.0f);
  odd.positions[5].x = std::nanf("");
  odd.indices = {0, 1, 2, 2, 1, 3, 4, 4, 4, 5, 6, 5, 7, 8, 9, 9, 8, 10, 1, 1, 3};  // 11 unused
  for (const Mesh* mesh : {&empty, &odd}) {
    for (const ReorderAlgorithm& algorithm : reorder_algorithms()) {
      if (!reorder_algorithm_applies(algorithm, *mesh)) continue;
      const Ordering ordering = algorithm.run(*mesh, params_for(16));
      testing::expect_permutation_with_winding(*mesh, ordering, algorithm.name + " on " + mesh->name);
    }
  }
}

}  // namespace
}  // namespace rastrace
