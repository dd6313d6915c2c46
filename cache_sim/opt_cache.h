// Belady's OPT (MIN, Belady 1966): on a miss in a full set, evict the resident line whose next
// use lies farthest in the future. Demand fetch, no bypass: the missing line is always inserted,
// which makes OPT the lower bound of every demand policy here (OPT <= LRU, FIFO, random).
// Offline: it needs the next-use time of every access, computed in one backward pass. The line
// stream and its next-use times are held in memory, 16 bytes per access; callers that stream
// traces (sweep, replay, LiveBankSink) refuse OPT above kOptMaxAccesses accesses (256 Mi, 4 GiB).
#pragma once

#include <cstdint>
#include <span>

#include "cache_sim/cache_config.h"

namespace rastrace {

inline constexpr std::uint64_t kOptMaxAccesses = std::uint64_t{1} << 28;
inline constexpr std::uint64_t kOptBytesPerAccess = 16;

// Throws InputError when OPT would have to hold more than `limit` accesses, stating the limit in
// accesses and bytes; callers check before they read the trace when they know its length.
void check_opt_capacity(std::uint64_t accesses, std::uint64_t limit = kOptMaxAccesses);

// Simulates OPT (config.policy is ignored) over line numbers (address >> log2(line size)).
CacheStats simulate_opt(const CacheConfig& config, std::span<const std::uint64_t> lines);

}  // namespace rastrace
