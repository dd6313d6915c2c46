#include <algorithm>
#include <numeric>

#include "core/error.h"

#include <gtest/gtest.h>

#include "adjacency_fixture.h"
#include "cache_sim/vertex_cache.h"
#include "reorder/adjacency/order.h"
#include "reorder/ordering.h"

namespace rastrace {
namespace {

double misses_per_vertex(const Mesh& mesh, const AdjacencyPrimitives& primitives,
                         const std::vector<std::uint32_t>& order, unsigned cache = 24) {
  const AdjacencyPrimitives ordered = permute_primitives(primitives, order);
  const VertexStreamStats stats =
      simulate_vertex_stream(ordered.indices, PrimitiveType::TriangleListAdjacency, VertexCachePolicy::Fifo, cache);
  EXPECT_EQ(stats.lookups, 6 * primitives.size());
  return double(stats.misses) / double(mesh.vertex_count());
}

void expect_permutation(std::vector<std::uint32_t> order, std::size_t n) {
  ASSERT_EQ(order.size(), n);
  std::sort(order.begin(), order.end());
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(order[i], i);
}

struct Expected {
  const char* file;
  // CM/V at seed 1, cache 24, from one run of `rastrace adjacency MESH` (docs/PERFORMANCE.md).
  double careful, fast, baseline, baseline_mesh;
};

class OrderingOnPaperMeshes : public ::testing::TestWithParam<Expected> {};

// The goals at cache 24 (the paper's figures with a margin): careful CM/V <= 1.60, fast <= 1.85, and their gains over
// the baseline >= 1.6 and >= 1.4. Against `baseline` (kcache on the cover faces alone) and against `baseline-mesh`
// (kcache on the whole mesh, the paper's naive use of a triangle method) the gains are met on all three meshes (over
// `baseline`: 1.70-2.01 and 1.46-1.79).
TEST_P(OrderingOnPaperMeshes, CarefulAndFastBeatBothBaselinesAtCache24) {
  const auto& built = testing::built_mesh(GetParam().file);
  const AdjacencyPrimitives& primitives = built.build.primitives;
  const auto careful = order_adjacency(AdjacencyOrder::Careful, built.mesh, primitives, 24);
  const auto fast = order_adjacency(AdjacencyOrder::Fast, built.mesh, primitives, 24);
  const auto baseline = order_adjacency(AdjacencyOrder::Baseline, built.mesh, primitives, 24);
  const auto baseline_mesh = order_adjacency(AdjacencyOrder::BaselineMesh, built.mesh, primitives, 24);
  expect_permutation(careful, primitives.size());
  expect_permutation(fast, primitives.size());
  expect_permutation(baseline, primitives.size());
  expect_permutation(baseline_mesh, primitives.size());
  const double c = misses_per_vertex(built.mesh, primitives, careful);
  const double f = misses_per_vertex(built.mesh, primitives, fast);
  const double b = misses_per_vertex(built.mesh, primitives, baseline);
  const double m = misses_per_vertex(built.mesh, primitives, baseline_mesh);
  EXPECT_NEAR(c, GetParam().careful, 0.0005);
  EXPECT_NEAR(f, GetParam().fast, 0.0005);
  EXPECT_NEAR(b, GetParam().baseline, 0.0005);
  EXPECT_NEAR(m, GetParam().baseline_mesh, 0.0005);
  EXPECT_LE(c, 1.50);
  EXPECT_LE(f, 1.85);
  EXPECT_GE(m / c, 1.6);
  EXPECT_GE(m / f, 1.4);
  EXPECT_GE(b / c, 1.6);
  EXPECT_GE(b / f, 1.4);
  EXPECT_GT(m, b);  // the whole-mesh order serves the cover primitives worse
}

INSTANTIATE_TEST_SUITE_P(Sander2008, OrderingOnPaperMeshes,
                         ::testing::Values(Expected{"fandisk.off", 1.456, 1.636, 2.925, 3.129},
                                           Expected{"triceratops.off", 1.442, 1.680, 2.458, 2.785},
                                           Expected{"bunny00.off", 1.459, 1.718, 2.624, 2.927}),
                         [](const auto& info) {
                           std::string name = info.param.file;
                           return name.substr(0, name.find('.'));
                         });

TEST(AdjacencyOrdering, BaselineMeshDrawsEachPrimitiveAtItsFirstFaceInKcacheOrder) {
  const auto& built = testing::built_mesh("triceratops.off");
  const AdjacencyPrimitives& primitives = built.build.primitives;
  ReorderParams params;
  params.cache_size = 24;
  const std::vector<std::uint32_t> faces = find_reorder_algorithm("kcache").run(built.mesh, params).face_order;
  std::vector<std::uint32_t> position(faces.size());
  for (std::uint32_t i = 0; i < faces.size(); ++i) position[faces[i]] = i;
  const auto order = order_adjacency_baseline_mesh(built.mesh, primitives, 24);
  expect_permutation(order, primitives.size());
  std::uint32_t previous = 0, with_assigned_first = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::uint32_t p = order[i];
    std::uint32_t first = position[primitives.cover_face[p]];
    if (primitives.assigned_face[p] != kNoFace && position[primitives.assigned_face[p]] < first) {
      first = position[primitives.assigned_face[p]];
      ++with_assigned_first;
    }
    if (i > 0) {
      EXPECT_LT(previous, first) << "primitive " << i;
    }
    previous = first;
  }
  EXPECT_GT(with_assigned_first, primitives.size() / 10);  // not simply the cover faces' order
}

// The look-ahead was tuned at cache 24; other sizes gain as much (the greedy without it, at
// cache 12 / 16 / 32: 2.105 / 1.751 / 1.363; the first version of careful: 2.239 / 1.849 / 1.397).
TEST(AdjacencyOrdering, CarefulOnTriceratopsAtOtherCacheSizes) {
  const auto& built = testing::built_mesh("triceratops.off");
  const AdjacencyPrimitives& primitives = built.build.primitives;
  for (const auto& [cache, expected] : {std::pair{12u, 2.004}, std::pair{16u, 1.665}, std::pair{32u, 1.319}})
    EXPECT_NEAR(misses_per_vertex(built.mesh, primitives, order_adjacency_careful(primitives, 2832, cache), cache),
                expected, 0.0005)
        << "cache " << cache;
}

TEST(AdjacencyOrdering, OrdersAreDeterministicAndHandleTinyCaches) {
  const auto& built = testing::built_mesh("triceratops.off");
  const AdjacencyPrimitives& primitives = built.build.primitives;
  EXPECT_EQ(order_adjacency_careful(primitives, 2832, 24), order_adjacency_careful(primitives, 2832, 24));
  EXPECT_EQ(order_adjacency_fast(primitives, 2832, 24), order_adjacency_fast(primitives, 2832, 24));
  for (const unsigned cache : {1u, 3u, 6u}) {
    expect_permutation(order_adjacency_careful(primitives, 2832, cache), primitives.size());
    expect_permutation(order_adjacency_fast(primitives, 2832, cache), primitives.size());
  }
  // A larger cache never hurts the careful order much: CM/V falls towards 1.
  const double at12 = misses_per_vertex(built.mesh, primitives, order_adjacency_careful(primitives, 2832, 12), 12);
  const double at32 = misses_per_vertex(built.mesh, primitives, order_adjacency_careful(primitives, 2832, 32), 32);
  EXPECT_LT(at32, at12);
}

TEST(AdjacencyOrdering, ParsesItsNames) {
  EXPECT_EQ(parse_adjacency_order("careful"), AdjacencyOrder::Careful);
  EXPECT_EQ(parse_adjacency_order("fast"), AdjacencyOrder::Fast);
  EXPECT_EQ(parse_adjacency_order("baseline"), AdjacencyOrder::Baseline);
  EXPECT_EQ(parse_adjacency_order("baseline-mesh"), AdjacencyOrder::BaselineMesh);
  EXPECT_STREQ(to_string(AdjacencyOrder::BaselineMesh), "baseline-mesh");
  EXPECT_THROW(parse_adjacency_order("tipsy"), InputError);
}

}  // namespace
}  // namespace rastrace
