// The cache-spec grammar (cache_sim/cache_spec.h): both kinds, alternatives and ranges expanded
// in the sweep's row order, every error naming the option and what is accepted, and the old
// spellings answered with the spec to write.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cache_sim/cache_spec.h"
#include "core/error.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;

std::string error_of(const std::string& text, const std::string& option = "--cache") {
  try {
    parse_cache_spec(text, option);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(CacheSpec, ByteCacheWithEveryKey) {
  const CacheSpec spec = parse_cache_spec(
      "size=16KiB,line=32B,assoc=full,policy=random,layout=block8,texel=8B,align=64KiB,seed=7,source=texel,stride=48B",
      "--cache");
  EXPECT_EQ(spec.kind, CacheKind::Byte);
  EXPECT_EQ(spec.combinations(), 1u);
  const std::vector<ByteCacheChoice> caches = byte_caches(spec);
  ASSERT_EQ(caches.size(), 1u);
  EXPECT_EQ(caches[0].cache.size_bytes, 16384u);
  EXPECT_EQ(caches[0].cache.line_bytes, 32u);
  EXPECT_EQ(caches[0].cache.assoc, 0u);
  EXPECT_EQ(caches[0].cache.policy, ReplacementPolicy::Random);
  EXPECT_EQ(caches[0].cache.seed, 7u);
  EXPECT_EQ(caches[0].layout.kind, LayoutKind::Block);
  EXPECT_EQ(caches[0].layout.block, 8u);
  EXPECT_EQ(caches[0].layout.texel_bytes, 8u);
  EXPECT_EQ(caches[0].layout.alignment, 65536u);
  EXPECT_EQ(spec.source, SweepSource::Texel);
  EXPECT_EQ(spec.stride, 48u);
  EXPECT_TRUE(vertex_caches(spec).empty());
}

TEST(CacheSpec, DefaultsForKeysNotGiven) {
  const CacheSpec byte = parse_cache_spec("size=8KiB", "--cache");
  ASSERT_EQ(byte_caches(byte).size(), 1u);
  EXPECT_EQ(format_cache_spec(byte_caches(byte)[0].cache), "size=8KiB,line=64B,assoc=4,policy=lru");
  EXPECT_EQ(layout_name(byte_caches(byte)[0].layout), "linear");
  EXPECT_EQ(byte_caches(byte)[0].layout.texel_bytes, 4u);
  EXPECT_EQ(byte_caches(byte)[0].layout.alignment, 4096u);
  EXPECT_FALSE(byte.source.has_value());
  const CacheSpec vertex = parse_cache_spec("entries=24", "--cache");
  ASSERT_EQ(vertex_caches(vertex).size(), 1u);
  EXPECT_EQ(format_cache_spec(vertex_caches(vertex)[0]), "entries=24,policy=fifo");
}

TEST(CacheSpec, TexelAndAlignApplyToEveryLayoutInAnyOrder) {
  for (const char* text :
       {"size=1KiB,texel=16B,align=1KiB,layout=linear/morton", "size=1KiB,layout=linear/morton,align=1KiB,texel=16B"}) {
    const std::vector<ByteCacheChoice> caches = byte_caches(parse_cache_spec(text, "--cache"));
    ASSERT_EQ(caches.size(), 2u) << text;
    for (const ByteCacheChoice& c : caches) {
      EXPECT_EQ(c.layout.texel_bytes, 16u) << text;
      EXPECT_EQ(c.layout.alignment, 1024u) << text;
    }
    EXPECT_EQ(caches[1].layout.kind, LayoutKind::Morton);
  }
}

TEST(CacheSpec, AlternativesExpandInTheSweepRowOrder) {
  // layout, policy, line, assoc, size: the last varies fastest, as sweep tables are sorted.
  const CacheSpec spec = parse_cache_spec(
      "size=1KiB..64KiB,line=32B/64B,assoc=1/2/4/full,policy=fifo/lru,layout=linear/morton", "--cache");
  EXPECT_EQ(spec.sizes, (std::vector<std::uint64_t>{1024, 2048, 4096, 8192, 16384, 32768, 65536}));
  EXPECT_EQ(spec.assocs, (std::vector<std::uint32_t>{1, 2, 4, 0}));
  const std::vector<ByteCacheChoice> caches = byte_caches(spec);
  ASSERT_EQ(caches.size(), 7u * 2u * 4u * 2u * 2u);
  EXPECT_EQ(spec.combinations(), caches.size());
  EXPECT_EQ(format_cache_spec(caches[0].cache), "size=1KiB,line=32B,assoc=1,policy=fifo");
  EXPECT_EQ(format_cache_spec(caches[1].cache), "size=2KiB,line=32B,assoc=1,policy=fifo");
  EXPECT_EQ(format_cache_spec(caches[7].cache), "size=1KiB,line=32B,assoc=2,policy=fifo");
  EXPECT_EQ(format_cache_spec(caches[28].cache), "size=1KiB,line=64B,assoc=1,policy=fifo");
  EXPECT_EQ(format_cache_spec(caches[56].cache), "size=1KiB,line=32B,assoc=1,policy=lru");
  EXPECT_EQ(layout_name(caches[111].layout), "linear");
  EXPECT_EQ(layout_name(caches[112].layout), "morton");
  EXPECT_EQ(format_cache_spec(caches.back().cache), "size=64KiB,line=64B,assoc=full,policy=lru");
  // The sweep runs the same alternatives.
  const SweepSpec sweep = sweep_spec(spec, SweepSource::Address);
  EXPECT_EQ(sweep.source, SweepSource::Address);
  EXPECT_EQ(sweep.sizes, spec.sizes);
  EXPECT_EQ(sweep.lines, (std::vector<std::uint32_t>{32, 64}));
  EXPECT_EQ(sweep.policies, (std::vector<ReplacementPolicy>{ReplacementPolicy::Fifo, ReplacementPolicy::Lru}));
  EXPECT_EQ(sweep.layouts.size(), 2u);
}

TEST(CacheSpec, VertexAlternativesExpandPolicyThenEntries) {
  const std::vector<VertexCacheSpec> caches =
      vertex_caches(parse_cache_spec("entries=12/16/24/32,policy=fifo/lru", "--cache"));
  ASSERT_EQ(caches.size(), 8u);
  EXPECT_EQ(format_cache_spec(caches[0]), "entries=12,policy=fifo");
  EXPECT_EQ(format_cache_spec(caches[3]), "entries=32,policy=fifo");
  EXPECT_EQ(format_cache_spec(caches[4]), "entries=12,policy=lru");
  const CacheSpec range = parse_cache_spec("entries=4..64,policy=lru/fifo", "--cache");
  EXPECT_EQ(range.entries, (std::vector<unsigned>{4, 8, 16, 32, 64}));
  EXPECT_EQ(range.vertex_policies, (std::vector<VertexCachePolicy>{VertexCachePolicy::Lru, VertexCachePolicy::Fifo}));
  // Repeated alternatives count once.
  EXPECT_EQ(parse_cache_spec("entries=16/16/8", "--cache").entries, (std::vector<unsigned>{16, 8}));
  EXPECT_EQ(parse_cache_spec("entries=1048576", "--cache").entries, (std::vector<unsigned>{1u << 20}));
}

TEST(CacheSpec, ErrorsNameTheOptionTheSpecAndWhatIsAccepted) {
  EXPECT_EQ(error_of("size=16KiB,lines=64B"),
            "--cache 'size=16KiB,lines=64B': unknown key 'lines': expected one of entries, model, warp, primgroup, "
            "size, line, sector, assoc, policy, layout, format, texel, align, seed, source, stride, pixel");
  EXPECT_EQ(error_of("size=16KiB,size=8KiB"), "--cache 'size=16KiB,size=8KiB': key 'size' given twice");
  EXPECT_EQ(error_of("size=16KiB,,line=64B"),
            "--cache 'size=16KiB,,line=64B': empty item; expected key=value items separated by ','");
  EXPECT_EQ(error_of("entries=16,size=16KiB"),
            "--cache 'entries=16,size=16KiB': entries (a vertex cache) and size (a byte cache) cannot be mixed in one "
            "spec");
  EXPECT_EQ(error_of("line=64B,assoc=4", "--tcache"),
            "--tcache 'line=64B,assoc=4': missing size=...: a byte cache needs its capacity, e.g. size=16KiB");
  EXPECT_THAT(error_of("policy=fifo"),
              HasSubstr("missing entries=... or model=... (a vertex cache, e.g. entries=16,policy=fifo or model=kerbl-nv)"));
  EXPECT_EQ(error_of("entries=0"), "--cache 'entries=0': entries=0: expected 1..1048576");
  EXPECT_EQ(error_of("entries=2097152"), "--cache 'entries=2097152': entries=2097152: expected 1..1048576");
  EXPECT_EQ(error_of("entries=16,policy=opt"),
            "--cache 'entries=16,policy=opt': policy=opt: expected fifo or lru (a vertex cache)");
  EXPECT_EQ(error_of("size=1KiB,policy=mru"),
            "--cache 'size=1KiB,policy=mru': policy=mru: expected fifo, lru, random or opt (a byte cache)");
  EXPECT_EQ(error_of("size=1KiB,layout=tiled"),
            "--cache 'size=1KiB,layout=tiled': layout=tiled: expected linear, block2, block4, block8, block16 or "
            "morton");
  EXPECT_EQ(error_of("size=1KiB,assoc=0"),
            "--cache 'size=1KiB,assoc=0': assoc=0: expected a number of ways >= 1 or full");
  EXPECT_EQ(error_of("size=1KiB,line=64B//32B"),
            "--cache 'size=1KiB,line=64B//32B': line=64B//32B: expected a byte size, e.g. line=64B or line=32B/64B");
  EXPECT_EQ(error_of("size=1KiB,seed=1/2"),
            "--cache 'size=1KiB,seed=1/2': seed takes one value, not alternatives: 1/2");
  EXPECT_EQ(error_of("size=1KiB,source=pixels"),
            "--cache 'size=1KiB,source=pixels': source=pixels: expected texel, vertex, address, depth or colour");
  EXPECT_THAT(error_of("size=3KiB..8KiB"), HasSubstr("a range between two powers of two"));
  EXPECT_THAT(error_of("size=lots"), HasSubstr("--cache size: 'lots': expected a byte size"));
  EXPECT_EQ(error_of(""),
            "--cache: empty cache spec; expected key=value items (entries, model, warp, primgroup, size, line, sector, "
            "assoc, policy, layout, format, texel, align, seed, source, stride, pixel)");
  EXPECT_THAT(error_of("size=1KiB,big"),
              HasSubstr("item 'big': expected key=value, with key one of entries, model, warp, primgroup, size"));
}

TEST(CacheSpec, OldSpellingsAreAnsweredWithTheSpecToWrite) {
  EXPECT_EQ(error_of("16KiB,64B,4way,lru", "--tcache"),
            "--tcache '16KiB,64B,4way,lru': write size=16KiB,line=64B,assoc=4,policy=lru");
  EXPECT_EQ(error_of("8KiB,32B,direct,fifo", "--tcache"),
            "--tcache '8KiB,32B,direct,fifo': write size=8KiB,line=32B,assoc=1,policy=fifo");
  EXPECT_EQ(error_of("1MiB,128B,full,opt", "--tcache"),
            "--tcache '1MiB,128B,full,opt': write size=1MiB,line=128B,assoc=full,policy=opt");
  EXPECT_EQ(error_of("fifo:16", "--vcache"), "--vcache 'fifo:16': write entries=16,policy=fifo");
  EXPECT_EQ(error_of("12,16"), "--cache '12,16': write entries=12/16");
  EXPECT_EQ(error_of("24"), "--cache '24': write entries=24");
  EXPECT_EQ(error_of("4..64,128"), "--cache '4..64,128': write entries=4..64/128");
}

TEST(CacheSpec, OneCacheOfOneKind) {
  EXPECT_EQ(format_cache_spec(parse_vertex_cache("entries=32,policy=lru", "--vcache")), "entries=32,policy=lru");
  const ByteCacheChoice t = parse_byte_cache("size=8KiB,line=32B,assoc=2,policy=fifo,layout=morton", "--tcache");
  EXPECT_EQ(format_cache_spec(t.cache), "size=8KiB,line=32B,assoc=2,policy=fifo");
  EXPECT_EQ(layout_name(t.layout), "morton");
  try {
    parse_vertex_cache("size=8KiB", "--vcache");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "--vcache 'size=8KiB': expected a post-transform vertex cache, e.g. entries=16,policy=fifo");
  }
  try {
    parse_vertex_cache("entries=16/32", "--cache");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--cache 'entries=16/32': expected one cache, not 2 alternatives");
  }
  try {
    parse_byte_cache("size=3KiB,assoc=32", "--tcache");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("--tcache 'size=3KiB,assoc=32': cache 3KiB/64B/32-way"));
  }
}

