#include <algorithm>
#include <numeric>

#include "core/error.h"

#include <gtest/gtest.h>

#include "adjacency_fixture.h"
#include "cache_sim/vertex_cache.h"
#include "reorder/adjacency_order.h"

namespace rastrace {
namespace {

double misses_per_vertex(const Mesh& mesh, const AdjacencyPrimitives& primitives, const std::vector<std::uint32_t>& order,
                         unsigned cache = 24) {
  const AdjacencyPrimitives ordered = permute_primitives(primitives, order);
  const VertexStreamStats stats = simulate_vertex_stream(ordered.indices, PrimitiveType::TriangleListAdjacency,
                                                         VertexCachePolicy::Fifo, cache);
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
  double careful_cmv, fast_cmv;    // measured at seed 1, cache 24
  double careful_gain, fast_gain;  // over kcache on the cover faces
};

class OrderingOnPaperMeshes : public ::testing::TestWithParam<Expected> {};

TEST_P(OrderingOnPaperMeshes, CarefulAndFastBeatTheBaselineAtCache24) {
  const auto& built = testing::built_mesh(GetParam().file);
  const AdjacencyPrimitives& primitives = built.build.primitives;
  const auto careful = order_adjacency(AdjacencyOrder::Careful, built.mesh, primitives, 24);
  const auto fast = order_adjacency(AdjacencyOrder::Fast, built.mesh, primitives, 24);
  const auto baseline = order_adjacency(AdjacencyOrder::Baseline, built.mesh, primitives, 24);
  expect_permutation(careful, primitives.size());
  expect_permutation(fast, primitives.size());
  expect_permutation(baseline, primitives.size());
  const double c = misses_per_vertex(built.mesh, primitives, careful);
  const double f = misses_per_vertex(built.mesh, primitives, fast);
  const double b = misses_per_vertex(built.mesh, primitives, baseline);
  EXPECT_LE(c, 1.60);
  EXPECT_LE(f, 1.85);
  EXPECT_NEAR(c, GetParam().careful_cmv, 0.0005);
  EXPECT_NEAR(f, GetParam().fast_cmv, 0.0005);
  EXPECT_NEAR(b / c, GetParam().careful_gain, 0.0005);
  EXPECT_NEAR(b / f, GetParam().fast_gain, 0.0005);
}

INSTANTIATE_TEST_SUITE_P(Sander2008, OrderingOnPaperMeshes,
                         ::testing::Values(Expected{"fandisk.off", 1.580, 1.636, 1.573, 1.519},
                                           Expected{"triceratops.off", 1.501, 1.680, 1.353, 1.209},
                                           Expected{"bunny00.off", 1.535, 1.718, 1.410, 1.260}),
                         [](const auto& info) {
                           std::string name = info.param.file;
                           return name.substr(0, name.find('.'));
                         });

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
  EXPECT_THROW(parse_adjacency_order("tipsy"), InputError);
}

}  // namespace
}  // namespace rastrace
