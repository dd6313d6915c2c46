// A cache hierarchy: levels 0 (L1, nearest the sampler) .. n-1, each a SectoredCache (any cache
// the grammar describes, sectors optional), with `units` copies of L1 in front of shared lower
// levels, as a GPU's texture units each have an L1 and share an L2.
//
// Requests flow down:
//   - an access goes to the L1 of its unit; unit_of_pixel() distributes screen tiles among units
//     (tile t = (x / tile, y / tile) goes to unit (tx + ty) mod units, so side-by-side and stacked
//     tiles land on different units, as GPUs hand quads of neighbouring tiles to different cores);
//   - a miss at level k fetches its granule (its sector, the line when unsectored) from level
//     k+1: one level-(k+1) access per level-(k+1) granule the range covers (a 128-byte L1 line over
//     a 32-byte-sectored L2 is 4 L2 accesses; a 32-byte L1 sector over a 128-byte L2 line is 1);
//     the miss's own line is allocated at level k before level k+1 is asked.
// Inclusion:
//   non-inclusive  levels fill independently; a lower level's eviction leaves upper levels alone
//   inclusive      when level k >= 1 evicts a line, every upper-level line overlapping its bytes
//                  is invalidated, in every L1 (back-invalidation), so upper contents stay a
//                  subset of lower ones
// Decoded L1 (decoded_l1): for block-compressed textures, the L1 holds decoded texels and the
// levels below hold compressed blocks, as texture units decompress between a cache of blocks and
// a cache of texels. L1 addresses are then in the decoded space (TextureLayout::decoded_address)
// and an L1 miss asks the next level for the compressed bytes its granule decodes from: granule
// [a, a + g) is [a >> s, (a + g) >> s) compressed, at least one byte, where 2^s is the texture's
// decoded bytes per compressed byte (8 for BC1, 4 for BC7). Inclusive hierarchies are refused
// here: a lower line's bytes would map back to a different range per format.
// Per level: accesses, misses (sector misses included), line misses, bytes requested from it
// (L1: accesses * element bytes, the texel size; below: the bytes the level above fetched),
// bytes it fetched from the next level (misses * granule). Request miss ratio = misses /
// accesses, byte miss ratio = bytes fetched / bytes requested; L1 figures sum the units.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cache_sim/sectored_cache.h"

namespace rastrace {

enum class Inclusion : std::uint8_t { NonInclusive, Inclusive };
const char* to_string(Inclusion inclusion);  // "non-inclusive", "inclusive"
// "inclusive", "non-inclusive"; InputError otherwise.
Inclusion parse_inclusion(const std::string& text);

struct CacheLevelSpec {
  CacheConfig cache;
  std::uint32_t sector_bytes = 0;  // 0: the whole line
};

struct HierarchyConfig {
  std::vector<CacheLevelSpec> levels;  // [0] = L1
  std::uint32_t units = 1;             // L1 copies (texture units)
  std::uint32_t tile = 16;             // pixels: side of the screen tiles dealt out to the units
  Inclusion inclusion = Inclusion::NonInclusive;
  std::uint32_t element_bytes = 4;  // bytes one L1 access asks for (the texel size)
  bool decoded_l1 = false;          // L1 of decoded texels over levels of compressed blocks
};

struct LevelStats {
  std::uint64_t accesses = 0;
  std::uint64_t misses = 0;       // accesses whose sector was absent (line misses included)
  std::uint64_t line_misses = 0;  // accesses whose line was absent
  std::uint64_t bytes_requested = 0;
  std::uint64_t bytes_fetched = 0;  // from the next level (memory below the last)
  std::uint64_t invalidations = 0;  // lines dropped by back-invalidation (inclusive only)

  double request_miss_ratio() const { return accesses ? double(misses) / double(accesses) : 0.0; }
  double byte_miss_ratio() const { return bytes_requested ? double(bytes_fetched) / double(bytes_requested) : 0.0; }
  bool operator==(const LevelStats&) const = default;
};

class CacheHierarchy {
 public:
  // Throws InputError on no level, zero units or tile, or an invalid level (named L1, L2, ...).
  explicit CacheHierarchy(HierarchyConfig config);

  // One element read by texture unit `unit` (< units) at byte `address`; true on an L1 hit.
  // decode_shift: for a decoded L1, log2 of the texture's decoded bytes per compressed byte.
  bool access(std::uint64_t address, std::uint32_t unit, std::uint32_t decode_shift = 0);
  static std::uint32_t unit_of_pixel(std::uint32_t x, std::uint32_t y, std::uint32_t tile, std::uint32_t units) {
    return (x / tile + y / tile) % units;
  }
  std::uint32_t unit_of_pixel(std::uint32_t x, std::uint32_t y) const {
    return unit_of_pixel(x, y, config_.tile, config_.units);
  }

  const HierarchyConfig& config() const { return config_; }
  // One entry per level; L1 sums its units.
  std::vector<LevelStats> stats() const;
  // The L1 of one unit alone.
  LevelStats unit_stats(std::uint32_t unit) const;

 private:
  void fill(std::size_t level, std::uint64_t first, std::uint64_t bytes);
  void back_invalidate(std::size_t level, std::uint64_t line);

  HierarchyConfig config_;
  std::vector<SectoredCache> l1_;     // one per unit
  std::vector<SectoredCache> lower_;  // levels 1..n-1
  std::vector<std::uint64_t> l1_requested_, l1_invalidated_;
  std::vector<std::uint64_t> lower_requested_, lower_invalidated_;
};

// "L1 16KiB/128B/4-way/lru sector 32B x4 units | L2 ..." for table titles and errors.
std::string describe(const HierarchyConfig& config);

}  // namespace rastrace
