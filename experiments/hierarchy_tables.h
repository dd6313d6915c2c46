// Cache hierarchies and sectored caches on the command line and in tables (replay --level,
// replay --cache ...,sector=32B):
//   --level SPEC (repeatable, L1 first)  each one byte cache of the grammar (cache_spec.h), sector=
//                                        allowed; the L1's layout=, texel= and align= map texels to
//                                        bytes for every level, so lower levels may not give their own
//   --units N        L1 copies (texture units), 1 by default
//   --tile PIXELS    side of the screen tiles dealt out to the units (16)
//   --inclusion inclusive|non-inclusive  (non-inclusive)
//   --decoded-l1     the L1 holds decoded texels, the levels below compressed blocks (for textures
//                    the trace or the L1's format= stores block-compressed; cache_hierarchy.h)
// A hierarchy table has one row per level; its parameters state the whole configuration and the
// bandwidth reduction (bytes the sampler requested / bytes fetched from memory by the last level).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "cache_sim/hierarchy_sink.h"
#include "core/table.h"

namespace rastrace {

struct HierarchyRequest {
  std::vector<std::string> levels;  // the --level specs; empty: no hierarchy
  std::uint32_t units = 1;
  std::uint32_t tile = 16;
  std::string inclusion = "non-inclusive";
  bool decoded_l1 = false;
};

// Throws InputError naming --level and the spec (alternatives, a vertex cache, a depth or colour
// cache, policy=opt, source=vertex, a lower level's own layout or format, a decoded L1 alone or
// inclusive).
HierarchySpec parse_hierarchy(const HierarchyRequest& request);

using TableParameters = std::vector<std::pair<std::string, TableCell>>;

// Rows: level, cache (its spec), sector_bytes, accesses, misses, line_misses, request_miss_ratio,
// bytes_requested, bytes_fetched, byte_miss_ratio, invalidations.
Table hierarchy_table(TableParameters parameters, const HierarchySpec& spec, const CacheHierarchy& hierarchy);
// One row per sectored cache (each a one-level hierarchy of one unit): the cache, layout,
// accesses, misses, line_misses, miss_rate, bytes_fetched.
Table sectored_cache_table(TableParameters parameters, const std::vector<HierarchySpec>& specs,
                           const HierarchySink& sink, std::size_t first);

// The spec of one level, e.g. "size=16KiB,line=128B,sector=32B,assoc=4,policy=lru".
std::string format_level_spec(const CacheLevelSpec& level);

}  // namespace rastrace
