#include "cache_sim/vertex_cache.h"

#include <algorithm>

#include "core/input_guard.h"
#include "core/enum_names.h"
#include "core/error.h"

namespace rastrace {

namespace {

constexpr EnumName<VertexCachePolicy> kPolicies[] = {{VertexCachePolicy::Fifo, "fifo"},
                                                     {VertexCachePolicy::Lru, "lru"}};

}  // namespace

const char* to_string(VertexCachePolicy policy) { return enum_to_string(policy, kPolicies); }

VertexCachePolicy parse_vertex_cache_policy(const std::string& text) {
  return parse_enum(text, kPolicies, "vertex cache policy");
}

VertexCache::VertexCache(VertexCachePolicy policy, unsigned entries)
    : policy_(policy), entries_(entries), clock_(std::uint64_t{entries} + 1) {
  if (entries == 0) throw InputError("vertex cache size 0: expected at least 1 entry");
}

void VertexCache::clear() {
  stamps_.clear();
  clock_ = std::uint64_t{entries_} + 1;
  // Only resident vertices have a slot index to reset: O(resident), paid for by their misses.
  for (const Slot& slot : slots_) slot_of_[slot.vertex] = 0;
  slots_.clear();
  head_ = tail_ = kNoSlot;
}

void VertexCache::unlink(std::uint32_t slot) {
  const Slot& s = slots_[slot];
  (s.prev == kNoSlot ? head_ : slots_[s.prev].next) = s.next;
  (s.next == kNoSlot ? tail_ : slots_[s.next].prev) = s.prev;
}

void VertexCache::push_front(std::uint32_t slot) {
  slots_[slot].prev = kNoSlot;
  slots_[slot].next = head_;
  (head_ == kNoSlot ? tail_ : slots_[head_].prev) = slot;
  head_ = slot;
}

bool VertexCache::access_lru(std::uint32_t vertex) {
  if (vertex >= slot_of_.size())
    grow_to_cover(slot_of_, vertex, "per-vertex LRU slots");
  if (const std::uint32_t found = slot_of_[vertex]) {
    if (found - 1 != head_) {
      unlink(found - 1);
      push_front(found - 1);
    }
    return true;
  }
  std::uint32_t slot;
  if (slots_.size() < entries_) {
    slot = static_cast<std::uint32_t>(slots_.size());
    slots_.push_back({vertex, kNoSlot, kNoSlot});
  } else {
    slot = tail_;  // evict the least recently used
    slot_of_[slots_[slot].vertex] = 0;
    unlink(slot);
    slots_[slot].vertex = vertex;
  }
  slot_of_[vertex] = slot + 1;
  push_front(slot);
  return false;
}

namespace {

// The common case (FIFO over a triangle list) in one flat pass, meshoptimizer style: a vertex's
// timestamp says both whether it is cached and whether it was ever seen (0 = never).
VertexStreamStats simulate_fifo_list(std::span<const std::uint32_t> indices, unsigned entries) {
  VertexStreamStats stats;
  std::vector<std::uint32_t> stamps(1024, 0);
  std::uint32_t clock = entries + 1;
  std::uint64_t misses = 0, vertices = 0, degenerate = 0;
  const auto lookup = [&](std::uint32_t v) {
    if (v >= stamps.size()) [[unlikely]]
      grow_to_cover(stamps, v, "per-vertex FIFO stamps");
    // Branch-free: a miss is data-dependent and mispredicts often; selects do not.
    std::uint32_t& stamp = stamps[v];
    const std::uint32_t old = stamp;
    const std::uint32_t miss = clock - old > entries;
    vertices += miss & (old == 0);
    stamp = miss ? clock : old;
    clock += miss;
    misses += miss;
  };
  const std::size_t whole = indices.size() - indices.size() % 3;
  const std::uint32_t* p = indices.data();
  for (std::size_t i = 0; i < whole; i += 3) {
    const std::uint32_t a = p[i], b = p[i + 1], c = p[i + 2];
    degenerate += (a == b) | (b == c) | (a == c);
    lookup(a);
    lookup(b);
    lookup(c);
  }
  for (std::size_t i = whole; i < indices.size(); ++i) lookup(p[i]);  // a trailing partial triangle is still fetched
  stats.lookups = stats.indices_sent = indices.size();
  stats.misses = misses;
  stats.vertices = vertices;
  stats.degenerate = degenerate;
  stats.triangles = whole / 3 - degenerate;
  return stats;
}

}  // namespace

VertexStreamStats vertex_stream_shape(std::span<const std::uint32_t> indices, PrimitiveType type,
                                      RestartIndex restart_index) {
  VertexStreamStats stats;
  std::vector<bool> seen;
  for (const std::uint32_t index : indices) {
    ++stats.indices_sent;
    if (is_restart(type, restart_index, index)) continue;
    ++stats.lookups;
    if (index >= seen.size()) grow_to_cover(seen, index, "per-vertex seen flags", false);
    if (!seen[index]) {
      seen[index] = true;
      ++stats.vertices;
    }
  }
  for_each_triangle(indices, type, restart_index, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (a == b || b == c || a == c)
      ++stats.degenerate;
    else
      ++stats.triangles;
  });
  return stats;
}

VertexStreamStats simulate_vertex_stream(std::span<const std::uint32_t> indices, PrimitiveType type,
                                         VertexCachePolicy policy, unsigned entries, RestartIndex restart_index) {
  VertexCache cache(policy, entries);
  // 2^32 - entries misses would wrap the 32-bit clock: longer streams take the general path.
  if (type == PrimitiveType::TriangleList && policy == VertexCachePolicy::Fifo &&
      indices.size() < std::size_t{0x7FFFFFFF} - entries)
    return simulate_fifo_list(indices, entries);
  VertexStreamStats stats = vertex_stream_shape(indices, type, restart_index);
  for (const std::uint32_t index : indices)
    if (!is_restart(type, restart_index, index) && !cache.access(index)) ++stats.misses;
  return stats;
}

}  // namespace rastrace