TEST(CacheSpec, HelpListsEveryKey) {
  const std::string help = cache_spec_keys_help();
  for (const char* key : {"entries (vertex)", "size (byte)", "policy:", "layout (byte)", "stride (byte)"})
    EXPECT_THAT(help, HasSubstr(key));
}

TEST(CacheSpec, DepthAndColourCachesTheAttilaModelAndPixelBytes) {
  const FramebufferCacheSpec attila = attila_framebuffer_cache(FramebufferBuffer::Depth);
  EXPECT_EQ(attila.cache.size_bytes, 16384u);  // 4 ways x 16 lines x (8 x 8 pixels x 4 B)
  EXPECT_EQ(attila.cache.line_bytes, 256u);
  EXPECT_EQ(attila.cache.assoc, 4u);
  EXPECT_EQ(attila.cache.policy, ReplacementPolicy::Lru);
  EXPECT_EQ(layout_name(attila.layout), "block8");
  EXPECT_EQ(attila.layout.texel_bytes, 4u);
  EXPECT_EQ(format_framebuffer_cache_spec(attila),
            "source=depth,size=16KiB,line=256B,assoc=4,policy=lru,layout=block8,pixel=4B");
  // Keys beside the model override it, in any order.
  const FramebufferCacheSpec bigger =
      parse_framebuffer_cache("size=32KiB,model=attila,pixel=2B", "--ccache", FramebufferBuffer::Colour);
  EXPECT_EQ(bigger.buffer, FramebufferBuffer::Colour);
  EXPECT_EQ(bigger.cache.size_bytes, 32768u);
  EXPECT_EQ(bigger.cache.line_bytes, 256u);
  EXPECT_EQ(bigger.layout.texel_bytes, 2u);
  // In --cache, source= says which buffer; alternatives expand as for any byte cache.
  const CacheSpec spec = parse_cache_spec("source=colour,size=4KiB/8KiB,line=64B,layout=linear/morton", "--cache");
  const std::vector<FramebufferCacheSpec> caches = framebuffer_caches(spec);
  ASSERT_EQ(caches.size(), 4u);
  EXPECT_EQ(caches[3].buffer, FramebufferBuffer::Colour);
  EXPECT_EQ(layout_name(caches[3].layout), "morton");
  EXPECT_EQ(caches[3].cache.size_bytes, 8192u);
  EXPECT_TRUE(framebuffer_caches(parse_cache_spec("size=4KiB", "--cache")).empty());
}

