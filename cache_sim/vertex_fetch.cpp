#include "cache_sim/vertex_fetch.h"

#include <algorithm>
#include <vector>

#include "cache_sim/byte_cache.h"
#include "cache_sim/cache_spec.h"
#include "core/error.h"
#include "core/index_stream.h"

namespace rastrace {

CacheConfig parse_fetch_cache(const std::string& text, const std::string& option) {
  if (text == "meshopt") return meshopt_fetch_cache();
  const CacheSpec spec = parse_cache_spec(text, option);
  if (spec.kind != CacheKind::Byte)
    throw InputError(option + " '" + text + "': vertex fetch goes through a byte cache: expected meshopt or " +
                     "size=...,line=...,assoc=...,policy=..., e.g. " + format_cache_spec(meshopt_fetch_cache()));
  return parse_byte_cache(text, option).cache;
}

VertexFetchStats simulate_vertex_fetch(std::span<const std::uint32_t> indices, PrimitiveType type,
                                       RestartIndex restart_index, std::uint32_t vertex_bytes,
                                       const CacheConfig& config) {
  if (vertex_bytes == 0) throw InputError("vertex size 0: expected at least 1 byte per vertex");
  ByteCache cache(config);
  const std::uint32_t shift = cache.line_shift();
  VertexFetchStats stats;
  stats.vertex_bytes = vertex_bytes;
  std::vector<bool> seen;
  for (const std::uint32_t index : indices) {
    if (is_restart(type, restart_index, index)) continue;
    ++stats.fetches;
    if (index >= seen.size()) seen.resize(std::max<std::size_t>(std::size_t{index} + 1, seen.size() * 2), false);
    if (!seen[index]) {
      seen[index] = true;
      ++stats.vertices;
    }
    const std::uint64_t first_byte = std::uint64_t{index} * vertex_bytes;
    const std::uint64_t last_line = (first_byte + vertex_bytes - 1) >> shift;
    for (std::uint64_t line = first_byte >> shift; line <= last_line; ++line) {
      ++stats.line_accesses;
      stats.misses += !cache.access_line(line);
    }
  }
  stats.bytes_fetched = stats.misses * config.line_bytes;
  return stats;
}

}  // namespace rastrace
