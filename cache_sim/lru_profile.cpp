#include "cache_sim/lru_profile.h"

#include <algorithm>
#include <numeric>

#include "core/error.h"
#include "core/function_clones.h"

namespace rastrace {

namespace {
constexpr std::uint64_t kMinTree = 1 << 16;
}

LruStackProfile::LruStackProfile() : map_(1024) { rebuild(0); }

void LruStackProfile::rebuild(std::uint64_t live) {
  // Times 0..live-1 live, room for at least as many new accesses.
  tree_size_ = std::max<std::uint64_t>(kMinTree, (2 * live + kBlockBits - 1) / kBlockBits * kBlockBits);
  words_.assign(tree_size_ / 64, 0);
  for (std::uint64_t t = 0; t < live; ++t) words_[t / 64] |= std::uint64_t{1} << (t % 64);
  const std::uint64_t block_count = tree_size_ / kBlockBits;
  blocks_.assign(block_count + 1, 0);
  for (std::uint64_t b = 0; b < block_count; ++b)
    for (std::uint64_t w = 0; w < kWordsPerBlock; ++w)
      blocks_[b + 1] += static_cast<std::int32_t>(std::popcount(words_[b * kWordsPerBlock + w]));
  // Linear-time Fenwick build from the raw counts.
  for (std::uint64_t i = 1; i <= block_count; ++i) {
    const std::uint64_t parent = i + (i & (~i + 1));
    if (parent <= block_count) blocks_[parent] += blocks_[i];
  }
  id_at_time_.resize(tree_size_);
  live_ = live;
  now_ = live;
}

void LruStackProfile::compact() {
  // Renumber the live last-use times 0..live-1 in order, keeping the relative order (which is all
  // the distances depend on): the live bits, read in time order, name the ids in that order.
  std::uint64_t next = 0;
  for (std::uint64_t w = 0; w < words_.size(); ++w)
    for (std::uint64_t bits = words_[w]; bits != 0; bits &= bits - 1) {
      const std::uint32_t id = id_at_time_[w * 64 + static_cast<std::uint64_t>(std::countr_zero(bits))];
      last_use_[id] = next;
      id_at_time_[next++] = id;  // next <= the time being read: nothing unread is overwritten
    }
  rebuild(next);
}

RASTRACE_CLONES("popcnt", "default")
void LruStackProfile::access_lines(std::span<const std::uint64_t> lines) {
  for (const std::uint64_t line : lines) access(line);
}

void LruStackProfile::forget(std::uint64_t line) {
  const std::uint32_t id = find_line(line);
  if (id == LineMap::kMissing) return;
  erase_line(line);
  set_bit(last_use_[id], false);
  last_use_[id] = kDead;
  free_ids_.push_back(id);
  if (line == last_line_) has_last_ = false;
}

std::uint64_t LruStackProfile::misses(std::uint64_t lines) const {
  std::uint64_t misses = compulsory_;
  for (std::uint64_t d = lines; d < histogram_.size(); ++d) misses += histogram_[d];
  return misses;
}

SetAssocLruProfile::SetAssocLruProfile(std::uint64_t sets, std::uint32_t max_ways) : sets_(sets), max_ways_(max_ways) {
  if (sets == 0 || max_ways == 0 || max_ways > 1024)
    throw InputError("set-associative profile: expected at least 1 set and 1..1024 ways");
  stacks_.assign(sets * max_ways, ~std::uint64_t{0});
  depth_hits_.assign(max_ways, 0);
}

void SetAssocLruProfile::access(std::uint64_t line) {
  ++accesses_;
  std::uint64_t* stack = stacks_.data() + (line % sets_) * max_ways_;
  std::uint32_t depth = 0;
  while (depth < max_ways_ && stack[depth] != line) ++depth;
  if (depth < max_ways_)
    ++depth_hits_[depth];
  else
    depth = max_ways_ - 1;  // a miss for every associativity: the deepest line falls off
  for (std::uint32_t i = depth; i > 0; --i) stack[i] = stack[i - 1];
  stack[0] = line;
}

std::uint64_t SetAssocLruProfile::misses(std::uint32_t ways) const {
  if (ways == 0 || ways > max_ways_)
    throw InputError("set-associative profile: " + std::to_string(ways) + " ways outside 1.." +
                     std::to_string(max_ways_));
  return accesses_ - std::accumulate(depth_hits_.begin(), depth_hits_.begin() + ways, std::uint64_t{0});
}

}  // namespace rastrace
