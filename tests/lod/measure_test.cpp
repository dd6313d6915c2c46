// The measurement rows: counts that follow from the representations' definitions, on a grid.
#include <gtest/gtest.h>

#include "collapse_sequences.h"
#include "core/error.h"
#include "lod/mixed_mode.h"
#include "lod/skip_strips.h"
#include "lod/sliding_window.h"
#include "lod/vanilla.h"
#include "lod/vipm_measure.h"
#include "scenes/procedural.h"

namespace rastrace {
namespace {

struct Fixture {
  testing::TestPm t = testing::test_progressive_mesh(make_grid(16, 16), 400);
};

TEST(VipmMeasure, VanillaRowsCountEveryDrawnTriangleOnceAndNoDegenerate) {
  Fixture f;
  auto vanilla = build_vanilla(f.t.pm);
  const std::vector<VipmLodRow> rows = measure_vipm(*vanilla);
  ASSERT_EQ(rows.size(), f.t.pm.collapses.size() + 1);
  std::uint64_t changed = 0;
  for (const CollapseRecord& c : f.t.pm.collapses) changed += c.changed_corners.size();
  for (const VipmLodRow& row : rows) {
    EXPECT_EQ(row.triangles, f.t.pm.triangle_count_at(row.lod));
    EXPECT_EQ(row.degenerate, 0u);
    EXPECT_EQ(row.indices, 3 * row.triangles);
    EXPECT_EQ(row.index_bytes, 6 * row.triangles);
    EXPECT_EQ(row.draw_calls, 1u);
    EXPECT_EQ(row.draw_vertex_range[0], 289u - row.lod);
    EXPECT_EQ(row.collapse_cost.collapses, row.lod == 0 ? 0u : 1u);
  }
  const VipmSummary s = summarize_vipm(*vanilla, rows);
  EXPECT_DOUBLE_EQ(s.index_writes_per_collapse, double(changed) / double(f.t.pm.collapses.size()));
  EXPECT_DOUBLE_EQ(s.index_writes_per_split, s.index_writes_per_collapse);
  EXPECT_EQ(s.levels, 1u);
  EXPECT_EQ(s.level_switches, 0u);
  EXPECT_EQ(s.index_bits, 16u);
}

TEST(VipmMeasure, SkipStripListsSubmitTheLevelsTrianglesAndCountBinnedOnesAsDegenerate) {
  Fixture f;
  LevelParams lists;
  lists.primitive = PrimitiveType::TriangleList;
  lists.algorithm = "tipsy";
  auto skip = build_skip_strips(f.t.pm, f.t.vertices, lists);
  VipmMeasureParams params;
  params.lod_step = 7;
  const std::vector<VipmLodRow> rows = measure_vipm(*skip, params);
  for (const VipmLodRow& row : rows) {
    const EditedLevel& level = skip->level_data()[row.level];
    EXPECT_EQ(row.triangles + row.degenerate, f.t.pm.triangle_count_at(level.first_lod)) << row.lod;
    EXPECT_EQ(row.triangles, f.t.pm.triangle_count_at(row.lod));
    EXPECT_LE(double(row.degenerate), 0.5 * double(row.triangles + row.degenerate) + 2.0) << row.lod;
  }
  const VipmSummary s = summarize_vipm(*skip, rows);
  EXPECT_GT(s.level_switches, 0u);
  EXPECT_GT(s.mean_degenerate_fraction, 0.0);
  // Down and up, a level is entered at most once each way (none if the stride jumps over it).
  EXPECT_LE(s.level_switches, 2u * (skip->levels() - 1));
}

TEST(VipmMeasure, MixedModeDrawsTwiceAndSlidingWindowOnce) {
  Fixture f;
  LevelParams lists;
  lists.primitive = PrimitiveType::TriangleList;
  lists.algorithm = "tipsy";
  auto mixed = build_mixed_mode(f.t.pm, f.t.vertices, lists);
  auto window = build_sliding_window(f.t.pm, f.t.vertices);
  const std::vector<VipmLodRow> mixed_rows = measure_vipm(*mixed);
  const std::vector<VipmLodRow> window_rows = measure_vipm(*window);
  EXPECT_EQ(mixed_rows.front().draw_calls, 2u);
  for (const VipmLodRow& row : mixed_rows) {
    EXPECT_EQ(row.degenerate, 0u);
    EXPECT_EQ(row.triangles, f.t.pm.triangle_count_at(row.lod));
  }
  for (const VipmLodRow& row : window_rows) {
    EXPECT_EQ(row.draw_calls, 1u);
    EXPECT_EQ(row.instance_bytes, 4u);
    EXPECT_EQ(row.collapse_cost.index_writes + row.split_cost.index_writes, 0u);
    EXPECT_EQ(row.streaming_bytes, (289u - row.lod) * 32u + row.index_bytes + 8u);
  }
  const VipmSummary s = summarize_vipm(*mixed, mixed_rows);
  // Mixed-mode copies only lists 3 and 4 per instance: less than vanilla's whole list.
  EXPECT_LT(s.max_instance_bytes, 512u * 6u);
}

TEST(VipmMeasure, ZeroStepOrEmptyCacheIsAnInputError) {
  Fixture f;
  auto vanilla = build_vanilla(f.t.pm);
  VipmMeasureParams params;
  params.lod_step = 0;
  EXPECT_THROW(measure_vipm(*vanilla, params), InputError);
  params.lod_step = 1;
  params.cache_entries = 0;
  EXPECT_THROW(measure_vipm(*vanilla, params), InputError);
}

}  // namespace
}  // namespace rastrace
