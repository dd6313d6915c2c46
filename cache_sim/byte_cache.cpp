#include "cache_sim/byte_cache.h"

#include <bit>

#include "core/error.h"
#include "core/input_guard.h"

namespace rastrace {

namespace {
constexpr std::uint32_t kScanWays = 16;
}

ByteCache::ByteCache(const CacheConfig& config) : config_(config), rng_(config.seed) {
  validate(config);
  if (config.policy == ReplacementPolicy::Opt)
    throw InputError("cache " + describe(config) + ": opt needs the whole trace (use simulate_opt)");
  line_shift_ = static_cast<std::uint32_t>(std::countr_zero(config.line_bytes));
  ways_ = static_cast<std::uint32_t>(config.ways());
  sets_ = config.sets();
  sets_pow2_ = std::has_single_bit(sets_);
  set_mask_ = sets_ - 1;
  scan_ = ways_ <= kScanWays;
  clear();
}

void ByteCache::clear() {
  accesses_ = misses_ = clock_ = 0;
  rng_ = CacheRng(config_.seed);
  const std::uint64_t lines = sets_ * ways_;
  // Per line: a tag and a stamp (scan), or map entry, line, links (larger sets).
  checked_bytes(lines, scan_ ? 16 : 40, "cache " + describe(config_) + ": simulator state");
  if (scan_) {
    tags_.assign(lines, ~std::uint64_t{0});
    stamps_.assign(lines, 0);
  } else {
    map_.reset(lines);
    slot_line_.assign(lines, 0);
    prev_.assign(lines, 0);
    next_.assign(lines, 0);
    head_.assign(sets_, 0);
    filled_.assign(sets_, 0);
  }
}

std::uint64_t ByteCache::access_lines(std::span<const std::uint64_t> lines) {
  const std::uint64_t before = misses_;
  if (scan_) {
    // One policy dispatch per batch, not per access.
    std::uint64_t misses = 0;
    switch (config_.policy) {
      case ReplacementPolicy::Lru:
        for (const std::uint64_t line : lines) misses += !scan_set<ReplacementPolicy::Lru>(line);
        break;
      case ReplacementPolicy::Fifo:
        for (const std::uint64_t line : lines) misses += !scan_set<ReplacementPolicy::Fifo>(line);
        break;
      default:
        for (const std::uint64_t line : lines) misses += !scan_set<ReplacementPolicy::Random>(line);
        break;
    }
    accesses_ += lines.size();
    misses_ += misses;
  } else {
    for (const std::uint64_t line : lines) access_line(line);
  }
  return misses_ - before;
}

bool ByteCache::access_hashed(std::uint64_t line) {
  const std::uint64_t set = set_of(line);
  const std::uint32_t first = static_cast<std::uint32_t>(set * ways_);
  const std::uint32_t found = map_.find(line);
  if (found != LineMap::kMissing) {
    if (config_.policy == ReplacementPolicy::Lru && head_[set] != found) {
      // Move to the front of the set's circular list.
      next_[prev_[found]] = next_[found];
      prev_[next_[found]] = prev_[found];
      const std::uint32_t head = head_[set];
      const std::uint32_t tail = prev_[head];
      prev_[found] = tail;
      next_[found] = head;
      next_[tail] = found;
      prev_[head] = found;
      head_[set] = found;
    }
    return true;
  }
  std::uint32_t slot;
  if (filled_[set] < ways_) {
    slot = first + filled_[set]++;
    if (config_.policy == ReplacementPolicy::Lru) {
      if (filled_[set] == 1) {
        prev_[slot] = next_[slot] = slot;
      } else {
        const std::uint32_t head = head_[set];
        const std::uint32_t tail = prev_[head];
        prev_[slot] = tail;
        next_[slot] = head;
        next_[tail] = slot;
        prev_[head] = slot;
      }
      head_[set] = slot;
    }
  } else {
    switch (config_.policy) {
      case ReplacementPolicy::Lru:
        // The tail becomes the head: rotating the circle by one is the whole update.
        slot = prev_[head_[set]];
        head_[set] = slot;
        break;
      case ReplacementPolicy::Fifo:
        slot = first + head_[set];
        head_[set] = head_[set] + 1 == ways_ ? 0 : head_[set] + 1;
        break;
      default:
        slot = first + static_cast<std::uint32_t>(rng_.next() % ways_);
        break;
    }
    map_.erase(slot_line_[slot]);
  }
  slot_line_[slot] = line;
  map_.insert(line, slot);
  return false;
}

CacheStats ByteCache::stats() const {
  CacheStats s;
  s.accesses = accesses_;
  s.misses = misses_;
  s.hits = accesses_ - misses_;
  s.bytes_fetched = misses_ * config_.line_bytes;
  return s;
}

}  // namespace rastrace
