// The geometry and policy of a byte-addressed cache (texture memory, vertex buffers, din traces),
// and the statistics every model reports.
//   size_bytes   capacity, a multiple of line_bytes * ways
//   line_bytes   power of two
//   assoc        ways per set: 1 = direct mapped, 0 = fully associative
//   policy       fifo, lru, random (seeded, deterministic), opt (Belady's MIN: offline lower bound)
// Statistics follow Dinero IV: the compulsory / capacity / conflict split of its -ccc option, where
// compulsory misses are first references to a line, capacity misses are the misses of a fully
// associative LRU cache of the same capacity minus the compulsory ones, conflict misses are the
// rest (negative when a policy beats fully associative LRU, as Dinero also reports).
#pragma once

#include <cstdint>
#include <string>

namespace rastrace {

enum class ReplacementPolicy : std::uint8_t { Fifo, Lru, Random, Opt };

const char* to_string(ReplacementPolicy policy);
// "fifo", "lru", "random", "opt"; throws InputError otherwise.
ReplacementPolicy parse_replacement_policy(const std::string& text);

struct CacheConfig {
  std::uint64_t size_bytes = 16 * 1024;
  std::uint32_t line_bytes = 64;
  std::uint32_t assoc = 4;  // 0 = fully associative
  ReplacementPolicy policy = ReplacementPolicy::Lru;
  std::uint64_t seed = 1;  // random policy only

  std::uint64_t lines() const { return size_bytes / line_bytes; }
  std::uint64_t ways() const { return assoc == 0 ? lines() : assoc; }
  std::uint64_t sets() const { return lines() / ways(); }
};

// Throws InputError unless the geometry is consistent (sizes above 0, line a power of two,
// capacity a whole number of sets, at most 2^31 lines).
void validate(const CacheConfig& config);
// "16KiB/64B/4-way/lru", "1MiB/128B/full/opt".
std::string describe(const CacheConfig& config);

struct CacheStats {
  std::uint64_t accesses = 0;
  std::uint64_t hits = 0;
  std::uint64_t misses = 0;
  std::uint64_t bytes_fetched = 0;  // misses * line size
  // The three Cs (only when computed: has_three_c).
  bool has_three_c = false;
  std::uint64_t compulsory = 0;
  std::int64_t capacity = 0;
  std::int64_t conflict = 0;

  double miss_rate() const { return accesses ? double(misses) / double(accesses) : 0.0; }
  bool operator==(const CacheStats&) const = default;
};

// The pseudo-random victim choice of the random policy: xorshift64*, one draw per eviction from
// a full set, victim way = draw % ways. Same seed, same trace -> same victims.
struct CacheRng {
  std::uint64_t state;
  explicit CacheRng(std::uint64_t seed) : state(seed ? seed : 0x9E3779B97F4A7C15ull) {}
  std::uint64_t next() {
    state ^= state >> 12;
    state ^= state << 25;
    state ^= state >> 27;
    return state * 0x2545F4914F6CDD1Dull;
  }
};

}  // namespace rastrace
