// A byte cache with dirty lines: the depth and colour caches of a raster back end, which read
// and write the framebuffer and so send traffic both ways.
//   read     a miss fetches the line from memory (line bytes read)
//   write    marks the line dirty; a write miss allocates the line without reading memory (the
//            lines carry byte masks, as GPU render-back-end caches do), so a colour buffer drawn
//            without blending is never read
//   evict    a dirty victim is written back (line bytes written)
//   flush    at the end of the frame every dirty line is written back
// Replacement: fifo, lru or seeded random (cache_config.h); opt is refused (a write-back cache's
// victim choice changes what it writes, which Belady's MIN does not model). The sets are scanned
// linearly, so a fully associative cache costs O(lines) per access: meant for the small caches
// of a raster back end (ATTILA's are 4-way, 64 lines).
#pragma once

#include <cstdint>
#include <vector>

#include "cache_sim/cache_config.h"

namespace rastrace {

struct WriteBackStats {
  std::uint64_t reads = 0;   // accesses, one per pixel
  std::uint64_t writes = 0;
  std::uint64_t read_misses = 0;
  std::uint64_t write_misses = 0;
  std::uint64_t lines_fetched = 0;       // read misses
  std::uint64_t lines_written_back = 0;  // dirty evictions and the end-of-frame flush
  std::uint64_t bytes_read = 0;          // lines_fetched * line size
  std::uint64_t bytes_written = 0;       // lines_written_back * line size

  bool operator==(const WriteBackStats&) const = default;
};

class WriteBackCache {
 public:
  // Throws InputError on an invalid geometry or on the opt policy.
  explicit WriteBackCache(const CacheConfig& config);

  // Line numbers (byte address >> line_shift()).
  void read(std::uint64_t line) { access(line, false); }
  void write(std::uint64_t line) { access(line, true); }
  // Writes back every dirty line; the lines stay cached, clean.
  void flush();

  const CacheConfig& config() const { return config_; }
  std::uint32_t line_shift() const { return line_shift_; }
  WriteBackStats stats() const;

 private:
  void access(std::uint64_t line, bool write);

  CacheConfig config_;
  std::uint32_t line_shift_ = 0;
  std::uint32_t ways_ = 0;
  std::uint64_t sets_ = 0;
  std::uint64_t clock_ = 0;
  CacheRng rng_;
  // Per way: its line, its timestamp (0 = empty; LRU: last use, FIFO: insertion), dirty.
  std::vector<std::uint64_t> tags_;
  std::vector<std::uint64_t> stamps_;
  std::vector<std::uint8_t> dirty_;
  WriteBackStats stats_;
};

}  // namespace rastrace
