// One-pass LRU profiles (Mattson, Gecsei, Slutz, Traiger 1970: the stack property of LRU).
//
// LruStackProfile: fully associative LRU, every capacity at once. For each access it finds the
// stack distance d = number of distinct lines used since the previous access to the same line;
// a cache of C lines hits exactly when d < C (Bennett and Kruskal 1975). The time axis holds one
// bit per line at its last use, and d = live bits after the line's previous use. The bits sit in
// 64-bit words, the words in 512-bit blocks with a count each, and a Fenwick tree over the block
// counts sums whole blocks: a query is a few popcounts and a walk of log2(blocks) steps over a tree
// that fits in L1 (a Fenwick tree over single times needed three walks of log2(times) steps over
// a tree 128 times larger). The time axis is renumbered when it fills, so memory stays
// O(distinct lines) however long the trace. misses(C) equals a per-size LRU simulation exactly;
// compulsory() counts first references.
//
// SetAssocLruProfile: a fixed number of sets, every associativity 1..max_ways at once: each set
// keeps its lines in recency order (max_ways deep); a hit at depth p hits every cache with more
// than p ways.
#pragma once

#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#include "cache_sim/line_map.h"

namespace rastrace {

class LruStackProfile {
 public:
  static constexpr std::uint64_t kFirstUse = ~std::uint64_t{0};

  LruStackProfile();
  void access(std::uint64_t line) {
    ++accesses_;
    const std::uint64_t distance = touch(line);
    if (distance == kFirstUse) {
      ++compulsory_;
      return;
    }
    if (distance >= histogram_.size()) [[unlikely]]
      histogram_.resize(distance + 1, 0);
    ++histogram_[distance];
  }
  // access() for each line; compiled with the POPCNT instruction where the CPU has it.
  void access_lines(std::span<const std::uint64_t> lines);

  // Moves `line` to the top of the stack and returns its stack distance (kFirstUse when the line
  // is not in the stack), without counting it in accesses() or the histogram: for callers that
  // keep their own (sampled, weighted) histogram.
  std::uint64_t touch(std::uint64_t line) {
    // Re-touching the most recent line (distance 0, most texel accesses) changes no stack order.
    if (line == last_line_ && has_last_) return 0;
    last_line_ = line;
    has_last_ = true;
    bool inserted;
    const std::uint32_t fresh = free_ids_.empty() ? static_cast<std::uint32_t>(last_use_.size()) : free_ids_.back();
    const std::uint32_t id = find_or_insert(line, fresh, inserted);
    std::uint64_t distance = kFirstUse;
    if (inserted) {
      if (free_ids_.empty())
        last_use_.push_back(now_);
      else
        free_ids_.pop_back();
    } else {
      const std::uint64_t last = last_use_[id];
      distance = live_after(last);
      set_bit(last, false);
    }
    last_use_[id] = now_;
    id_at_time_[now_] = id;
    set_bit(now_, true);
    if (++now_ == tree_size_) compact();
    return distance;
  }
  // Takes `line` out of the stack (a sampler that stops tracking it); nothing if it is not there.
  void forget(std::uint64_t line);
  // Lines in the stack.
  std::uint64_t live_lines() const { return live_; }

  std::uint64_t accesses() const { return accesses_; }
  std::uint64_t compulsory() const { return compulsory_; }
  std::uint64_t distinct_lines() const { return compulsory_; }
  // Misses of a fully associative LRU cache holding `lines` lines.
  std::uint64_t misses(std::uint64_t lines) const;
  // histogram()[d]: accesses at stack distance d (re-references only).
  const std::vector<std::uint64_t>& histogram() const { return histogram_; }

 private:
  static constexpr std::uint64_t kDead = ~std::uint64_t{0};  // last_use_ of a forgotten id
  // Lines below kDenseLines (texture memory up to 256 MiB at 64-byte lines) are looked up in a
  // flat array, which grows to the largest such line seen; the others in the hash map.
  static constexpr std::uint64_t kDenseLines = std::uint64_t{1} << 22;
  std::uint32_t find_or_insert(std::uint64_t line, std::uint32_t fresh, bool& inserted) {
    if (line >= kDenseLines) return map_.find_or_insert(line, fresh, inserted);
    if (line >= dense_.size()) [[unlikely]]
      dense_.resize(std::max<std::size_t>(std::bit_ceil(line + 1), 1024), 0);
    std::uint32_t& slot = dense_[line];  // id + 1, 0: none
    inserted = slot == 0;
    if (inserted) slot = fresh + 1;
    return slot - 1;
  }
  void erase_line(std::uint64_t line) {
    if (line >= kDenseLines)
      map_.erase(line);
    else if (line < dense_.size())
      dense_[line] = 0;
  }
  std::uint32_t find_line(std::uint64_t line) const {
    if (line >= kDenseLines) return map_.find(line);
    return line < dense_.size() && dense_[line] ? dense_[line] - 1 : LineMap::kMissing;
  }

  static constexpr std::uint64_t kBlockBits = 512, kWordsPerBlock = kBlockBits / 64;
  // Live bits at times after `time`.
  std::uint64_t live_after(std::uint64_t time) const {
    const std::uint64_t word = time / 64, block = time / kBlockBits;
    std::uint64_t after = static_cast<std::uint64_t>(std::popcount(words_[word] >> (time % 64) >> 1));
    for (std::uint64_t w = word + 1; w < (block + 1) * kWordsPerBlock; ++w)
      after += static_cast<std::uint64_t>(std::popcount(words_[w]));
    std::uint64_t through = 0;  // live bits in blocks 0..block
    for (std::uint64_t i = block + 1; i > 0; i &= i - 1) through += static_cast<std::uint64_t>(blocks_[i]);
    return after + live_ - through;
  }
  void set_bit(std::uint64_t time, bool live) {
    const std::uint64_t bit = std::uint64_t{1} << (time % 64);
    const std::int32_t delta = live ? 1 : -1;
    if (live)
      words_[time / 64] |= bit;
    else
      words_[time / 64] &= ~bit;
    live_ += static_cast<std::uint64_t>(static_cast<std::int64_t>(delta));
    const std::uint64_t block_count = tree_size_ / kBlockBits;
    for (std::uint64_t i = time / kBlockBits + 1; i <= block_count; i += i & (~i + 1)) blocks_[i] += delta;
  }
  void compact();
  void rebuild(std::uint64_t live);

  LineMap map_;                          // line -> id, lines from kDenseLines on
  std::vector<std::uint32_t> dense_;     // line -> id + 1, lines below kDenseLines
  std::vector<std::uint64_t> last_use_;  // per id
  std::vector<std::uint32_t> free_ids_;  // ids of forgotten lines, for reuse
  std::vector<std::uint64_t> words_;   // one bit per time: the line used then has not been used since
  std::vector<std::int32_t> blocks_;   // Fenwick tree over the live bits of each 512-bit block
  std::vector<std::uint32_t> id_at_time_;  // the line id last used at each time (valid where live)
  std::uint64_t tree_size_ = 0;        // times on the axis, a multiple of kBlockBits
  std::uint64_t now_ = 0;
  std::uint64_t live_ = 0;
  std::uint64_t accesses_ = 0;
  std::uint64_t compulsory_ = 0;
  std::vector<std::uint64_t> histogram_ = std::vector<std::uint64_t>(1, 0);
  std::uint64_t last_line_ = 0;
  bool has_last_ = false;
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
