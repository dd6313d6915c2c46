#include "cache_sim/write_back_cache.h"

#include <bit>

#include "core/error.h"

namespace rastrace {

WriteBackCache::WriteBackCache(const CacheConfig& config) : config_(config), rng_(config.seed) {
  validate(config_);
  if (config_.policy == ReplacementPolicy::Opt)
    throw InputError("cache " + describe(config_) +
                     ": opt is not a policy for a write-back (depth or colour) cache; expected fifo, lru or random");
  line_shift_ = static_cast<std::uint32_t>(std::countr_zero(config_.line_bytes));
  ways_ = static_cast<std::uint32_t>(config_.ways());
  sets_ = config_.sets();
  tags_.assign(config_.lines(), ~std::uint64_t{0});
  stamps_.assign(config_.lines(), 0);
  dirty_.assign(config_.lines(), 0);
}

void WriteBackCache::access(std::uint64_t line, bool write) {
  const std::uint64_t first = (line % sets_) * ways_;
  std::uint64_t* tags = tags_.data() + first;
  std::uint64_t* stamps = stamps_.data() + first;
  std::uint8_t* dirty = dirty_.data() + first;
  if (write)
    ++stats_.writes;
  else
    ++stats_.reads;
  std::uint32_t victim = 0;
  std::uint64_t oldest = ~std::uint64_t{0};
  for (std::uint32_t w = 0; w < ways_; ++w) {
    if (tags[w] == line) {
      if (config_.policy == ReplacementPolicy::Lru) stamps[w] = ++clock_;
      dirty[w] |= static_cast<std::uint8_t>(write);
      return;
    }
    if (stamps[w] < oldest) {
      oldest = stamps[w];
      victim = w;
    }
  }
  // Empty ways fill first; a full set loses its oldest line (fifo, lru) or a random one.
  if (config_.policy == ReplacementPolicy::Random && oldest != 0)
    victim = static_cast<std::uint32_t>(rng_.next() % ways_);
  if (stamps[victim] != 0 && dirty[victim]) ++stats_.lines_written_back;
  if (write) {
    ++stats_.write_misses;
  } else {
    ++stats_.read_misses;
    ++stats_.lines_fetched;
  }
  tags[victim] = line;
  stamps[victim] = ++clock_;
  dirty[victim] = static_cast<std::uint8_t>(write);
}

void WriteBackCache::flush() {
  for (std::size_t i = 0; i < dirty_.size(); ++i) {
    stats_.lines_written_back += dirty_[i];
    dirty_[i] = 0;
  }
}

WriteBackStats WriteBackCache::stats() const {
  WriteBackStats s = stats_;
  s.bytes_read = s.lines_fetched * config_.line_bytes;
  s.bytes_written = s.lines_written_back * config_.line_bytes;
  return s;
}

}  // namespace rastrace
