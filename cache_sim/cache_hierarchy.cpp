#include "cache_sim/cache_hierarchy.h"

#include <algorithm>

#include "core/enum_names.h"
#include "core/error.h"
#include "core/units.h"

namespace rastrace {

namespace {

constexpr EnumName<Inclusion> kInclusions[] = {{Inclusion::NonInclusive, "non-inclusive"},
                                               {Inclusion::Inclusive, "inclusive"}};

SectoredCache make_level(const CacheLevelSpec& spec, std::size_t level) {
  try {
    return SectoredCache(spec.cache, spec.sector_bytes);
  } catch (const InputError& e) {
    throw InputError("L" + std::to_string(level + 1) + ": " + e.what());
  }
}

std::uint64_t granule(const SectoredCache& cache) { return cache.sector_bytes(); }

}  // namespace

const char* to_string(Inclusion inclusion) { return enum_to_string(inclusion, kInclusions); }
Inclusion parse_inclusion(const std::string& text) { return parse_enum(text, kInclusions, "inclusion"); }

CacheHierarchy::CacheHierarchy(HierarchyConfig config) : config_(std::move(config)) {
  if (config_.levels.empty()) throw InputError("cache hierarchy: expected at least one level");
  if (config_.units == 0) throw InputError("cache hierarchy: units=0: expected at least one texture unit");
  if (config_.tile == 0) throw InputError("cache hierarchy: tile=0: expected a tile side of at least one pixel");
  if (config_.element_bytes == 0) throw InputError("cache hierarchy: element bytes 0");
  if (config_.decoded_l1 && config_.levels.size() < 2)
    throw InputError("cache hierarchy: a decoded L1 needs a level of compressed blocks below it (a second --level)");
  if (config_.decoded_l1 && config_.inclusion == Inclusion::Inclusive)
    throw InputError(
        "cache hierarchy: a decoded L1 holds texels in another address space than the compressed levels below; "
        "inclusive back-invalidation is not modelled: expected --inclusion non-inclusive");
  for (std::uint32_t u = 0; u < config_.units; ++u) l1_.push_back(make_level(config_.levels[0], 0));
  for (std::size_t k = 1; k < config_.levels.size(); ++k) lower_.push_back(make_level(config_.levels[k], k));
  l1_requested_.assign(config_.units, 0);
  l1_invalidated_.assign(config_.units, 0);
  lower_requested_.assign(lower_.size(), 0);
  lower_invalidated_.assign(lower_.size(), 0);
}

bool CacheHierarchy::access(std::uint64_t address, std::uint32_t unit, std::uint32_t decode_shift) {
  SectoredCache& l1 = l1_[unit];
  l1_requested_[unit] += config_.element_bytes;
  const SectoredCache::Outcome outcome = l1.access(address);
  if (outcome.hit) return true;
  if (!lower_.empty()) {
    const std::uint64_t g = granule(l1);
    const std::uint64_t first = address & ~(g - 1);
    // Compressed bytes the decoded granule comes from; a granule smaller than its block's decoded
    // texels still needs the block, so at least one byte of it.
    fill(1, first >> decode_shift, std::max<std::uint64_t>(g >> decode_shift, 1));
  }
  return false;
}

// Level `level` (>= 1) is asked for bytes [first, first + bytes).
void CacheHierarchy::fill(std::size_t level, std::uint64_t first, std::uint64_t bytes) {
  SectoredCache& cache = lower_[level - 1];
  lower_requested_[level - 1] += bytes;
  const std::uint64_t g = granule(cache);
  for (std::uint64_t a = first & ~(g - 1); a < first + bytes; a += g) {
    const SectoredCache::Outcome outcome = cache.access(a);
    if (outcome.hit) continue;
    if (outcome.evicted && config_.inclusion == Inclusion::Inclusive) back_invalidate(level, outcome.evicted_line);
    if (level < config_.levels.size() - 1) fill(level + 1, a, g);
  }
}

void CacheHierarchy::back_invalidate(std::size_t level, std::uint64_t line) {
  const std::uint64_t line_bytes = lower_[level - 1].config().line_bytes;
  const std::uint64_t first = line * line_bytes;
  for (std::uint32_t u = 0; u < config_.units; ++u) l1_invalidated_[u] += l1_[u].invalidate(first, line_bytes);
  for (std::size_t k = 1; k < level; ++k) lower_invalidated_[k - 1] += lower_[k - 1].invalidate(first, line_bytes);
}

LevelStats CacheHierarchy::unit_stats(std::uint32_t unit) const {
  const SectoredCache& c = l1_.at(unit);
  LevelStats s;
  s.accesses = c.accesses();
  s.misses = c.misses();
  s.line_misses = c.line_misses();
  s.bytes_requested = l1_requested_[unit];
  s.bytes_fetched = c.bytes_fetched();
  s.invalidations = l1_invalidated_[unit];
  return s;
}

std::vector<LevelStats> CacheHierarchy::stats() const {
  std::vector<LevelStats> out(config_.levels.size());
  for (std::uint32_t u = 0; u < config_.units; ++u) {
    const LevelStats s = unit_stats(u);
    out[0].accesses += s.accesses;
    out[0].misses += s.misses;
    out[0].line_misses += s.line_misses;
    out[0].bytes_requested += s.bytes_requested;
    out[0].bytes_fetched += s.bytes_fetched;
    out[0].invalidations += s.invalidations;
  }
  for (std::size_t k = 1; k < config_.levels.size(); ++k) {
    const SectoredCache& c = lower_[k - 1];
    LevelStats& s = out[k];
    s.accesses = c.accesses();
    s.misses = c.misses();
    s.line_misses = c.line_misses();
    s.bytes_requested = lower_requested_[k - 1];
    s.bytes_fetched = c.bytes_fetched();
    s.invalidations = lower_invalidated_[k - 1];
  }
  return out;
}

std::string describe(const HierarchyConfig& config) {
  std::string out;
  for (std::size_t k = 0; k < config.levels.size(); ++k) {
    const CacheLevelSpec& level = config.levels[k];
    out += (k ? " | L" : "L") + std::to_string(k + 1) + (k == 0 && config.decoded_l1 ? " decoded " : " ") +
           describe(level.cache);
    if (level.sector_bytes && level.sector_bytes != level.cache.line_bytes)
      out += " sector " + format_byte_size(level.sector_bytes);
    if (k == 0 && config.units > 1)
      out += " x" + std::to_string(config.units) + " units (" + std::to_string(config.tile) + "px tiles)";
  }
  if (config.levels.size() > 1) out += " | " + std::string(to_string(config.inclusion));
  return out;
}

}  // namespace rastrace
