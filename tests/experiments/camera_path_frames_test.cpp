// Several frames through caches that keep their contents (render --frames N, replay --per-frame):
// a static camera misses only in its first frame when the L2 holds the frame, a moving camera's
// trace replays frame by frame to the live render's per-frame table, and the frame table sums
// every frame.
#include <cstdint>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "experiments/frame_render.h"
#include "experiments/per_frame_caches.h"
#include "tests/support/temp_dir.h"
#include "traces/trace_reader.h"

namespace rastrace {
namespace {

std::string orbit_scene() {
  return (std::filesystem::path(RASTRACE_TEST_FILES_DIR).parent_path() / "docs" / "orbit_scene.json").string();
}

std::int64_t integer(const TableCell& cell) { return std::get<std::int64_t>(cell.value); }

// The frame table's (one row) integer under `key`.
std::int64_t frame_count(const Table& table, const std::string& key) {
  for (std::size_t c = 0; c < table.columns.size(); ++c)
    if (table.columns[c].key == key) return integer(table.rows.at(0)[c]);
  throw std::logic_error("no column " + key);
}

const Table& table_titled(const Frame& frame, const std::string& title) {
  for (const Table& t : frame.hierarchy)
    if (t.title == title) return t;
  throw std::logic_error("no table " + title);
}

// Columns of "Caches per frame": frame, cache, level, accesses, misses, line_misses, miss_rate, bytes_fetched.
constexpr std::size_t kFrame = 0, kLevel = 2, kAccesses = 3, kMisses = 4, kBytes = 7;

TEST(CameraPathFrames, AStaticCameraMissesInTheL2OnlyInItsFirstFrame) {
  FrameSpec spec;
  spec.flags.scene = "builtin:grid";
  spec.flags.size = "128x128";
  spec.flags.threads = 1;
  spec.frames = 3;
  // The grid's 256x256 checker (256 KiB with its mips) fits a 1 MiB L2, not the 4 KiB L1.
  spec.hierarchy.levels = {"size=4KiB,line=64B,assoc=4,layout=block4", "size=1MiB,line=64B,assoc=16"};
  const Frame frame = render_frame(spec);
  const Table& per_frame = table_titled(frame, "Caches per frame");
  ASSERT_EQ(per_frame.rows.size(), 6u);  // 3 frames x 2 levels
  std::vector<std::int64_t> l1_misses, l2_misses, accesses;
  for (const auto& row : per_frame.rows) {
    if (std::get<std::string>(row[kLevel].value) == "L1") {
      l1_misses.push_back(integer(row[kMisses]));
      accesses.push_back(integer(row[kAccesses]));
    } else {
      l2_misses.push_back(integer(row[kMisses]));
    }
  }
  EXPECT_EQ(accesses[0], accesses[1]);  // identical frames
  EXPECT_EQ(accesses[1], accesses[2]);
  // Frame 0: the frame's distinct 64-byte lines (the compulsory misses replay --cache
  // size=4MiB,line=64B,assoc=full,layout=block4 counts in its trace); then none.
  EXPECT_EQ(l2_misses, (std::vector<std::int64_t>{883, 0, 0}));
  EXPECT_EQ(l1_misses[1], l1_misses[2]);  // the L1 is too small to keep a frame: it misses every frame
  EXPECT_GT(l1_misses[1], 0);
  // The frame table sums the three frames.
  EXPECT_EQ(frame_count(frame.table, "texel_accesses"), 3 * accesses[0]);
}

TEST(CameraPathFrames, WithoutAHierarchyTheFrameTableSumsEveryFrame) {
  FrameSpec spec;
  spec.flags.scene = "builtin:grid";
  spec.flags.size = "96x96";
  spec.flags.threads = 1;
  const Frame one = render_frame(spec);
  spec.frames = 4;
  const Frame four = render_frame(spec);
  EXPECT_TRUE(four.hierarchy.empty());
  for (const char* key : {"triangles", "vertices_shaded", "fragments", "texel_accesses"})
    EXPECT_EQ(frame_count(four.table, key), 4 * frame_count(one.table, key)) << key;
  // The texture cache keeps its contents: fewer misses than 4 cold frames.
  EXPECT_LT(frame_count(four.table, "texture_misses"), 4 * frame_count(one.table, "texture_misses"));
}

TEST(CameraPathFrames, AnOrbitsPerFrameReplayEqualsTheLiveRenderFrameByFrameAndLevelByLevel) {
  const testing::TempDir dir;
  FrameSpec spec;
  spec.flags.scene = orbit_scene();
  spec.flags.size = "160x120";
  spec.flags.threads = 1;
  spec.frames = 6;
  spec.trace = dir.file("orbit.rtrace");
  spec.hierarchy.levels = {"size=16KiB,line=64B,assoc=4,layout=block4", "size=256KiB,line=64B,assoc=16"};
  const Frame frame = render_frame(spec);
  const Table& live = table_titled(frame, "Caches per frame");
  ASSERT_EQ(live.rows.size(), 12u);

  TraceReader reader(spec.trace);
  EXPECT_EQ(reader.version(), 4u);
  EXPECT_EQ(reader.frames(), 6u);
  const Table replayed = per_frame_replay_table(spec.trace, {}, spec.hierarchy);
  ASSERT_EQ(replayed.rows.size(), live.rows.size());
  for (std::size_t r = 0; r < live.rows.size(); ++r) EXPECT_EQ(replayed.rows[r], live.rows[r]) << "row " << r;

  // The camera moves: the frames differ in accesses, and the L2 keeps part of what earlier frames read.
  std::vector<std::int64_t> accesses, l2_misses;
  for (const auto& row : live.rows) {
    if (std::get<std::string>(row[kLevel].value) == "L1")
      accesses.push_back(integer(row[kAccesses]));
    else
      l2_misses.push_back(integer(row[kMisses]));
    EXPECT_EQ(integer(row[kFrame]), static_cast<std::int64_t>((&row - live.rows.data()) / 2));
  }
  EXPECT_NE(accesses[0], accesses[3]);
  // New texels come into view as the camera turns; by frame 5 the 256 KiB L2 holds them all.
  EXPECT_EQ(l2_misses, (std::vector<std::int64_t>{519, 87, 62, 60, 15, 0}));
  (void)kBytes;
}

TEST(CameraPathFrames, PerFrameReplayOfOneCacheSumsToThePlainReplaysMisses) {
  const testing::TempDir dir;
  FrameSpec spec;
  spec.flags.scene = orbit_scene();
  spec.flags.size = "96x72";
  spec.flags.threads = 1;
  spec.frames = 3;
  spec.trace = dir.file("orbit.rtrace");
  spec.tcache = "size=8KiB,line=64B,assoc=2,policy=lru,layout=block4";
  const Frame frame = render_frame(spec);
  const Table table = per_frame_replay_table(spec.trace, {spec.tcache}, {});
  ASSERT_EQ(table.rows.size(), 3u);
  std::int64_t misses = 0, accesses = 0;
  for (const auto& row : table.rows) misses += integer(row[kMisses]), accesses += integer(row[kAccesses]);
  EXPECT_EQ(misses, frame_count(frame.table, "texture_misses"));
  EXPECT_EQ(accesses, frame_count(frame.table, "texel_accesses"));
  EXPECT_THROW(per_frame_replay_table(spec.trace, {"entries=16,policy=fifo"}, {}), InputError);
  EXPECT_THROW(per_frame_replay_table(spec.trace, {"size=8KiB,line=64B,assoc=2,policy=opt"}, {}), InputError);
}

}  // namespace
}  // namespace rastrace
