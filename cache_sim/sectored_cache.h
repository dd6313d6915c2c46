// A sectored byte cache (Dinero IV's sub-blocks; NVIDIA's L1 since Fermi: 128-byte lines of four
// 32-byte sectors): a line is one tag and S sectors, each present or not. An access asks for the
// sector holding its byte:
//   line miss    the tag is absent: a way is (re)allocated, its sectors all absent, and only the
//                accessed sector is fetched
//   sector miss  the tag is present but the sector is not: only that sector is fetched
//   hit          the sector is present
// misses() counts both kinds (every access whose data was absent); line_misses() the first kind.
// Bytes fetched = misses() * sector bytes. With one sector per line (sector = line) the cache is
// ByteCache to the miss: same geometry, same fifo / lru / random rules (empty ways fill first,
// lowest way first; the random victim is draw % ways, cache_config.h), a sector miss on a
// resident line counts as a use for LRU and changes nothing for FIFO.
// invalidate() drops resident lines (back-invalidation by an inclusive lower level); the freed
// ways are empty and fill first again.
#pragma once

#include <cstdint>
#include <vector>

#include "cache_sim/cache_config.h"
#include "cache_sim/line_map.h"

namespace rastrace {

class SectoredCache {
 public:
  // sector_bytes 0 means the whole line. Throws InputError on an invalid geometry, on a sector
  // that is not a power of two dividing the line, on more than 64 sectors and on policy opt.
  SectoredCache(const CacheConfig& config, std::uint32_t sector_bytes);

  struct Outcome {
    bool hit = false;       // the sector was present
    bool line_hit = false;  // the tag was present
    bool evicted = false;   // a resident line was replaced to make room
    std::uint64_t evicted_line = 0;
  };
  Outcome access(std::uint64_t address);
  // Drops every resident line overlapping bytes [first, first + bytes); returns how many.
  std::uint64_t invalidate(std::uint64_t first, std::uint64_t bytes);
  void clear();

  const CacheConfig& config() const { return config_; }
  std::uint32_t sector_bytes() const { return sector_bytes_; }
  std::uint32_t sectors_per_line() const { return config_.line_bytes / sector_bytes_; }
  std::uint64_t accesses() const { return accesses_; }
  std::uint64_t misses() const { return misses_; }
  std::uint64_t line_misses() const { return line_misses_; }
  std::uint64_t bytes_fetched() const { return misses_ * sector_bytes_; }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  std::uint64_t set_of(std::uint64_t line) const { return sets_pow2_ ? (line & set_mask_) : (line % sets_); }
  std::uint32_t find(std::uint64_t line, std::uint64_t first_slot) const;
  std::uint32_t choose_victim(std::uint64_t first_slot);

  CacheConfig config_;
  std::uint32_t sector_bytes_ = 0;
  std::uint32_t line_shift_ = 0;
  std::uint32_t sector_shift_ = 0;
  std::uint32_t ways_ = 0;
  std::uint64_t sets_ = 0;
  std::uint64_t set_mask_ = 0;
  bool sets_pow2_ = true;
  bool hashed_ = false;  // more than 16 ways: lines found through map_
  std::uint64_t accesses_ = 0, misses_ = 0, line_misses_ = 0, clock_ = 0;
  CacheRng rng_;
  // Per slot (set * ways + way): its line (kEmpty = empty), LRU last use or FIFO insertion time,
  // present sectors (bit s = sector s).
  std::vector<std::uint64_t> tags_, stamps_, present_;
  LineMap map_;
};

}  // namespace rastrace