TEST(CacheSpec, DepthAndColourCacheErrorsSayWhatFits) {
  EXPECT_THAT(error_of("size=4KiB,pixel=4B"), HasSubstr("add source=depth or source=colour"));
  EXPECT_THAT(error_of("source=depth,size=4KiB,texel=4B"), HasSubstr("texel= does not apply to a depth cache"));
  EXPECT_THAT(error_of("source=depth,size=4KiB,policy=opt"), HasSubstr("policy=opt"));
  EXPECT_THAT(error_of("source=stencil,size=4KiB"), HasSubstr("texel, vertex, address, depth or colour"));
  EXPECT_THAT(error_of("model=ati"),
              HasSubstr("model=ati: expected nv-pascal, nv-maxwell, amd-gcn, intel, kerbl-nv, kerbl-nv-gl, kerbl-amd, "
                        "kerbl-intel or all (vertex reuse presets), or attila (a depth or colour cache)"));
  try {
    parse_framebuffer_cache("model=attila,source=colour", "--zcache", FramebufferBuffer::Depth);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("--zcache 'model=attila,source=colour': expected a depth cache"));
  }
  try {
    sweep_spec(parse_cache_spec("source=depth,size=4KiB", "--cache"), SweepSource::Texel);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("replayed"));
  }
}

}  // namespace
}  // namespace rastrace
