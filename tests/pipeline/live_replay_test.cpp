// Rendering with a live cache bank and replaying the trace written in the same pass give the
// same statistics, to the miss (DESIGN.md: the event stream is the seam).
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "cache_sim/live_bank_sink.h"
#include "pipeline/pipeline.h"
#include "pipeline/render_scene.h"
#include "tests/support/temp_dir.h"
#include "tests/support/textured_bunny.h"
#include "traces/memory_sink.h"
#include "traces/replay_file.h"
#include "traces/tee_sink.h"
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
  const TextureLevels levels = texture_levels(scene);
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
  TeeSink tee({&live, &writer});
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

// Depth and colour caches of every layout and policy, both depth tests, with and without
// hierarchical Z: the live bank and the replay of the trace written in the same pass agree to the
// byte, and tracing does not change the image.
TEST(LiveReplay, DepthAndColourCachesLiveEqualReplayToTheByteAndTracingKeepsTheImage) {
  const Scene scene = textured_bunny();
  const TextureLevels levels = texture_levels(scene);
  const FrameSize frame{static_cast<std::uint32_t>(scene.width), static_cast<std::uint32_t>(scene.height)};
  CacheBankConfig config;
  const char* layouts[] = {"linear", "block4", "block8", "morton"};
  for (const char* layout : layouts)
    for (const ReplacementPolicy policy : {ReplacementPolicy::Lru, ReplacementPolicy::Fifo, ReplacementPolicy::Random})
      for (const FramebufferBuffer buffer : {FramebufferBuffer::Depth, FramebufferBuffer::Colour}) {
        FramebufferCacheSpec spec;
        spec.buffer = buffer;
        spec.cache = CacheConfig{2048, 256, 4, policy, 9};
        spec.layout = parse_layout(layout);
        config.framebuffer.push_back(spec);
      }
  for (const bool late : {false, true}) {
    for (const bool hiz : {false, true}) {
      RenderOptions options;
      options.pipeline.raster.traversal = Traversal::Tiled8;
      options.pipeline.raster.depth_test = late ? DepthTest::Late : DepthTest::Early;
      options.pipeline.raster.hierarchical_z = hiz;
      const testing::TempDir dir;
      const std::string path = dir.file("frame.rtrace");
      TraceMetadata metadata;
      metadata.width = frame.width;
      metadata.height = frame.height;
      metadata.textures = levels;
      LiveBankSink live(config, levels, frame);
      TraceWriterOptions small_chunks;
      small_chunks.chunk_records = 1000;
      TraceWriter writer(path, metadata, small_chunks);
      TeeSink tee({&live, &writer});
      const RenderResult traced = render_scene(scene, options, &tee);
      const RenderResult plain = render_scene(scene, options, nullptr);

      LiveBankSink replayed(config, levels, frame);
      replay_file(path, replayed);
      ASSERT_EQ(live.framebuffer_stats().size(), config.framebuffer.size());
      for (std::size_t i = 0; i < config.framebuffer.size(); ++i) {
        const WriteBackStats& s = live.framebuffer_stats()[i];
        EXPECT_EQ(s, replayed.framebuffer_stats()[i]) << "cache " << i << " late " << late << " hiz " << hiz;
        if (config.framebuffer[i].buffer == FramebufferBuffer::Depth) {
          EXPECT_EQ(s.writes, traced.raster.fragments_passed);
          EXPECT_GT(s.bytes_read, 0u);
        } else {
          EXPECT_EQ(s.reads, 0u);
          EXPECT_EQ(s.bytes_read, 0u);
          EXPECT_EQ(s.writes, traced.raster.fragments_passed);
        }
        EXPECT_GT(s.bytes_written, 0u);
      }
      const std::size_t pixels = static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height);
      EXPECT_TRUE(std::equal(plain.framebuffer.colour(), plain.framebuffer.colour() + 4 * pixels,
                             traced.framebuffer.colour()));
      EXPECT_TRUE(std::equal(plain.framebuffer.depth(), plain.framebuffer.depth() + pixels, traced.framebuffer.depth()));
      // Neither the depth test's place nor hierarchical Z changes the image.
      RenderOptions early;
      early.pipeline.raster.traversal = Traversal::Tiled8;
      const RenderResult reference = render_scene(scene, early, nullptr);
      EXPECT_TRUE(std::equal(reference.framebuffer.colour(), reference.framebuffer.colour() + 4 * pixels,
                             traced.framebuffer.colour()));
      EXPECT_EQ(reference.raster.fragments_passed, traced.raster.fragments_passed);
      // Late, every covered fragment is shaded, except those hierarchical Z rejects before shading.
      if (late && !hiz) {
        EXPECT_EQ(traced.raster.fragments_shaded, traced.raster.fragments);
      }
      if (hiz) {
        EXPECT_GT(traced.raster.quads_rejected_hiz, 0u);
      }
    }
  }
}

