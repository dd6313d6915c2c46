// Block-compressed textures in the cache simulator: a texel's address is its block's first byte in
// the layout of blocks (texture_layout.h), a sweep over formats equals a naive reference row by
// row, and a decoded L1 over compressed levels asks for the compressed bytes of its lines.
#include <gtest/gtest.h>

#include <bit>
#include <map>
#include <string>
#include <vector>

#include "cache_sim/cache_hierarchy.h"
#include "cache_sim/cache_spec.h"
#include "cache_sim/hierarchy_sink.h"
#include "cache_sim/sweep.h"
#include "cache_sim/texture_layout.h"
#include "core/error.h"
#include "naive_cache.h"
#include "naive_hierarchy.h"
#include "support/synthetic_frame.h"
#include "support/temp_dir.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

LayoutSpec layout(const std::string& name, TextureFormat format) {
  LayoutSpec spec = parse_layout(name);
  spec.format = format;
  return spec;
}

TEST(CompressedLayout, ABc1TexelLivesInTheEightBytesOfItsBlockRowMajor) {
  // 16x8 texels: 4x2 blocks of 8 bytes; level 1 (8x4: 2x1 blocks) starts on the next 4 KiB page.
  const TextureLevels textures{{{16, 8, TextureFormat::Bc1}, {8, 4, TextureFormat::Bc1}}};
  const TextureLayout linear(parse_layout("linear"), textures);
  EXPECT_EQ(linear.address(0, 0, 0, 0), 0u);
  EXPECT_EQ(linear.address(0, 0, 3, 3), 0u);        // same block
  EXPECT_EQ(linear.address(0, 0, 5, 1), 8u);        // block (1, 0)
  EXPECT_EQ(linear.address(0, 0, 5, 6), 5u * 8u);   // block (1, 1)
  EXPECT_EQ(linear.address(0, 0, 15, 7), 7u * 8u);  // the last block
  EXPECT_EQ(linear.address(0, 1, 7, 3), 4096u + 8u);
  EXPECT_EQ(linear.total_bytes(), 4096u + 16u);
  EXPECT_EQ(linear.format(0), TextureFormat::Bc1);
}

TEST(CompressedLayout, MortonAndTilesOrderBlocksNotTexels) {
  // 16x16 BC7: 4x4 blocks of 16 bytes. Texel (5, 9) is block (1, 2): Z order 0b1001 = 9.
  const TextureLevels textures{{{16, 16}}};
  const TextureLayout morton(layout("morton", TextureFormat::Bc7), textures);
  EXPECT_EQ(morton.address(0, 0, 5, 9), 9u * 16u);
  EXPECT_EQ(morton.address(0, 0, 15, 15), 15u * 16u);
  // block2 tiles of 2x2 blocks, two tiles a row: block (1, 2) is in tile (0, 1), the third tile,
  // at index 1 inside it.
  const TextureLayout tiles(layout("block2", TextureFormat::Bc7), textures);
  EXPECT_EQ(tiles.address(0, 0, 5, 9), (2u * 4u + 1u) * 16u);
  EXPECT_EQ(tiles.address(0, 0, 9, 5), (1u * 4u + 2u) * 16u);  // block (2, 1): tile (1, 0), index 2
  EXPECT_EQ(layout_name(layout("block2", TextureFormat::Bc7)), "block2:bc7");
  EXPECT_EQ(parse_layout("block2:bc7").format, TextureFormat::Bc7);  // the name reads back
  EXPECT_EQ(parse_layout("block2:bc7").block, 2u);
  EXPECT_THROW(parse_layout("block2:dxt9"), InputError);
}

