// Rendering with a live cache bank and replaying the trace written in the same pass give the
// same statistics, to the miss (DESIGN.md: the event stream is the seam).
#include <string>

#include <gtest/gtest.h>

#include "cache_sim/live_bank_sink.h"
#include "pipeline/render_scene.h"
#include "tests/support/tee_sink.h"
#include "tests/support/temp_dir.h"
#include "tests/support/textured_bunny.h"
#include "traces/memory_sink.h"
#include "traces/replay_file.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

Scene textured_bunny() {
  Scene scene = testing::textured_bunny(200, 160, 128, 8);
  scene.camera.eye = glm::vec3(-0.02f, 0.15f, 0.25f);
  scene.camera.target = glm::vec3(-0.02f, 0.1f, 0.0f);
  scene.camera.near_plane = 0.01f;
  scene.camera.far_plane = 2.0f;
  return scene;
}

CacheBankConfig bank_config() {
  CacheBankConfig config;
  config.vertex = {{VertexCachePolicy::Fifo, 16}, {VertexCachePolicy::Lru, 12}, {VertexCachePolicy::Fifo, 32}};
  for (const LayoutKind kind : {LayoutKind::Linear, LayoutKind::Block, LayoutKind::Morton}) {
    for (const ReplacementPolicy policy : {ReplacementPolicy::Lru, ReplacementPolicy::Fifo}) {
      TextureCacheSpec spec;
      spec.cache.size_bytes = 4096;
      spec.cache.line_bytes = 64;
      spec.cache.assoc = 2;
      spec.cache.policy = policy;
      spec.layout.kind = kind;
      config.texture.push_back(spec);
    }
  }
  return config;
}

TEST(LiveReplay, LiveCacheBankEqualsReplayOfTheWrittenTraceToTheMiss) {
  const Scene scene = textured_bunny();
  TextureLevels levels;
  for (const Texture& t : scene.textures) {
    std::vector<LevelSize> sizes;
    for (const Image& image : t.levels)
      sizes.push_back({static_cast<std::uint32_t>(image.width), static_cast<std::uint32_t>(image.height)});
    levels.push_back(sizes);
  }
  const testing::TempDir dir;
  const std::string path = dir.file("live.rtrace");
  TraceMetadata metadata;
  metadata.scene = scene.name;
  metadata.width = static_cast<std::uint32_t>(scene.width);
  metadata.height = static_cast<std::uint32_t>(scene.height);
  metadata.filter = "trilinear";
  metadata.textures = levels;

  LiveBankSink live(bank_config(), levels);
  TraceWriterOptions small_chunks;
  small_chunks.chunk_records = 4096;  // many chunks: chunk boundaries must not change anything
  TraceWriter writer(path, metadata, small_chunks);
  testing::TeeSink tee(live, writer);
  RenderOptions options;
  options.pipeline.raster.traversal = Traversal::Tiled8;
  const RenderResult result = render_scene(scene, options, &tee);

  LiveBankSink replayed(bank_config(), levels);
  replay_file(path, replayed);

  ASSERT_GT(result.raster.texel_reads, 100000u);
  ASSERT_EQ(live.texture_stats().size(), 6u);
  for (std::size_t i = 0; i < live.texture_stats().size(); ++i) {
    EXPECT_EQ(live.texture_stats()[i].accesses, result.raster.texel_reads);
    EXPECT_GT(live.texture_stats()[i].misses, 0u);
    EXPECT_EQ(live.texture_stats()[i], replayed.texture_stats()[i]) << "texture cache " << i;
    EXPECT_EQ(live.texture_stats()[i].misses, replayed.texture_stats()[i].misses);
  }
  for (std::size_t i = 0; i < live.vertex_stats().size(); ++i) {
    EXPECT_EQ(live.vertex_stats()[i].misses, replayed.vertex_stats()[i].misses) << "vertex cache " << i;
    EXPECT_EQ(live.vertex_stats()[i].triangles, replayed.vertex_stats()[i].triangles);
    EXPECT_EQ(live.vertex_stats()[i].lookups, replayed.vertex_stats()[i].lookups);
  }
  // The pipeline's own shader invocations are the live model's FIFO-16 misses.
  EXPECT_EQ(live.vertex_stats()[0].misses, result.pipeline.vertices_shaded);
  EXPECT_EQ(live.vertex_stats()[0].triangles, result.pipeline.triangles);
}

}  // namespace
}  // namespace rastrace
