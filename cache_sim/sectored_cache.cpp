#include "cache_sim/sectored_cache.h"

#include <bit>

#include "core/error.h"
#include "core/units.h"

namespace rastrace {

namespace {
constexpr std::uint32_t kScanWays = 16;
}

SectoredCache::SectoredCache(const CacheConfig& config, std::uint32_t sector_bytes)
    : config_(config), sector_bytes_(sector_bytes ? sector_bytes : config.line_bytes), rng_(config.seed) {
  validate(config);
  if (config.policy == ReplacementPolicy::Opt)
    throw InputError("cache " + describe(config) + ": a sectored or hierarchy level is fifo, lru or random, not opt");
  if (!std::has_single_bit(sector_bytes_) || sector_bytes_ > config.line_bytes)
    throw InputError("cache " + describe(config) + ": sector " + format_byte_size(sector_bytes_) +
                     ": expected a power of two no larger than the line");
  if (config.line_bytes / sector_bytes_ > 64)
    throw InputError("cache " + describe(config) + ": sector " + format_byte_size(sector_bytes_) + ": " +
                     std::to_string(config.line_bytes / sector_bytes_) + " sectors per line, expected at most 64");
  line_shift_ = static_cast<std::uint32_t>(std::countr_zero(config.line_bytes));
  sector_shift_ = static_cast<std::uint32_t>(std::countr_zero(sector_bytes_));
  ways_ = static_cast<std::uint32_t>(config.ways());
  sets_ = config.sets();
  sets_pow2_ = std::has_single_bit(sets_);
  set_mask_ = sets_ - 1;
  hashed_ = ways_ > kScanWays;
  clear();
}

void SectoredCache::clear() {
  accesses_ = misses_ = line_misses_ = clock_ = 0;
  rng_ = CacheRng(config_.seed);
  const std::uint64_t slots = sets_ * ways_;
  tags_.assign(slots, kEmpty);
  stamps_.assign(slots, 0);
  present_.assign(slots, 0);
  if (hashed_) map_.reset(slots);
}

std::uint32_t SectoredCache::find(std::uint64_t line, std::uint64_t first_slot) const {
  if (hashed_) return map_.find(line);
  for (std::uint32_t w = 0; w < ways_; ++w)
    if (tags_[first_slot + w] == line) return static_cast<std::uint32_t>(first_slot + w);
  return LineMap::kMissing;
}

// The lowest empty way, else the policy's victim.
std::uint32_t SectoredCache::choose_victim(std::uint64_t first_slot) {
  std::uint64_t victim = first_slot;
  std::uint64_t oldest = ~std::uint64_t{0};
  for (std::uint64_t s = first_slot; s < first_slot + ways_; ++s) {
    if (tags_[s] == kEmpty) return static_cast<std::uint32_t>(s);
    if (stamps_[s] < oldest) {
      oldest = stamps_[s];
      victim = s;
    }
  }
  if (config_.policy == ReplacementPolicy::Random) victim = first_slot + rng_.next() % ways_;
  return static_cast<std::uint32_t>(victim);
}

SectoredCache::Outcome SectoredCache::access(std::uint64_t address) {
  ++accesses_;
  ++clock_;
  const std::uint64_t line = address >> line_shift_;
  const std::uint64_t sector_bit = std::uint64_t{1} << ((address >> sector_shift_) & (sectors_per_line() - 1));
  const std::uint64_t first_slot = set_of(line) * ways_;
  Outcome out;
  std::uint32_t slot = find(line, first_slot);
  if (slot != LineMap::kMissing) {
    out.line_hit = true;
    out.hit = (present_[slot] & sector_bit) != 0;
    if (config_.policy == ReplacementPolicy::Lru) stamps_[slot] = clock_;
    if (!out.hit) {
      ++misses_;
      present_[slot] |= sector_bit;
    }
    return out;
  }
  ++misses_;
  ++line_misses_;
  slot = choose_victim(first_slot);
  if (tags_[slot] != kEmpty) {
    out.evicted = true;
    out.evicted_line = tags_[slot];
    if (hashed_) map_.erase(tags_[slot]);
  }
  tags_[slot] = line;
  stamps_[slot] = clock_;
  present_[slot] = sector_bit;
  if (hashed_) map_.insert(line, slot);
  return out;
}

std::uint64_t SectoredCache::invalidate(std::uint64_t first, std::uint64_t bytes) {
  if (bytes == 0) return 0;
  std::uint64_t dropped = 0;
  const std::uint64_t last = (first + bytes - 1) >> line_shift_;
  for (std::uint64_t line = first >> line_shift_; line <= last; ++line) {
    const std::uint32_t slot = find(line, set_of(line) * ways_);
    if (slot == LineMap::kMissing) continue;
    if (hashed_) map_.erase(line);
    tags_[slot] = kEmpty;
    stamps_[slot] = 0;
    present_[slot] = 0;
    ++dropped;
  }
  return dropped;
}

}  // namespace rastrace
