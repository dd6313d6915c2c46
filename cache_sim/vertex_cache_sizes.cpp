#include "cache_sim/vertex_cache_sizes.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "core/input_guard.h"
#include "core/error.h"
#include "core/function_clones.h"

namespace rastrace {

namespace {

// Sixteen 32-bit lanes: one AVX-512 register, two AVX2 or four SSE2 registers depending on the
// clone of fifo_run() the CPU selects.
using Lanes = std::uint32_t __attribute__((vector_size(64)));
constexpr std::uint32_t kLaneWidth = 16;

// Accesses processed between folds of the 32-bit lane counters (and clock checks).
constexpr std::size_t kSlice = std::size_t{1} << 30;
// A lane clock above this is rebased before it can wrap (a slice adds at most kSlice).
constexpr std::uint32_t kClockRebase = std::uint32_t{1} << 31;
constexpr std::size_t kPrefetch = 8;

template <int Groups>
[[gnu::always_inline]] inline void fifo_groups(const std::uint32_t* vertices, std::size_t n, std::uint32_t* stamps,
                                               std::uint32_t* clock_out, const std::uint32_t* size_in,
                                               std::uint32_t* miss_out) {
  constexpr std::uint32_t lanes = Groups * kLaneWidth;
  Lanes clock[Groups], size[Groups], misses[Groups];
  for (int g = 0; g < Groups; ++g) {
    std::memcpy(&clock[g], clock_out + g * kLaneWidth, sizeof(Lanes));
    std::memcpy(&size[g], size_in + g * kLaneWidth, sizeof(Lanes));
    std::memcpy(&misses[g], miss_out + g * kLaneWidth, sizeof(Lanes));
  }
  for (std::size_t i = 0; i < n; ++i) {
    // The stamps of a vertex are a few cache lines of a large table: fetch those of the vertex
    // kPrefetch accesses ahead while this one is simulated (the loads are the cost otherwise).
    if (i + kPrefetch < n) {
      const std::uint32_t* ahead = stamps + std::size_t{vertices[i + kPrefetch]} * lanes;
      for (int g = 0; g < Groups; ++g) __builtin_prefetch(ahead + g * kLaneWidth, 1);
    }
    std::uint32_t* stamp = stamps + std::size_t{vertices[i]} * lanes;
    for (int g = 0; g < Groups; ++g) {
      Lanes s;
      std::memcpy(&s, stamp + g * kLaneWidth, sizeof(Lanes));
      const Lanes miss = (Lanes)(clock[g] - s > size[g]);  // all ones where the lane misses
      s = (s & ~miss) | (clock[g] & miss);
      clock[g] -= miss;
      misses[g] -= miss;
      std::memcpy(stamp + g * kLaneWidth, &s, sizeof(Lanes));
    }
  }
  for (int g = 0; g < Groups; ++g) {
    std::memcpy(clock_out + g * kLaneWidth, &clock[g], sizeof(Lanes));
    std::memcpy(miss_out + g * kLaneWidth, &misses[g], sizeof(Lanes));
  }
}

// Every FIFO lane over vertices[0, n). Lane counts up to 64 keep clocks and counters in registers.
RASTRACE_CLONES("avx512f", "avx2", "default")
void fifo_run(
    const std::uint32_t* vertices, std::size_t n, std::uint32_t* stamps, std::uint32_t lanes, std::uint32_t* clocks,
    const std::uint32_t* sizes, std::uint32_t* misses) {
  switch (lanes / kLaneWidth) {
    case 1:
      return fifo_groups<1>(vertices, n, stamps, clocks, sizes, misses);
    case 2:
      return fifo_groups<2>(vertices, n, stamps, clocks, sizes, misses);
    case 3:
      return fifo_groups<3>(vertices, n, stamps, clocks, sizes, misses);
    case 4:
      return fifo_groups<4>(vertices, n, stamps, clocks, sizes, misses);
    default:
      break;
  }
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t* stamp = stamps + std::size_t{vertices[i]} * lanes;
    for (std::uint32_t l = 0; l < lanes; ++l) {
      const std::uint32_t miss = clocks[l] - stamp[l] > sizes[l];
      stamp[l] = miss ? clocks[l] : stamp[l];
      clocks[l] += miss;
      misses[l] += miss;
    }
  }
}

}  // namespace

VertexCacheSizes::VertexCacheSizes(VertexCachePolicy policy, std::vector<unsigned> entries)
    : policy_(policy), entries_(std::move(entries)) {
  for (const unsigned k : entries_)
    if (k == 0) throw InputError("vertex cache size 0: expected at least 1 entry");
  if (policy_ == VertexCachePolicy::Lru) {
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      if (entries_[i] <= kMaxStackDepth)
        depth_ = std::max(depth_, entries_[i]);
      else
        single_.push_back({i, VertexCache(VertexCachePolicy::Lru, entries_[i])});
    }
    stack_.assign(depth_, 0);
    depth_hits_.assign(depth_, 0);
    return;
  }
  lanes_ = static_cast<std::uint32_t>((entries_.size() + kLaneWidth - 1) / kLaneWidth * kLaneWidth);
  // Padding lanes simulate a 1-entry cache nobody reads.
  sizes_.assign(lanes_, 1);
  std::copy(entries_.begin(), entries_.end(), sizes_.begin());
  clocks_.resize(lanes_);
  for (std::uint32_t l = 0; l < lanes_; ++l) clocks_[l] = sizes_[l] + 1;
  lane_misses_.assign(lanes_, 0);
  fifo_misses_.assign(lanes_, 0);
}

