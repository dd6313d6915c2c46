// NvTriStrip's stripifier (`nvstrip`): strips cut into pieces of K - 6 faces, one strip stream
// with a restart per piece, every face drawn once with its winding.
#include <gtest/gtest.h>

#include "reorder/nvstrip.h"
#include "reorder/strip.h"
#include "scenes/mesh_io.h"
#include "scenes/procedural.h"
#include "tests/support/ordering_checks.h"
#include "tests/support/test_data.h"

namespace rastrace {
namespace {

// Drawn triangles of each restart-separated strip.
std::vector<std::size_t> strip_lengths(const Ordering& ordering) {
  std::vector<std::size_t> lengths;
  std::size_t run = 0;
  for (const std::uint32_t index : ordering.indices) {
    if (index == ordering.restart_index) {
      lengths.push_back(run);
      run = 0;
    } else {
      ++run;
    }
  }
  lengths.push_back(run);
  return lengths;
}

TEST(Nvstrip, PiecesHoldAtMostKMinusSixFacesPlusASmallRemainder) {
  const Mesh triceratops = load_mesh(testing::data_file("meshes/triceratops.off"));
  for (const unsigned cache : {12u, 16u, 24u}) {
    ReorderParams params;
    params.cache_size = cache;
    const Ordering ordering = reorder_nvstrip(triceratops, params);
    testing::expect_permutation_with_winding(triceratops, ordering, "FIFO " + std::to_string(cache));
    EXPECT_EQ(ordering.type, PrimitiveType::TriangleStrip);
    const StripStats stats = strip_stats(ordering.indices, ordering.type, ordering.restart_index);
    EXPECT_EQ(stats.triangles, triceratops.face_count());
    // A piece of n faces sends n + 2 indices plus its swaps; a remainder of 1-3 faces stays on
    // the last piece of a strip, so no piece has more than K - 6 + 3 faces.
    for (const std::size_t indices : strip_lengths(ordering)) EXPECT_LE(indices, 2 * (cache - 6 + 3) + 2);
    EXPECT_GE(stats.strips, triceratops.face_count() / (cache - 6 + 3));
  }
}

TEST(Nvstrip, TinyCachesAndAwkwardMeshes) {
  const Mesh grid = make_grid(4, 4);
  for (const unsigned cache : {0u, 1u, 6u, 7u, 5000u}) {
    ReorderParams params;
    params.cache_size = cache;
    testing::expect_permutation_with_winding(grid, reorder_nvstrip(grid, params), "FIFO " + std::to_string(cache));
  }
  // A degenerate face, a duplicate face and an isolated face are all still drawn.
  Mesh odd;
  odd.name = "odd";
  for (int i = 0; i < 7; ++i) odd.positions.emplace_back(float(i), float(i % 2), 0.0f);
  odd.indices = {0, 1, 2, 2, 1, 3, 2, 1, 3, 4, 4, 5, 4, 5, 6};
  testing::expect_permutation_with_winding(odd, reorder_nvstrip(odd, ReorderParams{}), "odd");
}

}  // namespace
}  // namespace rastrace
