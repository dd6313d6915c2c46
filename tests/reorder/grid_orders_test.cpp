// Castano's 16x16 grid table (REFERENCE.md): the Scanline and Optimal rows reproduced exactly,
// the published baselines approached, and the "optimized for 8, run on 16" figure. His table was
// counted by NVIDIA Mesh Tools' eviction-charged accounting (cache_sim/eviction_charged.h); each
// figure is checked under it and under a strict FIFO, where they differ.
#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include "cache_sim/eviction_charged.h"
#include "cache_sim/vertex_cache.h"
#include "core/error.h"
#include "reorder/ordering.h"
#include "scenes/procedural.h"

namespace rastrace {
namespace {

VertexStreamStats run_on_fifo(const std::string& algo, const Mesh& mesh, unsigned target, unsigned simulated) {
  ReorderParams params;
  params.cache_size = target;
  const Ordering ordering = find_reorder_algorithm(algo).run(mesh, params);
  return simulate_vertex_stream(ordering.indices, ordering.type, VertexCachePolicy::Fifo, simulated,
                                ordering.restart_index);
}

// Transforms as Castano's simulator counted them, for the ordering `algo` makes for `target`.
std::uint64_t charged_on_fifo(const std::string& algo, const Mesh& mesh, unsigned target, unsigned simulated) {
  ReorderParams params;
  params.cache_size = target;
  const Ordering ordering = find_reorder_algorithm(algo).run(mesh, params);
  return eviction_charged_transforms(ordering.indices, ordering.type, simulated, ordering.restart_index);
}

struct CastanoRow {
  unsigned cache;
  double acmr;
  double atvr;
};

TEST(GridOrders, ScanlineMatchesCastanoAtEveryFifoSize) {
  const Mesh grid = make_grid(16, 16);
  for (const unsigned cache : {12u, 16u, 20u}) {
    const VertexStreamStats stats = run_on_fifo("scanline", grid, cache, cache);
    EXPECT_EQ(stats.triangles, 512u);
    EXPECT_EQ(stats.vertices, 289u);
    EXPECT_EQ(stats.misses, 544u) << "FIFO " << cache;
    EXPECT_NEAR(stats.acmr(), 1.062, 0.0005) << "FIFO " << cache;
    EXPECT_NEAR(stats.atvr(), 1.882, 0.0005) << "FIFO " << cache;
  }
}

TEST(GridOrders, OptimalMatchesCastanoAtFifo16And20) {
  const Mesh grid = make_grid(16, 16);
  for (const CastanoRow row : {CastanoRow{20, 0.564, 1.000}, CastanoRow{16, 0.598, 1.059}}) {
    const VertexStreamStats stats = run_on_fifo("grid", grid, row.cache, row.cache);
    EXPECT_EQ(stats.triangles, 512u);
    EXPECT_NEAR(stats.acmr(), row.acmr, 0.0005) << "FIFO " << row.cache;
    EXPECT_NEAR(stats.atvr(), row.atvr, 0.0005) << "FIFO " << row.cache;
  }
  EXPECT_EQ(run_on_fifo("grid", grid, 20, 20).misses, 289u);
  EXPECT_EQ(run_on_fifo("grid", grid, 16, 16).misses, 306u);
}

// The article's gridGen() at FIFO 12 cuts the grid into columns of 10 and 6 quads, both with a
// prefetch row: 11 * 17 + 7 * 17 = 306 true misses (ACMR 0.598), and meshoptimizer's analyzer
// agrees. Castano prints 0.600 / 1.062, i.e. 307: his simulator charges the second column's
// first prefetch triangle (x, x, x + 1) for two transforms of x, as the cache is full then.
TEST(GridOrders, OptimalMatchesCastanoAtFifo12UnderHisAccounting) {
  const Mesh grid = make_grid(16, 16);
  const std::uint64_t charged = charged_on_fifo("grid", grid, 12, 12);
  EXPECT_EQ(charged, 307u);
  EXPECT_NEAR(double(charged) / 512.0, 0.600, 0.0005);
  EXPECT_NEAR(double(charged) / 289.0, 1.062, 0.0005);

  const VertexStreamStats stats = run_on_fifo("grid", grid, 12, 12);
  EXPECT_EQ(stats.misses, 306u);
  ReorderParams params;
  params.cache_size = 12;
  const Ordering ordering = reorder_grid(grid, params);
  const meshopt_VertexCacheStatistics peer =
      meshopt_analyzeVertexCache(ordering.indices.data(), ordering.indices.size(), grid.vertex_count(), 12, 0, 0);
  EXPECT_EQ(peer.vertices_transformed, 306u);
}

// The rows where no later column is prefetched with a full cache: both accountings agree.
TEST(GridOrders, BothAccountingsAgreeOnTheOtherCastanoRows) {
  const Mesh grid = make_grid(16, 16);
  EXPECT_EQ(charged_on_fifo("grid", grid, 20, 20), 289u);
  EXPECT_EQ(charged_on_fifo("grid", grid, 16, 16), 306u);
  for (const unsigned cache : {12u, 16u, 20u}) EXPECT_EQ(charged_on_fifo("scanline", grid, cache, cache), 544u);
}

// Ordered for 8 (columns of 6, 6 and 4 quads, each prefetched): 7 + 7 + 5 vertex columns of 17,
// 323 true misses on FIFO 8 and on FIFO 16 alike (a larger cache cannot help: every vertex is
// reloaded only at a column seam). Castano's comment gives ATVR 1.125 for both, i.e. 325: his
// accounting charges one extra transform at each of the two later prefetch rows.
TEST(GridOrders, OptimalForEightRunOnSixteenMatchesCastanosComment) {
  const Mesh grid = make_grid(16, 16);
  for (const unsigned simulated : {8u, 16u}) {
    const std::uint64_t charged = charged_on_fifo("grid", grid, 8, simulated);
    EXPECT_EQ(charged, 325u) << "FIFO " << simulated;
    EXPECT_NEAR(double(charged) / 289.0, 1.125, 0.0005) << "FIFO " << simulated;
    EXPECT_EQ(run_on_fifo("grid", grid, 8, simulated).misses, 323u) << "FIFO " << simulated;
  }
}

// The accounting is confirmed by a row it was not fitted to: his Morton order is the same curve
// as ours, and under his accounting it gives his three figures exactly (strict FIFO 16: 0.766).
TEST(GridOrders, MortonMatchesCastanoExactlyUnderHisAccounting) {
  const Mesh grid = make_grid(16, 16);
  EXPECT_EQ(charged_on_fifo("morton", grid, 20, 20), 368u);  // 0.719
  EXPECT_EQ(charged_on_fifo("morton", grid, 16, 16), 384u);  // 0.750
  EXPECT_EQ(charged_on_fifo("morton", grid, 12, 12), 416u);  // 0.8125, printed 0.812
  EXPECT_EQ(run_on_fifo("morton", grid, 16, 16).misses, 392u);
}

TEST(GridOrders, CacheOfWidthPlusTwoTransformsEveryVertexOnce) {
  for (const int w : {4, 9, 16, 30}) {
    const Mesh grid = make_grid(w, w);
    const VertexStreamStats stats =
        run_on_fifo("grid", grid, static_cast<unsigned>(w + 2), static_cast<unsigned>(w + 2));
    EXPECT_EQ(stats.misses, grid.vertex_count()) << w << "x" << w;
  }
}

TEST(GridOrders, DegeneratesOnlyInTheIndexStream) {
  const Mesh grid = make_grid(16, 16);
  ReorderParams params;
  params.cache_size = 12;
  const Ordering ordering = reorder_grid(grid, params);
  EXPECT_EQ(ordering.face_order.size(), 512u);
  // Two columns (10 and 6 quads), each with a prefetch row: 16 degenerate triangles.
  EXPECT_EQ(ordering.indices.size(), 3u * (512u + 16u));
  const VertexStreamStats stats = simulate_vertex_stream(ordering.indices, ordering.type, VertexCachePolicy::Fifo, 12);
  EXPECT_EQ(stats.degenerate, 16u);
}

// Castano's rows for the other methods; ours may be at most 10% above them.
TEST(GridOrders, BaselinesWithinTenPercentOfCastano) {
  const Mesh grid = make_grid(16, 16);
  struct Published {
    const char* algo;
    double acmr20, acmr16, acmr12;
  };
  const Published rows[] = {
      {"morton", 0.719, 0.750, 0.812},  {"hilbert", 0.699, 0.754, 0.797}, {"kcache", 0.711, 0.766, 0.807},
      {"forsyth", 0.666, 0.699, 0.859}, {"tipsy", 0.658, 0.711, 0.758},
  };
  for (const Published& row : rows) {
    bool registered = false;
    for (const ReorderAlgorithm& algorithm : reorder_algorithms()) registered |= algorithm.name == row.algo;
    if (!registered) continue;
    EXPECT_LE(run_on_fifo(row.algo, grid, 20, 20).acmr(), row.acmr20 * 1.10) << row.algo << " FIFO 20";
    EXPECT_LE(run_on_fifo(row.algo, grid, 16, 16).acmr(), row.acmr16 * 1.10) << row.algo << " FIFO 16";
    EXPECT_LE(run_on_fifo(row.algo, grid, 12, 12).acmr(), row.acmr12 * 1.10) << row.algo << " FIFO 12";
  }
}

// NvTriStrip's row (0.818 / 0.775 / 0.875 at FIFO 20 / 16 / 12) against `nvstrip`, counted both
// ways: within 10% of it either way at every size. Like his, ours is best at 16, where the
// pieces of 10 faces fit the cache; at 20 the pieces of 14 faces overflow it.
TEST(GridOrders, NvstripWithinTenPercentOfCastanosNvTriStripRow) {
  const Mesh grid = make_grid(16, 16);
  struct Row {
    unsigned cache;
    double published;
    std::uint64_t charged, strict;
  };
  for (const Row row : {Row{20, 0.818, 400, 398}, Row{16, 0.775, 389, 384}, Row{12, 0.875, 431, 429}}) {
    const std::uint64_t charged = charged_on_fifo("nvstrip", grid, row.cache, row.cache);
    const std::uint64_t strict = run_on_fifo("nvstrip", grid, row.cache, row.cache).misses;
    EXPECT_EQ(charged, row.charged) << "FIFO " << row.cache;
    EXPECT_EQ(strict, row.strict) << "FIFO " << row.cache;
    EXPECT_NEAR(double(charged) / 512.0, row.published, 0.10 * row.published) << "FIFO " << row.cache;
    EXPECT_NEAR(double(strict) / 512.0, row.published, 0.10 * row.published) << "FIFO " << row.cache;
  }
}

TEST(GridOrders, GridOrderRejectsMeshesThatAreNotGrids) {
  Mesh mesh = make_grid(4, 4);
  mesh.grid.reset();
  EXPECT_THROW(reorder_grid(mesh, ReorderParams{}), InputError);
  EXPECT_FALSE(reorder_algorithm_applies(find_reorder_algorithm("grid"), mesh));
  Mesh edited = make_grid(4, 4);
  std::swap(edited.indices[0], edited.indices[1]);
  EXPECT_THROW(reorder_grid(edited, ReorderParams{}), InputError);
}

TEST(GridOrders, ScanlineOnNonGridSweepsRows) {
  // The same grid without its grid tag goes through the centroid sweep: same order.
  Mesh mesh = make_grid(8, 8);
  mesh.grid.reset();
  const Ordering ordering = reorder_scanline(mesh, ReorderParams{});
  for (std::uint32_t i = 0; i < ordering.face_order.size(); ++i) EXPECT_EQ(ordering.face_order[i], i);
}

}  // namespace
}  // namespace rastrace
