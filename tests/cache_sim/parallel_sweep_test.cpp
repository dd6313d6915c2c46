// The sweep's worker threads (cache_sim/sweep.cpp) each replay the trace with the reader's own
// read-ahead thread: four workers must give exactly the rows one worker gives. scripts/tsan.sh
// runs these tests under ThreadSanitizer.
#include <gtest/gtest.h>

#include <mutex>
#include <vector>

#include "cache_sim/sweep.h"
#include "support/synthetic_frame.h"
#include "support/temp_dir.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

// A synthetic frame's texel trace at `path`, in small chunks, so each replay reads many chunks
// and the read-ahead thread has work.
testing::SyntheticFrame write_frame_trace(const std::string& path) {
  testing::SyntheticFrame frame = testing::make_synthetic_frame(96, 64, 64);
  TraceMetadata meta;
  meta.scene = "synthetic";
  meta.width = 96;
  meta.height = 64;
  meta.textures = frame.textures;
  TraceWriter writer(path, meta, TraceWriterOptions{.chunk_records = 2048});
  writer.texel_accesses(frame.texels);
  writer.finish();
  return frame;
}

TEST(ParallelSweep, FourWorkersGiveTheRowsOfOneWorkerToTheMiss) {
  testing::TempDir dir;
  const std::string path = (dir.path() / "frame.rtrace").string();
  const testing::SyntheticFrame frame = write_frame_trace(path);
  ASSERT_GT(frame.texels.size(), 8u * 2048);

  SweepSpec spec;
  spec.sizes = {1024, 4096, 16384};
  spec.assocs = {1, 0};
  spec.policies = {ReplacementPolicy::Lru, ReplacementPolicy::Fifo};
  const SweepResult serial = run_sweep(path, spec, 1, false);
  const SweepResult parallel = run_sweep(path, spec, 4, false);
  ASSERT_EQ(serial.rows.size(), 12u);
  ASSERT_EQ(parallel.rows.size(), serial.rows.size());
  std::uint64_t misses = 0;
  for (std::size_t i = 0; i < serial.rows.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(parallel.rows[i].cache.size_bytes, serial.rows[i].cache.size_bytes);
    EXPECT_EQ(parallel.rows[i].stats, serial.rows[i].stats);  // every count, the three Cs too
    EXPECT_EQ(parallel.rows[i].stats.accesses, frame.texels.size());
    misses += serial.rows[i].stats.misses;
  }
  EXPECT_GT(misses, 0u);
}

// A SweepRowSink is how the Python module writes a sweep's numpy columns while the sweep runs: it
// must see every row of the result once, after its statistics are final, from the worker threads,
// and begin() first with the number of rows.
// Records what the sweep hands over: a copy of each row as done() sees it.
class RecordingSink final : public SweepRowSink {
 public:
  void begin(std::size_t rows) override {
    ++begins;
    seen.resize(rows);
    times.assign(rows, 0);
  }
  void done(const SweepRows& rows, const std::vector<std::size_t>& indices) override {
    std::lock_guard lock(mutex);
    for (const std::size_t i : indices) {
      seen.at(i) = rows[i];
      ++times.at(i);
    }
  }
  int begins = 0;
  std::vector<SweepRow> seen;
  std::vector<int> times;
  std::mutex mutex;
};

TEST(SweepRowSink, SeesEveryRowOnceWithItsFinalStatistics) {
  testing::TempDir dir;
  const std::string path = (dir.path() / "frame.rtrace").string();
  const testing::SyntheticFrame frame = write_frame_trace(path);

  SweepSpec spec;
  spec.sizes = {512, 1024, 4096, 16384};
  spec.lines = {32, 64};
  spec.assocs = {1, 4, 0};
  spec.policies = {ReplacementPolicy::Lru, ReplacementPolicy::Fifo};
  spec.layouts = {LayoutSpec{}, parse_layout("morton")};
  RecordingSink sink;
  const SweepResult result = run_sweep(path, spec, 3, false, &sink);
  ASSERT_EQ(result.rows.size(), 4u * 2 * 3 * 2 * 2);
  EXPECT_EQ(sink.begins, 1);
  ASSERT_EQ(sink.seen.size(), result.rows.size());
  for (std::size_t i = 0; i < result.rows.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(sink.times[i], 1);
    EXPECT_EQ(sink.seen[i].stats, result.rows[i].stats);
    EXPECT_EQ(sink.seen[i].stats.accesses, frame.texels.size());
    EXPECT_EQ(sink.seen[i].configuration, result.rows[i].configuration);
    EXPECT_EQ(sink.seen[i].layout, sweep_layout_name(spec, result.rows[i].layout_index));
  }
  EXPECT_EQ(sweep_layout_name(spec, 1), "morton");
}

}  // namespace
}  // namespace rastrace