TEST(CompressedLayout, PartialEdgeBlocksCountWholeAndAstc8x8BlocksAreSixteenBytes) {
  const TextureLevels textures{{{5, 3, TextureFormat::Bc1}, {2, 1, TextureFormat::Bc1}, {1, 1, TextureFormat::Bc1}}};
  const TextureLayout bc1(parse_layout("linear"), textures);
  EXPECT_EQ(bc1.address(0, 0, 4, 2), 8u);  // the second block of a 2x1 grid
  EXPECT_EQ(bc1.address(0, 2, 0, 0), 2u * 4096u);
  EXPECT_EQ(bc1.total_bytes(), 2u * 4096u + 8u);
  const TextureLayout astc(layout("linear", TextureFormat::Astc8x8), TextureLevels{{{20, 9}}});
  EXPECT_EQ(astc.address(0, 0, 19, 8), (3u + 2u) * 16u);  // 3x2 blocks
  EXPECT_EQ(astc.total_bytes(), 6u * 16u);
}

TEST(CompressedLayout, DecodedAddressesPutABlocksTexelsInItsDecodedBytes) {
  const TextureLevels textures{{{16, 8}}};
  const TextureLayout bc1(layout("linear", TextureFormat::Bc1), textures);
  EXPECT_EQ(bc1.decode_shift(0), 3u);  // 64 decoded bytes from 8
  // Texel (6, 5): block (1, 1) at 40, texel (2, 1) inside it.
  EXPECT_EQ(bc1.decoded_address(0, 0, 6, 5), (40u << 3) + (1u * 4u + 2u) * 4u);
  const TextureLayout bc7(layout("linear", TextureFormat::Bc7), textures);
  EXPECT_EQ(bc7.decode_shift(0), 2u);
  const TextureLayout astc(layout("linear", TextureFormat::Astc8x8), textures);
  EXPECT_EQ(astc.decode_shift(0), 4u);  // 256 decoded bytes from 16
  const TextureLayout rgba(parse_layout("linear"), textures);
  EXPECT_EQ(rgba.decoded_address(0, 0, 6, 5), rgba.address(0, 0, 6, 5));
  EXPECT_EQ(rgba.decode_shift(0), 0u);
}

TEST(CompressedLayout, AnAlignmentBelowTheBlockIsRefused) {
  LayoutSpec spec = layout("linear", TextureFormat::Bc7);
  spec.alignment = 8;
  EXPECT_THROW(TextureLayout(spec, TextureLevels{{{8, 8}}}), InputError);
}