TEST(LiveReplay, StripRestartingAt0xFFFFFFFFCountsItsRestartsLiveAndReplayed) {
  // Three strips of one draw, restarting at GL's fixed index 0xFFFFFFFF (which once doubled as
  // "no restart", so the two restarts went uncounted in indices sent):
  //   0 1 2 3 4 5 | 4 5 6 6 6 7 8 9 | 2 3 4
  // 19 indices sent, 17 fetched; 4 + 3 + 1 = 8 triangles drawn, 3 degenerate (6 5 6, 6 6 6, 6 6 7).
  Mesh mesh;
  mesh.name = "strip row";
  for (int k = 0; k < 5; ++k) {
    const float x = -0.9f + 0.45f * static_cast<float>(k);
    mesh.positions.emplace_back(x, 0.5f, 0.0f);
    mesh.positions.emplace_back(x, -0.5f, 0.0f);
  }
  constexpr std::uint32_t R = kStripRestart;
  const std::vector<std::uint32_t> indices = {0, 1, 2, 3, 4, 5, R, 4, 5, 6, 6, 6, 7, 8, 9, R, 2, 3, 4};
  const std::string path =
      (std::filesystem::temp_directory_path() / ("rastrace-restart-" + std::to_string(::getpid()) + ".rtrace"))
          .string();
  CacheBankConfig config;
  config.vertex = {{VertexCachePolicy::Fifo, 16}, {VertexCachePolicy::Fifo, 4}, {VertexCachePolicy::Lru, 4}};
  LiveBankSink live(config, {});
  PipelineStats rendered;
  {
    TraceWriter writer(path, TraceMetadata{});
    TeeSink tee({&live, &writer});
    Framebuffer framebuffer(64, 64);
    Pipeline pipeline(framebuffer, PipelineOptions{}, &tee);
    DrawCall call;
    call.indices = indices;
    call.type = PrimitiveType::TriangleStrip;
    call.restart_index = R;
    pipeline.draw(mesh, glm::mat4(1.0f), call, {});
    pipeline.finish();
    rendered = pipeline.stats();
  }
  LiveBankSink replayed(config, {});
  replay_file(path, replayed);
  MemorySink events;
  replay_file(path, events);
  std::filesystem::remove(path);

  ASSERT_EQ(events.draws.size(), 1u);
  EXPECT_EQ(events.draws[0].restart_index, R);
  EXPECT_EQ(rendered.lookups, 17u);
  EXPECT_EQ(rendered.triangles, 8u);
  EXPECT_EQ(rendered.vertices_shaded, 10u);
  // FIFO 4 and LRU 4 both miss 0-9 once and 2 3 4 again at the end.
  const std::uint64_t misses[] = {10, 13, 13};
  for (const LiveBankSink* bank : {&live, &replayed}) {
    ASSERT_EQ(bank->vertex_stats().size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
      const VertexStreamStats& s = bank->vertex_stats()[i];
      EXPECT_EQ(s.indices_sent, 19u) << "cache " << i;
      EXPECT_EQ(s.lookups, 17u);
      EXPECT_EQ(s.misses, misses[i]) << "cache " << i;
      EXPECT_EQ(s.triangles, 8u);
      EXPECT_EQ(s.degenerate, 3u);
      EXPECT_EQ(s.vertices, 10u);
      const VertexStreamStats model = simulate_vertex_stream(indices, PrimitiveType::TriangleStrip,
                                                             config.vertex[i].policy, config.vertex[i].entries, R);
      EXPECT_EQ(model.indices_sent, s.indices_sent);
      EXPECT_EQ(model.misses, s.misses);
    }
  }
}

}  // namespace
}  // namespace rastrace
