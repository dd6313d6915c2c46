#include "cache_sim/vertex_cache.h"

#include <algorithm>

#include "core/error.h"

namespace rastrace {

const char* to_string(VertexCachePolicy policy) {
  return policy == VertexCachePolicy::Fifo ? "fifo" : "lru";
}

VertexCachePolicy parse_vertex_cache_policy(const std::string& text) {
  if (text == "fifo") return VertexCachePolicy::Fifo;
  if (text == "lru") return VertexCachePolicy::Lru;
  throw InputError("unknown vertex cache policy '" + text + "': expected fifo or lru");
}

VertexCache::VertexCache(VertexCachePolicy policy, unsigned entries)
    : policy_(policy), entries_(entries), clock_(std::uint64_t{entries} + 1) {
  if (entries == 0) throw InputError("vertex cache size 0: expected at least 1 entry");
  recency_.reserve(entries);
}

void VertexCache::clear() {
  stamps_.clear();
  clock_ = std::uint64_t{entries_} + 1;
  recency_.clear();
}

bool VertexCache::access_lru(std::uint32_t vertex) {
  const auto found = std::find(recency_.begin(), recency_.end(), vertex);
  if (found != recency_.end()) {
    std::rotate(recency_.begin(), found, found + 1);
    return true;
  }
  if (recency_.size() < entries_) recency_.push_back(vertex);
  else recency_.back() = vertex;
  std::rotate(recency_.begin(), recency_.end() - 1, recency_.end());
  return false;
}

VertexStreamStats simulate_vertex_stream(std::span<const std::uint32_t> indices, PrimitiveType type,
                                         VertexCachePolicy policy, unsigned entries,
                                         std::uint32_t restart_index) {
  VertexCache cache(policy, entries);
  VertexStreamStats stats;
  std::vector<bool> seen;
  for (const std::uint32_t index : indices) {
    ++stats.indices_sent;
    if (type == PrimitiveType::TriangleStrip && index == restart_index) continue;
    ++stats.lookups;
    if (!cache.access(index)) ++stats.misses;
    if (index >= seen.size()) seen.resize(static_cast<std::size_t>(index) + 1, false);
    if (!seen[index]) {
      seen[index] = true;
      ++stats.vertices;
    }
  }
  for_each_triangle(indices, type, restart_index, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (a == b || b == c || a == c) ++stats.degenerate;
    else ++stats.triangles;
  });
  return stats;
}

}  // namespace rastrace
