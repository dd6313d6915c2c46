// The one-pass LRU profiles of a hierarchy's first level (LruProfileSink with units): every size
// and every associativity of the L1s at once equals a CacheHierarchy with those L1s, access for
// access, on a frame-like texel stream dealt out to texture units by screen tile.
#include <gtest/gtest.h>

#include "cache_sim/cache_hierarchy.h"
#include "cache_sim/profile_sink.h"
#include "core/error.h"
#include "tests/support/synthetic_frame.h"

namespace rastrace {
namespace {

struct Frame {
  testing::SyntheticFrame frame = testing::make_synthetic_frame(128, 96, 256);
  LayoutSpec layout = parse_layout("block4");
};

std::uint64_t hierarchy_l1_misses(const Frame& f, const CacheConfig& l1, std::uint32_t units, std::uint32_t tile) {
  HierarchyConfig config;
  config.levels = {{l1, 0}};
  config.units = units;
  config.tile = tile;
  CacheHierarchy hierarchy(config);
  const TextureLayout layout(f.layout, f.frame.textures);
  for (const TexelAccess& t : f.frame.texels)
    hierarchy.access(layout.address(t.texture, t.level, t.x, t.y), hierarchy.unit_of_pixel(t.pixel_x, t.pixel_y));
  return hierarchy.stats().front().misses;
}

TEST(ProfileUnits, EverySizeAndAssociativityOfFourL1sEqualsTheHierarchysFirstLevel) {
  const Frame f;
  for (const std::uint32_t tile : {8u, 16u, 32u}) {
    LruProfileSpec spec;
    spec.line_bytes = 64;
    spec.layout = f.layout;
    spec.units = 4;
    spec.tile = tile;
    spec.sets = 16;
    spec.max_ways = 8;
    LruProfileSink sink(spec, f.frame.textures);
    sink.texel_accesses(f.frame.texels);
    sink.finish();
    EXPECT_EQ(sink.accesses(), f.frame.texels.size());
    for (const std::uint64_t lines : {1u, 4u, 16u, 64u, 256u, 1024u}) {
      const CacheConfig full{lines * 64, 64, 0, ReplacementPolicy::Lru, 1};
      EXPECT_EQ(sink.misses(lines), hierarchy_l1_misses(f, full, 4, tile)) << lines << " lines, tile " << tile;
    }
    for (std::uint32_t ways = 1; ways <= 8; ++ways) {
      const CacheConfig set_assoc{16ull * ways * 64, 64, ways, ReplacementPolicy::Lru, 1};
      EXPECT_EQ(sink.set_misses(ways), hierarchy_l1_misses(f, set_assoc, 4, tile)) << ways << " ways, tile " << tile;
    }
  }
}

TEST(ProfileUnits, FourUnitsFetchSharedTexelsMoreThanOnceAndOneUnitIsThePlainProfile) {
  const Frame f;
  LruProfileSpec one;
  one.layout = f.layout;
  LruProfileSpec four = one;
  four.units = 4;
  LruProfileSink a(one, f.frame.textures), b(four, f.frame.textures);
  a.texel_accesses(f.frame.texels);
  b.texel_accesses(f.frame.texels);
  const CacheConfig full{64 * 64, 64, 0, ReplacementPolicy::Lru, 1};
  EXPECT_EQ(a.misses(64), hierarchy_l1_misses(f, full, 1, 16));
  // Each unit sees a quarter of the tiles: neighbouring tiles' shared texels are fetched by
  // several units, so the first references alone grow.
  EXPECT_EQ(a.compulsory(), 515u);
  EXPECT_EQ(b.compulsory(), 829u);
  // The same total capacity split four ways misses more (1,387 against 894); four times the
  // capacity (64 lines per unit) misses a little less (836).
  EXPECT_EQ(a.misses(64), 894u);
  EXPECT_EQ(b.misses(16), 1387u);
  EXPECT_EQ(b.misses(64), 836u);
}

TEST(ProfileUnits, UnitsOnAStreamWithoutPixelsAndBadCountsAreErrors) {
  const Frame f;
  LruProfileSpec spec;
  spec.source = SweepSource::Address;
  spec.units = 2;
  EXPECT_THROW(LruProfileSink(spec, f.frame.textures), InputError);
  spec.source = SweepSource::Texel;
  spec.units = 0;
  EXPECT_THROW(LruProfileSink(spec, f.frame.textures), InputError);
  spec.units = 2;
  spec.tile = 0;
  EXPECT_THROW(LruProfileSink(spec, f.frame.textures), InputError);
}

}  // namespace
}  // namespace rastrace
