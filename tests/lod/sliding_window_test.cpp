// Sliding window: no index written at run time, at most 16 bytes per instance, and Forsyth's
// relaxation of the collapse order gives a valid sequence with the same last mesh and fewer levels.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "collapse_sequences.h"
#include "core/error.h"
#include "lod/sliding_window.h"
#include "lod/sliding_window_relax.h"
#include "lod/vanilla.h"
#include "representation_checks.h"
#include "scenes/mesh_io.h"
#include "scenes/procedural.h"
#include "support/test_data.h"

namespace rastrace {
namespace {

using testing::drawn_triangles;
using testing::reference_triangles;

Mesh renumbered(const Mesh& vertices, const std::vector<std::uint32_t>& input_vertex) {
  Mesh out;
  out.name = vertices.name;
  for (std::uint32_t v : input_vertex) out.positions.push_back(vertices.positions[v]);
  return out;
}

TEST(SlidingWindow, WritesNoIndexAndKeepsAtMost16BytesPerInstance) {
  const testing::TestPm t = testing::test_progressive_mesh(make_grid(16, 16), 400);
  auto window = build_sliding_window(t.pm, t.vertices);
  const std::vector<std::uint32_t> before = window->indices();
  LodChangeCost total;
  const std::uint32_t last = window->lod_count() - 1;
  for (std::uint32_t n = 0; n <= last; ++n) total += window->set_lod(n);
  for (std::uint32_t n = last + 1; n-- > 0;) total += window->set_lod(n);
  total += window->set_lod(last / 2);
  EXPECT_EQ(total.index_writes, 0u);
  EXPECT_EQ(total.bytes_copied, 0u);
  EXPECT_EQ(total.level_switches, 0u);
  EXPECT_EQ(window->indices(), before);
  EXPECT_LE(window->memory().instance_bytes, 16u);
  EXPECT_EQ(window->record_bytes(), 8u);
  EXPECT_EQ(window->memory().table_bytes, 8u * (last + 1));
  ASSERT_EQ(window->draws().size(), 1u);
  EXPECT_EQ(window->draws()[0].vertex_count, 289u - last / 2);
}

TEST(SlidingWindow, EveryWindowHoldsTheLodsTrianglesAndTheTableMatchesTheLevels) {
  const testing::TestPm t = testing::test_progressive_mesh(make_grid(16, 16), 400);
  auto window = build_sliding_window(t.pm, t.vertices);
  EXPECT_EQ(window->levels(), sliding_window_level_starts(t.pm).size());
  EXPECT_GT(window->levels(), 2u);
  for (std::uint32_t n = 0; n < window->lod_count(); ++n) {
    window->set_lod(n);
    EXPECT_EQ(window->records()[n].triangles, t.pm.triangle_count_at(n));
    ASSERT_EQ(drawn_triangles(*window), reference_triangles(t.pm, n)) << n;
  }
}

// On a grid most errors tie, so tolerance 0 already re-orders among equal errors; `wider_helps`
// asks that 10% do better still.
void expect_relaxation_is_valid_and_helps(const testing::TestPm& t, std::uint32_t stride, bool wider_helps) {
  const std::size_t strict_levels = sliding_window_level_starts(t.pm).size();
  const RelaxedOrder zero = relax_for_sliding_window(t.pm, 0.0);
  const RelaxedOrder tenth = relax_for_sliding_window(t.pm, 0.1);
  std::printf(
      "%s: %zu collapses, sliding-window levels: QEM order %zu, tolerance 0: %u, tolerance 10%%: %u (%u moved)\n",
      t.pm.name.c_str(), t.pm.collapses.size(), strict_levels, zero.levels, tenth.levels, tenth.out_of_order);
  EXPECT_LE(zero.levels, strict_levels);
  EXPECT_LT(tenth.levels, strict_levels);
  EXPECT_LE(tenth.levels, zero.levels);
  if (wider_helps) {
    EXPECT_LT(tenth.levels, zero.levels);
  }
  EXPECT_GT(tenth.out_of_order, 0u);
  const auto last = static_cast<std::uint32_t>(t.pm.collapses.size());
  // Same last mesh, in the source mesh's vertex ids.
  EXPECT_EQ(reference_triangles(tenth.pm, last, &tenth.pm.vertex_order),
            reference_triangles(t.pm, last, &t.pm.vertex_order));
  // The relaxed order is itself a sequence: sliding window on it draws what vanilla on it draws.
  const Mesh vertices = renumbered(t.vertices, tenth.input_vertex);
  auto window = build_sliding_window(tenth.pm, vertices);
  auto vanilla = build_vanilla(tenth.pm);
  EXPECT_EQ(window->levels(), tenth.levels);
  std::vector<std::uint32_t> lods;
  for (std::uint32_t n = 0; n < last; n += stride) lods.push_back(n);
  lods.push_back(last);
  for (std::uint32_t n : lods) {
    window->set_lod(n);
    vanilla->set_lod(n);
    ASSERT_EQ(drawn_triangles(*window), drawn_triangles(*vanilla)) << n;
    ASSERT_EQ(drawn_triangles(*vanilla), reference_triangles(tenth.pm, n)) << n;
  }
}

TEST(SlidingWindow, RelaxedOrderOnGridIsValidAndNeedsFewerLevels) {
  expect_relaxation_is_valid_and_helps(testing::test_progressive_mesh(make_grid(16, 16), 400), 1, false);
}

TEST(SlidingWindow, RelaxedOrderOnTriceratopsIsValidAndNeedsFewerLevels) {
  expect_relaxation_is_valid_and_helps(
      testing::test_progressive_mesh(load_mesh(testing::data_file("meshes/triceratops.off")), 2400), 61, true);
}

TEST(SlidingWindow, NegativeToleranceIsAnInputError) {
  const testing::TestPm t = testing::test_progressive_mesh(make_grid(4, 4), 5);
  EXPECT_THROW(relax_for_sliding_window(t.pm, -0.1), InputError);
}

}  // namespace
}  // namespace rastrace
