// Post-transform vertex caches of many sizes in one pass over the index stream, with the same
// misses, size by size, as one VertexCache (vertex_cache.h) per size.
//
// LRU has the stack property (Mattson et al. 1970): a k-entry LRU cache hits exactly when the
// vertex is among the k most recently used distinct vertices. One recency stack as deep as the
// largest size gives every size at once: a hit at depth d hits every cache with more than d
// entries. The stack is searched only when the vertex is in it (a per-vertex flag), and hits in a
// good order sit near the top, so a hit costs O(depth) and a miss one shift. LRU sizes above
// kMaxStackDepth (where a shift would cost more than a recency list) keep their own VertexCache.
//
// FIFO has no stack property (Belady's anomaly: a larger FIFO can miss more), so each size keeps
// its own cache, but all of them advance together: one SIMD lane per size, each lane a FIFO as
// timestamps (meshoptimizer's test `clock - stamp[v] <= k`). Per vertex id the stamps of all
// lanes sit side by side, so one access is a few vector loads, compares and stores whatever the
// number of sizes. Memory: 4 bytes per vertex id per FIFO size (rounded up to 16 sizes).
// Clearing (a new draw) moves every lane's clock past its size instead of touching the stamps.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cache_sim/vertex_cache.h"

namespace rastrace {

class VertexCacheSizes {
 public:
  static constexpr unsigned kMaxStackDepth = 1024;

  // entries: the sizes, each >= 1 (InputError otherwise); any order, repeats allowed.
  VertexCacheSizes(VertexCachePolicy policy, std::vector<unsigned> entries);

  // Looks up each vertex in every cache, in order.
  void access(std::span<const std::uint32_t> vertices);
  void access(std::uint32_t vertex) { access(std::span<const std::uint32_t>(&vertex, 1)); }
  // Empties every cache (a new draw); the miss counts stay.
  void clear();

  VertexCachePolicy policy() const { return policy_; }
  const std::vector<unsigned>& entries() const { return entries_; }
  std::uint64_t accesses() const { return accesses_; }
  // Misses of the cache with entries()[i] entries since construction.
  std::uint64_t misses(std::size_t i) const;

 private:
  void access_lru(std::span<const std::uint32_t> vertices);
  void access_fifo(std::span<const std::uint32_t> vertices);
  void grow_fifo(std::uint32_t vertex);
  void rebase_fifo();

  VertexCachePolicy policy_;
  std::vector<unsigned> entries_;
  std::uint64_t accesses_ = 0;

  // LRU: the recency stack, most recent first, `depth_` deep; hits counted by depth.
  std::uint32_t depth_ = 0;
  std::uint32_t filled_ = 0;
  std::vector<std::uint32_t> stack_;
  std::vector<std::uint8_t> in_stack_;  // per vertex id
  std::vector<std::uint64_t> depth_hits_;
  struct Single {  // an LRU size above kMaxStackDepth
    std::size_t index;
    VertexCache cache;
    std::uint64_t misses = 0;
  };
  std::vector<Single> single_;

  // FIFO: lanes_ lanes (entries_ padded to 16); stamps_[v * lanes_ + l], clocks_[l], sizes_[l].
  std::uint32_t lanes_ = 0;
  std::vector<std::uint32_t> stamps_;
  std::vector<std::uint32_t> clocks_;
  std::vector<std::uint32_t> sizes_;
  std::vector<std::uint32_t> lane_misses_;  // since the last fold into fifo_misses_
  std::vector<std::uint64_t> fifo_misses_;
  std::uint64_t ids_ = 0;  // vertex ids with stamps
};

// simulate_vertex_stream() for every size in `entries` in one pass: element i has the statistics
// of simulate_vertex_stream(indices, type, policy, entries[i], restart_index).
std::vector<VertexStreamStats> simulate_vertex_stream_sizes(std::span<const std::uint32_t> indices,
                                                            PrimitiveType type, VertexCachePolicy policy,
                                                            const std::vector<unsigned>& entries,
                                                            RestartIndex restart_index = kNoRestart);

}  // namespace rastrace
