// The sweep's worker threads (cache_sim/sweep.cpp) each replay the trace with the reader's own
// read-ahead thread: four workers must give exactly the rows one worker gives. scripts/tsan.sh
// runs this test under ThreadSanitizer.
#include <gtest/gtest.h>

#include "cache_sim/sweep.h"
#include "support/synthetic_frame.h"
#include "support/temp_dir.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

TEST(ParallelSweep, FourWorkersGiveTheRowsOfOneWorkerToTheMiss) {
  testing::TempDir dir;
  const std::string path = (dir.path() / "frame.rtrace").string();
  const testing::SyntheticFrame frame = testing::make_synthetic_frame(96, 64, 64);
  TraceMetadata meta;
  meta.scene = "synthetic";
  meta.width = 96;
  meta.height = 64;
  meta.textures = frame.textures;
  // Small chunks, so each replay reads many chunks and the read-ahead thread has work.
  TraceWriter writer(path, meta, TraceWriterOptions{.chunk_records = 2048});
  writer.texel_accesses(frame.texels);
  writer.finish();
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

}  // namespace
}  // namespace rastrace
