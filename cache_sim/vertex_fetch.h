// Vertex-buffer fetch: the bytes the input assembler reads from a vertex buffer for an index
// stream. Vertex v occupies bytes [v * stride, (v + 1) * stride); every index sent (restart
// indices excluded) reads every cache line those bytes touch through one byte cache
// (byte_cache.h), with no post-transform cache in front, as meshoptimizer's analyzer models it.
//   bytes fetched  misses x line size
//   overfetch      bytes fetched / (distinct vertices referenced x stride): 1.0 when every
//                  referenced vertex is read from memory exactly once and lines hold nothing else
// meshoptimizer's model (meshopt_analyzeVertexFetch) is the preset "meshopt": direct mapped,
// 128 KiB, 64-byte lines; on it this function gives meshoptimizer's bytes exactly (tests).
// Overfetch is about 1.0-1.3 for a cache-ordered mesh whose vertex buffer is in first-use order
// (reorder/vertex_order.h) and grows with the distance between uses of nearby vertices.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "cache_sim/cache_config.h"
#include "traces/events.h"

namespace rastrace {

struct VertexFetchStats {
  std::uint64_t fetches = 0;        // indices that read the vertex buffer
  std::uint64_t line_accesses = 0;  // cache lines read (a vertex may straddle two or more)
  std::uint64_t misses = 0;
  std::uint64_t bytes_fetched = 0;  // misses x line size
  std::uint64_t vertices = 0;       // distinct vertices referenced
  std::uint32_t vertex_bytes = 0;   // the stride

  double overfetch() const {
    return vertices ? double(bytes_fetched) / (double(vertices) * double(vertex_bytes)) : 0.0;
  }
};

// meshoptimizer's fetch model: direct mapped (the policy is moot), 128 KiB, 64-byte lines.
inline CacheConfig meshopt_fetch_cache() { return {128 * 1024, 64, 1, ReplacementPolicy::Lru, 1}; }

// One byte cache for vertex fetch: "meshopt" (the preset above) or one byte-cache spec
// (size=...,line=...,assoc=...,policy=...). Throws InputError naming `option` otherwise.
CacheConfig parse_fetch_cache(const std::string& text, const std::string& option);

// Throws InputError for a stride of 0 or an invalid cache.
VertexFetchStats simulate_vertex_fetch(std::span<const std::uint32_t> indices, PrimitiveType type,
                                       RestartIndex restart_index, std::uint32_t vertex_bytes,
                                       const CacheConfig& cache);

}  // namespace rastrace
