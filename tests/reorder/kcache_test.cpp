// K-Cache-Reorder (Lin and Yu 2006) against an independent model of the same rule: the cost
// C1 - 0.5 C2 + 1.3 C3 over the resident vertices, fans emitted with the completed-triangle rule.
// That model's FIFO ACMR, ordered for and run on the same K, is the expectation to 0.01.
#include <gtest/gtest.h>

#include "cache_sim/vertex_cache.h"
#include "reorder/kcache.h"
#include "scenes/mesh_io.h"
#include "scenes/procedural.h"
#include "tests/support/ordering_checks.h"
#include "tests/support/test_data.h"

namespace rastrace {
namespace {

double kcache_acmr(const Mesh& mesh, unsigned cache) {
  ReorderParams params;
  params.cache_size = cache;
  const Ordering ordering = reorder_kcache(mesh, params);
  testing::expect_permutation_with_winding(mesh, ordering, mesh.name + " FIFO " + std::to_string(cache));
  return simulate_vertex_stream(ordering.indices, ordering.type, VertexCachePolicy::Fifo, cache).acmr();
}

struct ModelRow {
  unsigned cache;
  double acmr;
};

// At FIFO 12 the grid is 0.021 below the model's 0.623 (308 misses against about 319). The grid
// starts from one corner and has no dead end, so the run is one chain of exact ties broken the
// same way each time, and the push order inside a triangle is enough to move it: the same grid
// with each triangle's corners rotated gives 0.615. The real meshes agree to 0.005.
TEST(KCacheReorder, GridWithinAHundredthOfTheIndependentModelAtFifo16And20) {
  const Mesh grid = make_grid(16, 16);
  for (const ModelRow row : {ModelRow{16, 0.590}, ModelRow{20, 0.564}})
    EXPECT_NEAR(kcache_acmr(grid, row.cache), row.acmr, 0.01) << "FIFO " << row.cache;
  EXPECT_NEAR(kcache_acmr(grid, 12), 308.0 / 512.0, 1e-9);
}

TEST(KCacheReorder, FandiskWithinAHundredthOfTheIndependentModel) {
  const Mesh fandisk = load_mesh(testing::data_file("meshes/fandisk.off"));
  ASSERT_EQ(fandisk.face_count(), 12946u);
  for (const ModelRow row : {ModelRow{12, 0.625}, ModelRow{16, 0.597}, ModelRow{20, 0.579}})
    EXPECT_NEAR(kcache_acmr(fandisk, row.cache), row.acmr, 0.01) << "FIFO " << row.cache;
}

TEST(KCacheReorder, TriceratopsAndBunnyWithinAHundredthOfTheIndependentModel) {
  const Mesh triceratops = load_mesh(testing::data_file("meshes/triceratops.off"));
  for (const ModelRow row : {ModelRow{12, 0.646}, ModelRow{16, 0.615}, ModelRow{20, 0.601}})
    EXPECT_NEAR(kcache_acmr(triceratops, row.cache), row.acmr, 0.01) << "triceratops FIFO " << row.cache;
  const Mesh bunny = load_mesh(testing::data_file("meshes/bunny00.off"));
  for (const ModelRow row : {ModelRow{12, 0.644}, ModelRow{16, 0.612}, ModelRow{20, 0.595}})
    EXPECT_NEAR(kcache_acmr(bunny, row.cache), row.acmr, 0.01) << "bunny00 FIFO " << row.cache;
}

}  // namespace
}  // namespace rastrace
