#include <gtest/gtest.h>

#include "cache_sim/live_bank_sink.h"
#include "core/error.h"
#include "scenes/procedural.h"
#include "tests/support/temp_dir.h"
#include "traces/trace_reader.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

// Sends an index buffer as the pipeline does: primitive starts marked, restart indices dropped.
void send_index_buffer(EventSink& sink, std::uint32_t draw, PrimitiveType type, std::span<const std::uint32_t> indices,
                       RestartIndex restart = kNoRestart) {
  sink.begin_draw({draw, type, restart});
  std::vector<VertexFetch> fetches;
  walk_index_stream(
      indices, type, restart,
      [&](std::size_t i, bool start) {
        fetches.push_back({indices[i], start});
      },
      [](const AssembledTriangle&) {});
  // Uneven batches: statistics must not depend on how the renderer batches.
  for (std::size_t i = 0; i < fetches.size(); i += 37)
    sink.vertex_fetches(std::span(fetches).subspan(i, std::min<std::size_t>(37, fetches.size() - i)));
  sink.end_draw();
}

void expect_same(const VertexStreamStats& a, const VertexStreamStats& b) {
  EXPECT_EQ(a.lookups, b.lookups);
  EXPECT_EQ(a.misses, b.misses);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.degenerate, b.degenerate);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.indices_sent, b.indices_sent);
}

TEST(LiveBankSink, VertexStatisticsEqualSimulateVertexStreamForListsAndStrips) {
  const Mesh grid = make_grid(16, 16);
  CacheBankConfig config;
  for (unsigned k : {4u, 12u, 16u, 20u}) {
    config.vertex.push_back(vertex_cache_spec(VertexCachePolicy::Fifo, k));
    config.vertex.push_back(vertex_cache_spec(VertexCachePolicy::Lru, k));
  }
  LiveBankSink bank(config, {});
  send_index_buffer(bank, 0, PrimitiveType::TriangleList, grid.indices);
  bank.finish();
  for (std::size_t i = 0; i < config.vertex.size(); ++i)
    expect_same(bank.vertex_stats()[i], simulate_vertex_stream(grid.indices, PrimitiveType::TriangleList,
                                                               config.vertex[i].policy, config.vertex[i].entries));
  EXPECT_NEAR(bank.vertex_stats()[4].acmr(), 1.062, 0.0005);  // FIFO 12, Castano's scanline row

  const std::vector<std::uint32_t> strip = {0, 1, 2, 3, 3, 4, 4, 5, 6, 0xFFFF, 7, 8, 9, 7, 0xFFFF, 2, 2, 3};
  LiveBankSink strips(config, {});
  send_index_buffer(strips, 0, PrimitiveType::TriangleStrip, strip, 0xFFFF);
  strips.finish();
  for (std::size_t i = 0; i < config.vertex.size(); ++i)
    expect_same(strips.vertex_stats()[i],
                simulate_vertex_stream(strip, PrimitiveType::TriangleStrip, config.vertex[i].policy,
                                       config.vertex[i].entries, 0xFFFF));
  EXPECT_EQ(strips.vertex_stats()[0].degenerate, 5u);  // 4 in the first strip, (2,2,3) in the last
}

TEST(LiveBankSink, EachDrawStartsWithAnEmptyVertexCache) {
  CacheBankConfig config;
  config.vertex.push_back(vertex_cache_spec(VertexCachePolicy::Fifo, 16));
  LiveBankSink bank(config, {});
  const std::vector<std::uint32_t> tri = {0, 1, 2};
  send_index_buffer(bank, 0, PrimitiveType::TriangleList, tri);
  send_index_buffer(bank, 1, PrimitiveType::TriangleList, tri);
  bank.finish();
  EXPECT_EQ(bank.vertex_stats()[0].misses, 6u);
  EXPECT_EQ(bank.vertex_stats()[0].vertices, 6u);
}

