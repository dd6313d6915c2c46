// A FIFO post-transform cache flushed at warp and primitive-group boundaries: the model of
// meshoptimizer's analyzer (meshopt_analyzeVertexCache, Kapoulkine), reproduced miss for miss and
// warp for warp (tests/cache_sim/vertex_reuse_test.cpp runs both in the same process).
//
// Per primitive, the vertices not in the FIFO are counted (a repeated vertex once per
// occurrence); if they would not fit in the current warp (warp_size lanes), or primgroup_size
// primitives are already in it, the warp is executed and the cache flushed before the primitive
// is added. A warp of 0 or a primgroup of 0 means no such limit; with both 0 this is a plain
// FIFO and the stream is one "warp". Lanes: every warp occupies warp_size lanes.
// meshoptimizer's profiles: NVIDIA Pascal 32/32/32, Kepler-Maxwell 16/32/32, AMD GCN 14/64/128,
// Intel 128/0/0 (the presets in cache_sim/vertex_reuse.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rastrace {

class WarpFifo {
 public:
  // entries >= 1; warp 0 or >= 3; primgroup any (0 = none). InputError otherwise.
  WarpFifo(unsigned entries, unsigned warp, unsigned primgroup);

  // Sizes the stamps for vertex ids below `vertex_count`, so a stream's walk never grows them.
  void reserve(std::size_t vertex_count) {
    if (vertex_count > stamps_.size()) stamps_.resize(vertex_count, 0);
  }
  // One primitive of `count` (3 or 6) fetched indices.
  void primitive(const std::uint32_t* vertices, unsigned count);
  // Executes the open warp and flushes the cache (a draw boundary).
  void flush();

  std::uint64_t misses() const { return misses_; }
  // Warps executed, the open one included.
  std::uint64_t warps() const { return warps_ + (warp_offset_ > 0); }

 private:
  bool cached(std::uint32_t vertex) const {
    return vertex < stamps_.size() && clock_ - stamps_[vertex] <= entries_;
  }
  void rebase_clock();

  unsigned entries_, warp_, primgroup_;
  // meshoptimizer's timestamps: a vertex is cached while fewer than `entries` misses happened
  // since its own; a flush advances the clock by entries + 1. 0 = never inserted.
  std::vector<std::uint32_t> stamps_;
  std::uint32_t clock_;
  unsigned warp_offset_ = 0, primgroup_offset_ = 0;
  std::uint64_t misses_ = 0, warps_ = 0;
};

}  // namespace rastrace
