// The one grammar every command uses to name caches (`--cache`, `--vcache`, `--tcache`):
//
//   spec         := item (',' item)*
//   item         := key '=' alternatives
//   alternatives := value ('/' value)*        a value of a size or count may be a power-of-two
//                                             range a..b (1KiB..64KiB, 4..64), as in core/units.h
//
// Two kinds of cache, told apart by their keys (mixing them is an error):
//   vertex (post-transform) cache   entries=1..1048576 (required), policy=fifo|lru (fifo),
//                                   warp=0|3..1024 (0), primgroup=0..65536 (0): meshoptimizer's
//                                   FIFO flushed per warp of that many vertices or primitives
//                                   (FIFO only; cache_sim/warp_fifo.h)
//   vertex reuse preset             model=NAME[/NAME...]|all, alone (it fixes every parameter):
//                                   nv-pascal, nv-maxwell, amd-gcn, intel (meshoptimizer's
//                                   profiles), kerbl-nv, kerbl-nv-gl, kerbl-amd, kerbl-intel
//                                   (Kerbl et al. 2018's batch models); cache_sim/vertex_reuse.h
//   byte cache                      size=SIZE (required), line=SIZE (64B), assoc=N|full (4),
//                                   policy=fifo|lru|random|opt (lru),
//                                   layout=linear|block2|block4|block8|block16|morton (linear),
//                                   format=trace|rgba8|bc1|bc3|bc4|bc5|bc7|astc4x4|astc8x8 (trace: the
//                                   formats the trace records; else every texture replayed stored so,
//                                   its blocks laid out by layout=; texture_layout.h),
//                                   texel=SIZE (4B), align=SIZE (4KiB), seed=N (1),
//                                   source=texel|vertex|address (what the trace holds), stride=SIZE (32B),
//                                   sector=SIZE (the line: unsectored), e.g. line=128B,sector=32B for
//                                   four 32-byte sectors (sectored_cache.h; replay and hierarchies only)
//   depth or colour cache           a byte cache with source=depth|colour: its elements are pixels
//                                   (pixel=SIZE, 4B), its layout lays out the frame; write-back
//                                   (write_back_cache.h), so policy=opt is refused
//   model=attila                    ATTILA's depth and colour caches: size=16KiB,line=256B,assoc=4,
//                                   policy=lru,layout=block8 (4 ways of 16 lines of 8x8-pixel tiles);
//                                   keys given beside it override it
// size, line, assoc, policy, layout, format and entries take alternatives; a spec with alternatives
// stands for the cross product. Expansion order (the last key varies fastest), which is the
// row order of the sweep tables: byte caches layout (each layout once per format), policy, line, sector, assoc, size; vertex
// caches policy, entries, warp, primgroup (presets in the order given).
//
// Errors are InputErrors that name the option and the spec, and list the accepted keys or values.
// A spec in one of the spellings used before this grammar (`16KiB,64B,4way,lru`, `fifo:16`,
// `12,16`, `24`) is an error that shows the spec to write instead.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cache_sim/cache_config.h"
#include "cache_sim/live_bank_sink.h"
#include "cache_sim/sweep.h"
#include "cache_sim/texture_layout.h"
#include "cache_sim/vertex_cache.h"
#include "cache_sim/vertex_reuse.h"

namespace rastrace {

enum class CacheKind : std::uint8_t { Vertex, Byte };

// One spec as written: every key's alternatives in the order given (duplicates removed), the
// defaults for keys not given.
struct CacheSpec {
  CacheKind kind = CacheKind::Byte;
  // Vertex caches.
  std::vector<unsigned> entries;
  std::vector<VertexCachePolicy> vertex_policies{VertexCachePolicy::Fifo};
  std::vector<unsigned> warps{0};
  std::vector<unsigned> primgroups{0};
  std::vector<std::string> models;  // presets; when given, the only vertex key
  // Byte caches.
  std::vector<std::uint64_t> sizes;
  std::vector<std::uint32_t> lines{64};
  std::vector<std::uint32_t> assocs{4};  // 0 = fully associative
  std::vector<ReplacementPolicy> policies{ReplacementPolicy::Lru};
  std::vector<LayoutSpec> layouts{LayoutSpec{}};  // texel and align applied to every layout
  std::uint64_t seed = 1;
  std::optional<SweepSource> source;  // unset: what the trace holds
  std::optional<FramebufferBuffer> buffer;  // source=depth|colour: a framebuffer cache
  std::uint32_t stride = 32;
  std::vector<std::uint32_t> sectors{0};  // sector bytes, 0 = the whole line

  // How many caches the spec stands for.
  std::size_t combinations() const;
};

// Parses `text`, the value of `option` ("--cache"). Throws InputError on any error above.
CacheSpec parse_cache_spec(const std::string& text, const std::string& option);

// The cross product, in the expansion order above. Byte caches are not validated here: a sweep
// skips impossible geometries, a replay reports them (validate() in cache_config.h).
std::vector<VertexCacheSpec> vertex_caches(const CacheSpec& spec);
struct ByteCacheChoice {
  CacheConfig cache;
  LayoutSpec layout;
  std::uint32_t sector_bytes = 0;  // 0 = unsectored
};
std::vector<ByteCacheChoice> byte_caches(const CacheSpec& spec);
// Exactly one cache of one kind (render's --vcache and --tcache, adjacency's --cache): the other
// kind or alternatives are InputErrors; the byte cache's geometry is validated; sector= is refused
// (these caches are whole-line caches).
VertexCacheSpec parse_vertex_cache(const std::string& text, const std::string& option);
ByteCacheChoice parse_byte_cache(const std::string& text, const std::string& option);
// Depth or colour caches: the cross product of a spec with source=depth|colour (empty otherwise).
std::vector<FramebufferCacheSpec> framebuffer_caches(const CacheSpec& spec);
// One cache of `buffer` (render's --zcache, --ccache): source= may be left out; validated.
FramebufferCacheSpec parse_framebuffer_cache(const std::string& text, const std::string& option,
                                             FramebufferBuffer buffer);
// model=attila for one buffer.
FramebufferCacheSpec attila_framebuffer_cache(FramebufferBuffer buffer);
// A byte-cache spec as the sweep runs it (source: the spec's, or `fallback` when it has none);
// InputError for depth and colour caches, which replay takes and sweep does not.
SweepSpec sweep_spec(const CacheSpec& spec, SweepSource fallback);

// The spec that describes one cache, e.g. "size=16KiB,line=64B,assoc=4,policy=lru" or "model=kerbl-nv".
std::string format_cache_spec(const CacheConfig& cache);
std::string format_cache_spec(const VertexCacheSpec& cache);
// "source=depth,size=16KiB,line=256B,assoc=4,policy=lru,layout=block8,pixel=4B": every parameter.
std::string format_framebuffer_cache_spec(const FramebufferCacheSpec& cache);

// The keys, their kinds and accepted values, one line each (for --help and errors).
std::string cache_spec_keys_help();

}  // namespace rastrace
