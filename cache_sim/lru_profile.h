// One-pass LRU profiles (Mattson, Gecsei, Slutz, Traiger 1970: the stack property of LRU).
//
// LruStackProfile: fully associative LRU, every capacity at once. For each access it finds the
// stack distance d = number of distinct lines used since the previous access to the same line;
// a cache of C lines hits exactly when d < C. Distances come from a Fenwick tree over last-use
// times (one bit per line at its last use): d = live lines used after the previous use, O(log n).
// The time axis is renumbered when it fills, so memory stays O(distinct lines) however long the
// trace. misses(C) equals a per-size LRU simulation exactly; compulsory() counts first references.
//
// SetAssocLruProfile: a fixed number of sets, every associativity 1..max_ways at once: each set
// keeps its lines in recency order (max_ways deep); a hit at depth p hits every cache with more
// than p ways.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cache_sim/line_map.h"

namespace rastrace {

class LruStackProfile {
 public:
  LruStackProfile();
  void access(std::uint64_t line) {
    ++accesses_;
    // Re-touching the most recent line (distance 0, most texel accesses) changes no stack order:
    // count it and leave the tree alone.
    if (line == last_line_ && accesses_ > 1) {
      ++histogram_[0];
      return;
    }
    last_line_ = line;
    bool inserted;
    std::uint32_t& id = map_.find_or_insert(line, static_cast<std::uint32_t>(last_use_.size()), inserted);
    if (inserted) {
      ++compulsory_;
      last_use_.push_back(now_);
    } else {
      const std::uint64_t last = last_use_[id];
      // Lines whose last use is after `last`: all live bits minus those at or before it.
      const std::uint64_t distance = live_ - prefix(last);
      add(last, -1);
      --live_;
      if (distance >= histogram_.size()) histogram_.resize(distance + 1, 0);
      ++histogram_[distance];
      last_use_[id] = now_;
    }
    add(now_, +1);
    ++live_;
    if (++now_ == tree_size_) compact();
  }
  void access_lines(std::span<const std::uint64_t> lines) {
    for (const std::uint64_t line : lines) access(line);
  }

  std::uint64_t accesses() const { return accesses_; }
  std::uint64_t compulsory() const { return compulsory_; }
  std::uint64_t distinct_lines() const { return compulsory_; }
  // Misses of a fully associative LRU cache holding `lines` lines.
  std::uint64_t misses(std::uint64_t lines) const;
  // histogram()[d]: accesses at stack distance d (re-references only).
  const std::vector<std::uint64_t>& histogram() const { return histogram_; }

 private:
  // Fenwick tree over times 0..tree_size_-1 (1-based inside).
  std::uint64_t prefix(std::uint64_t time) const {  // bits at times <= time
    std::uint64_t sum = 0;
    for (std::uint64_t i = time + 1; i > 0; i &= i - 1) sum += tree_[i];
    return sum;
  }
  void add(std::uint64_t time, std::int32_t delta) {
    for (std::uint64_t i = time + 1; i <= tree_size_; i += i & (~i + 1)) tree_[i] += delta;
  }
  void compact();

  LineMap map_;                          // line -> id
  std::vector<std::uint64_t> last_use_;  // per id
  std::vector<std::int32_t> tree_;
  std::uint64_t tree_size_ = 0;
  std::uint64_t now_ = 0;
  std::uint64_t live_ = 0;
  std::uint64_t accesses_ = 0;
  std::uint64_t compulsory_ = 0;
  std::vector<std::uint64_t> histogram_ = std::vector<std::uint64_t>(1, 0);
  std::uint64_t last_line_ = 0;
};

class SetAssocLruProfile {
 public:
  // sets >= 1, 1 <= max_ways <= 1024.
  SetAssocLruProfile(std::uint64_t sets, std::uint32_t max_ways);
  void access(std::uint64_t line);
  void access_lines(std::span<const std::uint64_t> lines) {
    for (const std::uint64_t line : lines) access(line);
  }
  std::uint64_t accesses() const { return accesses_; }
  // Misses of the LRU cache with this many sets and `ways` ways (1..max_ways).
  std::uint64_t misses(std::uint32_t ways) const;

 private:
  std::uint64_t sets_;
  std::uint32_t max_ways_;
  std::uint64_t accesses_ = 0;
  std::vector<std::uint64_t> stacks_;      // per set, max_ways lines, most recent first (~0 = empty)
  std::vector<std::uint64_t> depth_hits_;  // hits at each depth
};

}  // namespace rastrace