TEST(CompressedCacheSpec, FormatMultipliesTheLayoutsAndTraceKeepsTheTracesFormats) {
  const CacheSpec spec = parse_cache_spec("size=16KiB,layout=linear/morton,format=trace/bc1/bc7", "--cache");
  ASSERT_EQ(spec.layouts.size(), 6u);
  EXPECT_EQ(layout_name(spec.layouts[0]), "linear");
  EXPECT_EQ(layout_name(spec.layouts[1]), "linear:bc1");
  EXPECT_EQ(layout_name(spec.layouts[5]), "morton:bc7");
  EXPECT_EQ(spec.combinations(), 6u);
  try {
    parse_cache_spec("size=16KiB,format=dxt9", "--cache");
    FAIL() << "format=dxt9 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dxt9"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bc7"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_cache_spec("source=depth,size=16KiB,format=bc1", "--zcache"), InputError);
  EXPECT_THROW(parse_cache_spec("source=depth,size=16KiB,layout=block8:bc1", "--zcache"), InputError);
  // Layouts that differ only in their format are two layouts.
  EXPECT_EQ(parse_cache_spec("size=16KiB,layout=block4:bc1/block4:bc7", "--cache").layouts.size(), 2u);
}

// The naive reference's own address rule, written from the layout's definition: the unit grid
// (texels, or blocks of bw x bh), ordered row-major, in B x B tiles, or in Z order per square tile.
std::uint64_t naive_address(const std::string& kind, std::uint32_t tile, TextureFormat format,
                            const std::vector<LevelSize>& levels, std::uint32_t level, std::uint32_t x,
                            std::uint32_t y) {
  const BlockShape shape = block_shape(format);
  std::uint64_t base = 0;
  for (std::uint32_t k = 0;; ++k) {
    const std::uint64_t gw = (levels[k].width + shape.width - 1) / shape.width;
    const std::uint64_t gh = (levels[k].height + shape.height - 1) / shape.height;
    std::uint64_t units = 0, offset = 0;
    const std::uint64_t ux = x / shape.width, uy = y / shape.height;
    if (kind == "linear") {
      units = gw * gh;
      offset = uy * gw + ux;
    } else if (kind == "block") {
      const std::uint64_t tiles_w = (gw + tile - 1) / tile, tiles_h = (gh + tile - 1) / tile;
      units = tiles_w * tiles_h * tile * tile;
      offset = ((uy / tile) * tiles_w + ux / tile) * tile * tile + (uy % tile) * tile + ux % tile;
    } else {
      const std::uint64_t pw = std::bit_ceil(gw), ph = std::bit_ceil(gh), side = std::min(pw, ph);
      units = pw * ph;
      std::uint64_t z = 0;
      for (int b = 0; b < 32; ++b) z |= (((ux % side) >> b) & 1) << (2 * b) | (((uy % side) >> b) & 1) << (2 * b + 1);
      offset = (ux / side + uy / side) * side * side + z;
    }
    if (k == level) return base + offset * shape.bytes;
    base += units * shape.bytes;
    base = (base + 4095) / 4096 * 4096;
  }
}

TEST(CompressedSweep, EqualsANaiveReferenceConfigurationByConfiguration) {
  testing::SyntheticFrame frame = testing::make_synthetic_frame(64, 48, 64);
  for (LevelSize& level : frame.textures[0]) level.format = TextureFormat::Bc1;  // as the trace records it
  testing::TempDir dir;
  const std::string path = (dir.path() / "bc1.rtrace").string();
  TraceMetadata meta;
  meta.scene = "synthetic";
  meta.width = 64;
  meta.height = 48;
  meta.textures = frame.textures;
  TraceWriter writer(path, meta, TraceWriterOptions{.chunk_records = 4096});
  writer.texel_accesses(frame.texels);
  writer.finish();

  const CacheSpec cache = parse_cache_spec(
      "size=512B/2KiB,line=32B/64B,assoc=1/full,policy=lru/fifo,layout=linear/block4/morton,"
      "format=trace/bc7/astc8x8/rgba8",
      "--cache");
  const SweepSpec spec = sweep_spec(cache, SweepSource::Texel);
  const SweepResult result = run_sweep(path, spec, 2, false);
  ASSERT_EQ(result.rows.size(), 2u * 2u * 2u * 2u * 3u * 4u);
  std::map<std::size_t, std::vector<std::uint64_t>> addresses;  // per layout index
  for (std::size_t l = 0; l < spec.layouts.size(); ++l) {
    const LayoutSpec& s = spec.layouts[l];
    const std::string kind = s.kind == LayoutKind::Linear ? "linear" : s.kind == LayoutKind::Block ? "block" : "morton";
    const TextureFormat format = s.format.value_or(TextureFormat::Bc1);
    for (const TexelAccess& t : frame.texels)
      addresses[l].push_back(naive_address(kind, s.block, format, frame.textures[0], t.level, t.x, t.y));
  }
  std::uint64_t bc1_misses = 0, rgba8_misses = 0;
  for (const SweepRow& row : result.rows) {
    SCOPED_TRACE(row.layout + " " + describe(row.cache));
    const char* policy = row.cache.policy == ReplacementPolicy::Lru ? "lru" : "fifo";
    const std::uint64_t expected = testing::naive_misses(addresses.at(row.layout_index), row.cache.size_bytes,
                                                         row.cache.line_bytes, row.cache.assoc, policy);
    EXPECT_EQ(row.stats.misses, expected);
    if (row.layout == "morton" && row.cache.size_bytes == 2048) bc1_misses += row.stats.misses;
    if (row.layout == "morton:rgba8" && row.cache.size_bytes == 2048) rgba8_misses += row.stats.misses;
  }
  // An eighth of the bytes per texel: far fewer misses in the same cache.
  EXPECT_LT(bc1_misses * 3, rgba8_misses);
}

TEST(DecodedHierarchy, AnL1MissAsksTheLevelBelowForTheCompressedBytesOfItsLine) {
  const testing::SyntheticFrame frame = testing::make_synthetic_frame(64, 48, 64);
  for (const TextureFormat format : {TextureFormat::Bc1, TextureFormat::Bc7, TextureFormat::Astc8x8}) {
    SCOPED_TRACE(to_string(format));
    HierarchySpec spec;
    spec.layout = layout("morton", format);
    spec.hierarchy.levels = {{CacheConfig{1024, 64, 4, ReplacementPolicy::Lru, 1}, 0},
                             {CacheConfig{4096, 64, 4, ReplacementPolicy::Lru, 1}, 0}};
    spec.hierarchy.decoded_l1 = true;
    HierarchySink sink({spec}, frame.textures);
    sink.texel_accesses(frame.texels);
    const std::vector<LevelStats> stats = sink.hierarchy(0).stats();

    // The reference: a naive L1 on decoded addresses; each L1 miss asks the naive L2 for the
    // compressed bytes [line >> s, (line + 64) >> s), at least one, one access per L2 line.
    const TextureLayout map(spec.layout, frame.textures);
    const std::uint32_t s = map.decode_shift(0);
    testing::NaiveSectoredCache l1(1024, 64, 4, "lru", 0), l2(4096, 64, 4, "lru", 0);
    std::uint64_t l1_misses = 0, l2_accesses = 0, l2_misses = 0, l2_requested = 0;
    for (const TexelAccess& t : frame.texels) {
      const std::uint64_t d = map.decoded_address(0, t.level, t.x, t.y);
      if (l1.access(d).hit) continue;
      ++l1_misses;
      const std::uint64_t first = (d & ~std::uint64_t{63}) >> s, bytes = std::max<std::uint64_t>(64 >> s, 1);
      l2_requested += bytes;
      for (std::uint64_t a = first & ~std::uint64_t{63}; a < first + bytes; a += 64) {
        ++l2_accesses;
        if (!l2.access(a).hit) ++l2_misses;
      }
    }
    EXPECT_EQ(stats[0].misses, l1_misses);
    EXPECT_EQ(stats[0].bytes_fetched, l1_misses * 64);
    EXPECT_EQ(stats[1].accesses, l2_accesses);
    EXPECT_EQ(stats[1].misses, l2_misses);
    EXPECT_EQ(stats[1].bytes_requested, l2_requested);
    EXPECT_EQ(stats[1].bytes_requested, l1_misses * (64u >> s));
    EXPECT_GT(l2_misses, 0u);
  }
}

TEST(DecodedHierarchy, TexturesThatDecodeAtDifferentRatiosAreRefused) {
  HierarchySpec spec;
  spec.layout = parse_layout("block4");
  spec.hierarchy.levels = {{CacheConfig{1024, 64, 4, ReplacementPolicy::Lru, 1}, 0},
                           {CacheConfig{4096, 64, 4, ReplacementPolicy::Lru, 1}, 0}};
  spec.hierarchy.decoded_l1 = true;
  const TextureLevels mixed{{{16, 16, TextureFormat::Bc1}}, {{16, 16, TextureFormat::Rgba8}}};
  EXPECT_THROW(HierarchySink({spec}, mixed), InputError);
  spec.layout.format = TextureFormat::Bc7;  // one format for all: accepted
  EXPECT_NO_THROW(HierarchySink({spec}, mixed));
}

TEST(DecodedHierarchy, AloneOrInclusiveIsRefused) {
  HierarchyConfig config;
  config.levels = {{CacheConfig{1024, 64, 4, ReplacementPolicy::Lru, 1}, 0}};
  config.decoded_l1 = true;
  EXPECT_THROW(CacheHierarchy{config}, InputError);
  config.levels.push_back({CacheConfig{4096, 64, 4, ReplacementPolicy::Lru, 1}, 0});
  config.inclusion = Inclusion::Inclusive;
  EXPECT_THROW(CacheHierarchy{config}, InputError);
  config.inclusion = Inclusion::NonInclusive;
  EXPECT_NO_THROW(CacheHierarchy{config});
}

}  // namespace
}  // namespace rastrace