TEST(LiveBankSink, TexelOutsideTheMetadataTexturesIsAnInputError) {
  CacheBankConfig config;
  config.texture.push_back({CacheConfig{}, parse_layout("block4")});
  LiveBankSink bank(config, {{{8, 8}}});
  const TexelAccess inside{0, 0, 7, 7, 0, 0, 0}, outside{0, 0, 8, 0, 0, 0, 3};
  bank.texel_accesses({&inside, 1});
  EXPECT_THROW(bank.texel_accesses({&outside, 1}), InputError);
}

TEST(LiveBankSink, ReplayingTheWrittenTraceGivesTheLiveStatisticsExactly) {
  // A frame-like texel walk over a 64x64 mip chain, plus the grid's vertex stream; events go to a
  // live bank and to a trace writer at once (as a render with both sinks would).
  const TextureLevels textures = {mip_chain_sizes(64, 64), mip_chain_sizes(16, 32)};
  CacheBankConfig config;
  config.vertex = {{VertexCachePolicy::Fifo, 12}, {VertexCachePolicy::Lru, 16}};
  for (const char* layout : {"linear", "block4", "morton"})
    for (auto policy :
         {ReplacementPolicy::Lru, ReplacementPolicy::Fifo, ReplacementPolicy::Random, ReplacementPolicy::Opt})
      config.texture.push_back({CacheConfig{1024, 64, 2, policy, 7}, parse_layout(layout)});
  config.vertex_buffer.push_back({CacheConfig{512, 32, 0, ReplacementPolicy::Lru, 1}, 32});
  const testing::TempDir dir;
  const std::string path = dir.file("live.rtrace");
  LiveBankSink live(config, textures);
  {
    TraceMetadata meta;
    meta.textures = textures;
    TraceWriter writer(path, meta, {3, 500});
    const Mesh grid = make_grid(16, 16);
    for (EventSink* sink : {static_cast<EventSink*>(&live), static_cast<EventSink*>(&writer)})
      send_index_buffer(*sink, 0, PrimitiveType::TriangleList, grid.indices);
    std::vector<TexelAccess> texels;
    for (std::uint32_t py = 0; py < 40; ++py)
      for (std::uint32_t px = 0; px < 40; ++px) {
        const std::uint8_t level = static_cast<std::uint8_t>(px < 20 ? 0 : 1);
        const std::uint32_t tex = py < 30 ? 0 : 1;
        const std::uint32_t x = (px * 3 / 2) >> level, y = (py + px / 3) >> level;
        for (std::uint32_t dy = 0; dy < 2; ++dy)
          for (std::uint32_t dx = 0; dx < 2; ++dx)
            texels.push_back({static_cast<std::uint16_t>(tex), level,
                              static_cast<std::uint16_t>(std::min(x + dx, textures[tex][level].width - 1)),
                              static_cast<std::uint16_t>(std::min(y + dy, textures[tex][level].height - 1)),
                              static_cast<std::uint16_t>(px), static_cast<std::uint16_t>(py), py});
      }
    live.texel_accesses(texels);
    writer.texel_accesses(texels);
    live.finish();
    writer.finish();
  }
  LiveBankSink replayed(config, TraceReader(path).metadata().textures);
  TraceReader reader(path);
  replay_trace(reader, replayed);
  for (std::size_t i = 0; i < config.vertex.size(); ++i)
    expect_same(replayed.vertex_stats()[i], live.vertex_stats()[i]);
  for (std::size_t i = 0; i < config.texture.size(); ++i) {
    EXPECT_EQ(replayed.texture_stats()[i], live.texture_stats()[i]) << i;
    EXPECT_EQ(live.texture_stats()[i].accesses, 6400u);
    EXPECT_GT(live.texture_stats()[i].misses, 0u);
  }
  EXPECT_EQ(replayed.vertex_buffer_stats()[0], live.vertex_buffer_stats()[0]);
  // OPT is the lower bound on every layout.
  for (std::size_t l = 0; l < 3; ++l)
    for (std::size_t p = 0; p < 3; ++p)
      EXPECT_LE(live.texture_stats()[l * 4 + 3].misses, live.texture_stats()[l * 4 + p].misses);
}

}  // namespace
}  // namespace rastrace