std::uint64_t VertexCacheSizes::misses(std::size_t i) const {
  if (policy_ == VertexCachePolicy::Fifo) return fifo_misses_[i] + lane_misses_[i];
  for (const Single& s : single_)
    if (s.index == i) return s.misses;
  std::uint64_t hits = 0;
  for (unsigned d = 0; d < entries_[i]; ++d) hits += depth_hits_[d];
  return accesses_ - hits;
}

void VertexCacheSizes::access(std::span<const std::uint32_t> vertices) {
  accesses_ += vertices.size();
  if (policy_ == VertexCachePolicy::Lru)
    access_lru(vertices);
  else
    access_fifo(vertices);
}

void VertexCacheSizes::access_lru(std::span<const std::uint32_t> vertices) {
  for (Single& s : single_)
    for (const std::uint32_t v : vertices) s.misses += !s.cache.access(v);
  if (depth_ == 0) return;
  for (const std::uint32_t v : vertices) {
    if (v >= in_stack_.size()) [[unlikely]]
      grow_to_cover(in_stack_, v, "per-vertex LRU state");
    std::uint32_t d;
    if (in_stack_[v]) {
      d = 0;
      while (stack_[d] != v) ++d;  // it is there: no bound needed
      ++depth_hits_[d];
    } else {
      // A miss for every size: the deepest vertex (when the stack is full) falls off.
      if (filled_ == depth_)
        in_stack_[stack_[depth_ - 1]] = 0;
      else
        ++filled_;
      in_stack_[v] = 1;
      d = filled_ - 1;
    }
    std::memmove(stack_.data() + 1, stack_.data(), std::size_t{d} * sizeof(std::uint32_t));
    stack_[0] = v;
  }
}

void VertexCacheSizes::grow_fifo(std::uint32_t vertex) {
  const std::uint64_t ids = std::max<std::uint64_t>(std::uint64_t{vertex} + 1, ids_ * 2);
  checked_bytes(ids * lanes_, sizeof(stamps_[0]), "per-vertex FIFO stamps (vertex index " + std::to_string(vertex) + ")");
  stamps_.resize(ids * lanes_, 0);  // 0: never inserted, a miss at any clock (clocks exceed sizes)
  ids_ = ids;
}

void VertexCacheSizes::rebase_fifo() {
  // Keeps clock - stamp for every stamp still within its lane's size, and makes the others 0.
  for (std::uint32_t l = 0; l < lanes_; ++l) {
    const std::uint32_t base = clocks_[l] - sizes_[l] - 1;
    for (std::uint64_t v = 0; v < ids_; ++v) {
      std::uint32_t& s = stamps_[v * lanes_ + l];
      s = s > base ? s - base : 0;
    }
    clocks_[l] = sizes_[l] + 1;
  }
}

void VertexCacheSizes::access_fifo(std::span<const std::uint32_t> vertices) {
  for (std::size_t begin = 0; begin < vertices.size(); begin += kSlice) {
    const std::span<const std::uint32_t> slice = vertices.subspan(begin, std::min(kSlice, vertices.size() - begin));
    const std::uint32_t top = *std::max_element(slice.begin(), slice.end());
    if (top >= ids_) grow_fifo(top);
    fifo_run(slice.data(), slice.size(), stamps_.data(), lanes_, clocks_.data(), sizes_.data(), lane_misses_.data());
    for (std::uint32_t l = 0; l < lanes_; ++l) {
      fifo_misses_[l] += lane_misses_[l];
      lane_misses_[l] = 0;
    }
    if (*std::max_element(clocks_.begin(), clocks_.end()) > kClockRebase) rebase_fifo();
  }
}

void VertexCacheSizes::clear() {
  if (policy_ == VertexCachePolicy::Lru) {
    for (std::uint32_t d = 0; d < filled_; ++d) in_stack_[stack_[d]] = 0;
    filled_ = 0;
    for (Single& s : single_) s.cache.clear();
    return;
  }
  // Every stamp is below its lane's clock: moving the clock on by the size evicts them all.
  bool wrap = false;
  for (std::uint32_t l = 0; l < lanes_; ++l) {
    clocks_[l] += sizes_[l] + 1;
    wrap |= clocks_[l] > kClockRebase;
  }
  if (wrap) {
    std::fill(stamps_.begin(), stamps_.end(), 0);
    for (std::uint32_t l = 0; l < lanes_; ++l) clocks_[l] = sizes_[l] + 1;
  }
}

std::vector<VertexStreamStats> simulate_vertex_stream_sizes(std::span<const std::uint32_t> indices,
                                                            PrimitiveType type, VertexCachePolicy policy,
                                                            const std::vector<unsigned>& entries,
                                                            RestartIndex restart_index) {
  VertexCacheSizes caches(policy, entries);
  const VertexStreamStats shape = vertex_stream_shape(indices, type, restart_index);
  if (type == PrimitiveType::TriangleStrip && restart_index) {
    std::vector<std::uint32_t> fetched;
    fetched.reserve(indices.size());
    for (const std::uint32_t v : indices)
      if (v != *restart_index) fetched.push_back(v);
    caches.access(fetched);
  } else {
    caches.access(indices);
  }
  std::vector<VertexStreamStats> out(entries.size(), shape);
  for (std::size_t i = 0; i < entries.size(); ++i) out[i].misses = caches.misses(i);
  return out;
}

}  // namespace rastrace
