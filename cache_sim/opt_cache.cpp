#include "cache_sim/opt_cache.h"

#include <algorithm>
#include <bit>
#include <vector>

#include "cache_sim/line_map.h"
#include "core/error.h"
#include "core/input_guard.h"
#include "core/units.h"

namespace rastrace {

void check_opt_capacity(std::uint64_t accesses, std::uint64_t limit) {
  if (accesses <= limit) return;
  throw InputError("opt: " + std::to_string(accesses) + " accesses, more than the " + std::to_string(limit) +
                   " OPT holds in memory (" + std::to_string(kOptBytesPerAccess) + " bytes each, " +
                   format_byte_size(limit * kOptBytesPerAccess) +
                   "); drop opt, shorten the trace, or use --sample for the other policies");
}

CacheStats simulate_opt(const CacheConfig& config, std::span<const std::uint64_t> lines) {
  validate(config);
  const std::uint64_t n = lines.size();
  // next[i]: position of the next access to lines[i]; a line never used again gets a distinct
  // value above every position so that keys stay unique (needed by the lazy heaps below).
  std::vector<std::uint64_t> next(n);
  std::uint64_t positions_seen = 0;  // distinct lines in the trace
  {
    LineMap last(1024);
    std::vector<std::uint64_t> positions;
    for (std::uint64_t i = n; i-- > 0;) {
      bool inserted;
      std::uint32_t& index = last.find_or_insert(lines[i], static_cast<std::uint32_t>(positions.size()), inserted);
      if (inserted) {
        positions.push_back(i);
        next[i] = n + i + 1;  // never again
      } else {
        next[i] = positions[index];
        positions[index] = i;
      }
    }
    positions_seen = positions.size();
  }

  const std::uint64_t sets = config.sets();
  // A fully associative OPT cache holding every distinct line never evicts: more ways than
  // distinct lines change nothing but the memory (1 GiB of 1-byte lines would need 40 GiB).
  const std::uint64_t ways =
      sets == 1 ? std::max<std::uint64_t>(1, std::min<std::uint64_t>(config.ways(), positions_seen)) : config.ways();
  checked_bytes(sets * ways, 40, "cache " + describe(config) + ": OPT simulator state");
  const bool pow2 = std::has_single_bit(sets);
  const bool scan = ways <= 16;
  std::vector<std::uint64_t> slot_line(sets * ways), slot_next(sets * ways);
  std::vector<std::uint32_t> filled(sets, 0);
  std::vector<std::vector<std::pair<std::uint64_t, std::uint32_t>>> heaps(scan ? 0 : sets);
  LineMap resident(sets * ways);

  CacheStats stats;
  stats.accesses = n;
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::uint64_t line = lines[i];
    const std::uint64_t set = pow2 ? (line & (sets - 1)) : line % sets;
    const std::uint32_t found = resident.find(line);
    std::uint32_t slot;
    if (found != LineMap::kMissing) {
      slot = found;
    } else {
      ++stats.misses;
      if (filled[set] < ways) {
        slot = static_cast<std::uint32_t>(set * ways + filled[set]++);
      } else {
        if (scan) {
          slot = static_cast<std::uint32_t>(set * ways);
          for (std::uint64_t w = 1; w < ways; ++w)
            if (slot_next[set * ways + w] > slot_next[slot]) slot = static_cast<std::uint32_t>(set * ways + w);
        } else {
          auto& heap = heaps[set];
          while (true) {
            std::pop_heap(heap.begin(), heap.end());
            const auto top = heap.back();
            heap.pop_back();
            if (slot_next[top.second] == top.first) {
              slot = top.second;
              break;
            }
          }
        }
        resident.erase(slot_line[slot]);
      }
      slot_line[slot] = line;
      resident.insert(line, slot);
    }
    slot_next[slot] = next[i];
    if (!scan) {
      auto& heap = heaps[set];
      heap.emplace_back(next[i], slot);
      std::push_heap(heap.begin(), heap.end());
      if (heap.size() > 4 * ways + 64) {
        // Drop the stale entries left by hits.
        heap.clear();
        for (std::uint32_t w = 0; w < filled[set]; ++w) {
          const std::uint32_t s = static_cast<std::uint32_t>(set * ways + w);
          heap.emplace_back(slot_next[s], s);
        }
        std::make_heap(heap.begin(), heap.end());
      }
    }
  }
  stats.hits = stats.accesses - stats.misses;
  stats.bytes_fetched = stats.misses * config.line_bytes;
  return stats;
}

}  // namespace rastrace
