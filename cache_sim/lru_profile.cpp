#include "cache_sim/lru_profile.h"

#include <algorithm>
#include <numeric>

#include "core/error.h"

namespace rastrace {

namespace {
constexpr std::uint64_t kMinTree = 1 << 16;
}

LruStackProfile::LruStackProfile() : map_(1024), tree_(kMinTree + 1, 0), tree_size_(kMinTree) {}

void LruStackProfile::compact() {
  // Renumber the live last-use times 0..live-1 in order, keeping the relative order (which is all
  // the distances depend on), and leave room for at least as many new accesses.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> order;
  order.reserve(last_use_.size());
  for (std::uint32_t id = 0; id < last_use_.size(); ++id) order.emplace_back(last_use_[id], id);
  std::sort(order.begin(), order.end());
  tree_size_ = std::max<std::uint64_t>(kMinTree, 2 * order.size());
  tree_.assign(tree_size_ + 1, 0);
  for (std::uint64_t t = 0; t < order.size(); ++t) {
    last_use_[order[t].second] = t;
    tree_[t + 1] = 1;
  }
  // Linear-time Fenwick build from the raw counts.
  for (std::uint64_t i = 1; i <= tree_size_; ++i) {
    const std::uint64_t parent = i + (i & (~i + 1));
    if (parent <= tree_size_) tree_[parent] += tree_[i];
  }
  now_ = order.size();
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
