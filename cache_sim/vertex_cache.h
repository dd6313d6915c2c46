// The post-transform vertex cache: fully associative, k entries, keyed by vertex id.
// FIFO is what most hardware built (Hoppe 1999); LRU is the other textbook policy.
// Both are O(1) per access for any k (up to the 2^20 entries the command line accepts): FIFO
// as insertion timestamps, LRU as a doubly linked recency list over k slots with a per-vertex
// slot index. Memory is one word per vertex id seen plus one slot per resident vertex.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "traces/events.h"

namespace rastrace {

enum class VertexCachePolicy { Fifo, Lru };

const char* to_string(VertexCachePolicy policy);
// "fifo" or "lru"; throws InputError otherwise.
VertexCachePolicy parse_vertex_cache_policy(const std::string& text);

class VertexCache {
 public:
  // entries >= 1; throws InputError otherwise.
  VertexCache(VertexCachePolicy policy, unsigned entries);

  // Looks the vertex up; on a miss it is inserted (evicting per policy). Returns true on a hit.
  bool access(std::uint32_t vertex) {
    return policy_ == VertexCachePolicy::Fifo ? access_fifo(vertex) : access_lru(vertex);
  }
  void clear();

  VertexCachePolicy policy() const { return policy_; }
  unsigned entries() const { return entries_; }

 private:
  // FIFO as timestamps (meshoptimizer's trick): a vertex is resident while fewer than
  // `entries` misses happened since it was inserted. Hits do not reorder a FIFO.
  bool access_fifo(std::uint32_t vertex) {
    if (vertex >= stamps_.size()) stamps_.resize(static_cast<std::size_t>(vertex) + 1, 0);
    if (clock_ - stamps_[vertex] <= entries_) return true;
    stamps_[vertex] = clock_++;
    return false;
  }
  bool access_lru(std::uint32_t vertex);
  void unlink(std::uint32_t slot);
  void push_front(std::uint32_t slot);

  static constexpr std::uint32_t kNoSlot = 0xFFFFFFFFu;
  struct Slot {
    std::uint32_t vertex;
    std::uint32_t prev;  // towards the most recent; kNoSlot at the head
    std::uint32_t next;  // towards the least recent; kNoSlot at the tail
  };

  VertexCachePolicy policy_;
  unsigned entries_;
  std::vector<std::uint64_t> stamps_;  // FIFO: insertion clock per vertex
  std::uint64_t clock_;
  std::vector<std::uint32_t> slot_of_;  // LRU: per vertex, its slot + 1; 0 = not resident
  std::vector<Slot> slots_;             // LRU: one per resident vertex (at most entries_)
  std::uint32_t head_ = kNoSlot;        // LRU: most recently used slot
  std::uint32_t tail_ = kNoSlot;        // LRU: least recently used slot, the next victim
};

struct VertexStreamStats {
  std::uint64_t lookups = 0;     // indices looked up (restart indices excluded)
  std::uint64_t misses = 0;      // vertex shader invocations
  std::uint64_t triangles = 0;   // drawn (non-degenerate) triangles
  std::uint64_t degenerate = 0;  // triangles with a repeated vertex: looked up, not drawn
  std::uint64_t vertices = 0;    // distinct vertices referenced

  double acmr() const { return triangles ? double(misses) / double(triangles) : 0.0; }
  double atvr() const { return vertices ? double(misses) / double(vertices) : 0.0; }
  // Hoppe's b: indices sent per drawn triangle (restart indices count: they are sent).
  std::uint64_t indices_sent = 0;
  double indices_per_triangle() const { return triangles ? double(indices_sent) / double(triangles) : 0.0; }
  // Set by the reuse models of cache_sim/vertex_reuse.h: warps (waves, SIMD threads) executed,
  // and the lanes they occupy (0 for a plain cache, which has no warps).
  std::uint64_t warps = 0;
  std::uint64_t lane_slots = 0;
  double lane_use() const { return lane_slots ? double(misses) / double(lane_slots) : 0.0; }
};

// The statistics of an index stream that no cache changes (misses = 0): lookups, indices sent,
// distinct vertices, drawn and degenerate triangles.
VertexStreamStats vertex_stream_shape(std::span<const std::uint32_t> indices, PrimitiveType type,
                                      RestartIndex restart_index = kNoRestart);

// Runs an index stream through a vertex cache, primitive by primitive as the pipeline does.
VertexStreamStats simulate_vertex_stream(std::span<const std::uint32_t> indices, PrimitiveType type,
                                         VertexCachePolicy policy, unsigned entries,
                                         RestartIndex restart_index = kNoRestart);

}  // namespace rastrace
