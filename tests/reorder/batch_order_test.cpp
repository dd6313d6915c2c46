// The batch-aware order (reorder/batch.cpp) under the batch model it is made for, against the
// FIFO-tuned orders: fewer shader invocations under kerbl-nv on fandisk and triceratops.
#include <gtest/gtest.h>

#include "cache_sim/vertex_reuse.h"
#include "reorder/ordering.h"
#include "tests/support/ordering_checks.h"
#include "tests/support/test_meshes.h"

namespace rastrace {
namespace {

std::uint64_t invocations(const Ordering& ordering, const char* preset) {
  return simulate_vertex_reuse(ordering.indices, ordering.type, find_vertex_reuse_preset(preset)->spec,
                               ordering.restart_index)
      .misses;
}

TEST(BatchOrder, IsAPermutationAndBeatsEveryFifoTunedOrderUnderTheNvidiaBatchModel) {
  for (const char* name : {"fandisk.off", "triceratops.off"}) {
    const Mesh& mesh = testing::cached_mesh(name);
    ReorderParams params;  // FIFO 16, the orders' default target
    const Ordering batch = find_reorder_algorithm("batch").run(mesh, params);
    testing::expect_permutation_with_winding(mesh, batch, name);
    const std::uint64_t ours = invocations(batch, "kerbl-nv");
    for (const char* fifo_tuned : {"forsyth", "tipsy", "kcache", "greedy"}) {
      const Ordering other = find_reorder_algorithm(fifo_tuned).run(mesh, params);
      EXPECT_LT(ours, invocations(other, "kerbl-nv")) << name << " against " << fifo_tuned;
    }
  }
}

}  // namespace
}  // namespace rastrace
