// Online byte-addressed cache models: FIFO, LRU and seeded random replacement, any associativity
// (see cache_config.h; OPT needs the future and lives in opt_cache.h).
// Two engines behind one class, chosen from the geometry:
//   - up to 16 ways: the set's tags and timestamps side by side, scanned linearly (LRU victim =
//     oldest use, FIFO victim = oldest insertion; empty ways fill first, lowest way first);
//   - more ways (fully associative caches): a flat hash map from line to slot plus, per set, an
//     intrusive LRU list or a FIFO ring, so an access is O(1) whatever the capacity.
// Expect well over 100 M accesses/s for small associativities (docs/PERFORMANCE.md).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cache_sim/cache_config.h"
#include "cache_sim/line_map.h"

namespace rastrace {

class ByteCache {
 public:
  // Throws InputError on an invalid geometry or on the opt policy.
  explicit ByteCache(const CacheConfig& config);

  // Byte address -> true on a hit. A miss fetches the whole line.
  bool access(std::uint64_t address) { return access_line(address >> line_shift_); }
  // Line number (address / line size) -> true on a hit.
  bool access_line(std::uint64_t line) {
    ++accesses_;
    const bool hit = scan_ ? access_scan(line) : access_hashed(line);
    misses_ += !hit;
    return hit;
  }
  // Runs a batch of line numbers; returns the misses among them.
  std::uint64_t access_lines(std::span<const std::uint64_t> lines);

  void clear();
  const CacheConfig& config() const { return config_; }
  std::uint32_t line_shift() const { return line_shift_; }
  std::uint64_t accesses() const { return accesses_; }
  std::uint64_t misses() const { return misses_; }
  // accesses, hits, misses, bytes fetched (no three-C split: see LruStackProfile).
  CacheStats stats() const;

 private:
  std::uint64_t set_of(std::uint64_t line) const { return sets_pow2_ ? (line & set_mask_) : (line % sets_); }

  template <ReplacementPolicy P>
  bool scan_set(std::uint64_t line) {
    const std::uint64_t first = set_of(line) * ways_;
    std::uint64_t* tags = tags_.data() + first;
    std::uint64_t* stamps = stamps_.data() + first;
    std::uint32_t victim = 0;
    std::uint64_t oldest = ~std::uint64_t{0};
    for (std::uint32_t w = 0; w < ways_; ++w) {
      if (tags[w] == line) {
        if constexpr (P == ReplacementPolicy::Lru) stamps[w] = ++clock_;
        return true;
      }
      if (stamps[w] < oldest) {
        oldest = stamps[w];
        victim = w;
      }
    }
    if constexpr (P == ReplacementPolicy::Random) {
      if (oldest != 0) victim = static_cast<std::uint32_t>(rng_.next() % ways_);
    }
    tags[victim] = line;
    stamps[victim] = ++clock_;
    return false;
  }

  bool access_scan(std::uint64_t line) {
    switch (config_.policy) {
      case ReplacementPolicy::Lru:
        return scan_set<ReplacementPolicy::Lru>(line);
      case ReplacementPolicy::Fifo:
        return scan_set<ReplacementPolicy::Fifo>(line);
      default:
        return scan_set<ReplacementPolicy::Random>(line);
    }
  }
  bool access_hashed(std::uint64_t line);

  CacheConfig config_;
  std::uint32_t line_shift_ = 0;
  std::uint32_t ways_ = 0;
  std::uint64_t sets_ = 0;
  std::uint64_t set_mask_ = 0;
  bool sets_pow2_ = true;
  bool scan_ = true;
  std::uint64_t accesses_ = 0;
  std::uint64_t misses_ = 0;
  std::uint64_t clock_ = 0;
  CacheRng rng_;
  // Scan engine: per way its line (~0 = empty) and its timestamp (0 = empty).
  std::vector<std::uint64_t> tags_;
  std::vector<std::uint64_t> stamps_;
  // Hashed engine: slot = set * ways + way.
  LineMap map_;
  std::vector<std::uint64_t> slot_line_;
  std::vector<std::uint32_t> prev_, next_;  // LRU list per set, through slots
  std::vector<std::uint32_t> head_;         // per set: most recent slot (LRU) or next victim (FIFO)
  std::vector<std::uint32_t> filled_;       // per set: ways in use
};

}  // namespace rastrace
