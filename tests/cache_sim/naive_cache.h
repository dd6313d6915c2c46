// The reference the fast simulators are checked against. Deliberately naive and separate from
// cache_sim/: a set is a std::vector of resident lines searched front to back, every policy is
// written out longhand, OPT looks for each resident line's next use by scanning the rest of the
// trace (quadratic; test-sized traces only). It shares nothing with the fast code except the
// documented random-victim rule (xorshift64*, one draw per eviction from a full set, way = draw % ways).
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace rastrace::testing {

struct NaiveResult {
  std::uint64_t misses = 0;
  std::uint64_t compulsory = 0;
  std::uint64_t fully_associative_lru_misses = 0;
};

// policy: "fifo", "lru", "random", "opt"; assoc 0 = fully associative.
inline std::uint64_t naive_misses(const std::vector<std::uint64_t>& addresses, std::uint64_t size_bytes,
                                  std::uint64_t line_bytes, std::uint64_t assoc, const std::string& policy,
                                  std::uint64_t seed = 1) {
  const std::uint64_t lines = size_bytes / line_bytes;
  const std::uint64_t ways = assoc == 0 ? lines : assoc;
  const std::uint64_t sets = lines / ways;
  struct Way {
    std::uint64_t line;
    std::uint64_t inserted;
    std::uint64_t used;
  };
  std::vector<std::vector<Way>> cache(sets);
  std::uint64_t rng = seed ? seed : 0x9E3779B97F4A7C15ull;
  std::uint64_t misses = 0;
  for (std::size_t t = 0; t < addresses.size(); ++t) {
    const std::uint64_t line = addresses[t] / line_bytes;
    std::vector<Way>& set = cache[line % sets];
    bool hit = false;
    for (Way& w : set) {
      if (w.line == line) {
        hit = true;
        w.used = t;
      }
    }
    if (hit) continue;
    ++misses;
    if (set.size() < ways) {
      set.push_back({line, t, t});
      continue;
    }
    std::size_t victim = 0;
    if (policy == "lru") {
      for (std::size_t i = 0; i < set.size(); ++i)
        if (set[i].used < set[victim].used) victim = i;
    } else if (policy == "fifo") {
      for (std::size_t i = 0; i < set.size(); ++i)
        if (set[i].inserted < set[victim].inserted) victim = i;
    } else if (policy == "random") {
      rng ^= rng >> 12;
      rng ^= rng << 25;
      rng ^= rng >> 27;
      victim = static_cast<std::size_t>((rng * 0x2545F4914F6CDD1Dull) % ways);
    } else {  // opt: farthest next use; never used again is farthest of all
      std::uint64_t farthest = 0;
      for (std::size_t i = 0; i < set.size(); ++i) {
        std::uint64_t next = addresses.size() + 1;
        for (std::size_t u = t + 1; u < addresses.size(); ++u)
          if (addresses[u] / line_bytes == set[i].line) {
            next = u;
            break;
          }
        if (next > farthest) {
          farthest = next;
          victim = i;
        }
      }
    }
    set[victim] = {line, t, t};
  }
  return misses;
}

inline std::uint64_t naive_compulsory(const std::vector<std::uint64_t>& addresses, std::uint64_t line_bytes) {
  std::set<std::uint64_t> seen;
  for (const std::uint64_t a : addresses) seen.insert(a / line_bytes);
  return seen.size();
}

}  // namespace rastrace::testing
