// The reference for sectored caches and cache hierarchies, in the spirit of naive_cache.h: each
// set is a fixed row of way records {valid, line, inserted, used, sectors as a vector<bool>}
// searched front to back, the victim chosen longhand (first invalid way, else oldest use / oldest
// insertion / xorshift64* draw % ways), and the hierarchy written as plain recursion over a vector
// of levels. It shares no code with cache_sim/ and follows only the documented rules of
// sectored_cache.h and cache_hierarchy.h.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rastrace::testing {

struct NaiveLevelStats {
  std::uint64_t accesses = 0, misses = 0, line_misses = 0, bytes_requested = 0, bytes_fetched = 0,
                invalidations = 0;
};

class NaiveSectoredCache {
 public:
  // policy "fifo", "lru" or "random"; assoc 0 = fully associative; sector_bytes 0 = the line.
  NaiveSectoredCache(std::uint64_t size_bytes, std::uint64_t line_bytes, std::uint64_t assoc, std::string policy,
                     std::uint64_t sector_bytes, std::uint64_t seed = 1)
      : line_bytes_(line_bytes),
        sector_bytes_(sector_bytes ? sector_bytes : line_bytes),
        policy_(std::move(policy)),
        rng_(seed ? seed : 0x9E3779B97F4A7C15ull) {
    const std::uint64_t lines = size_bytes / line_bytes;
    ways_ = assoc == 0 ? lines : assoc;
    sets_.assign(lines / ways_, std::vector<Way>(ways_));
    for (auto& set : sets_)
      for (Way& w : set) w.sectors.assign(line_bytes_ / sector_bytes_, false);
  }

  struct Result {
    bool hit = false;
    bool evicted = false;
    std::uint64_t evicted_line = 0;
  };

  Result access(std::uint64_t address) {
    ++time_;
    ++stats.accesses;
    const std::uint64_t line = address / line_bytes_;
    const std::uint64_t sector = (address % line_bytes_) / sector_bytes_;
    std::vector<Way>& set = sets_[line % sets_.size()];
    Result r;
    for (Way& w : set) {
      if (w.valid && w.line == line) {
        if (policy_ == "lru") w.used = time_;
        if (w.sectors[sector]) {
          r.hit = true;
          return r;
        }
        w.sectors[sector] = true;
        ++stats.misses;
        stats.bytes_fetched += sector_bytes_;
        return r;
      }
    }
    ++stats.misses;
    ++stats.line_misses;
    stats.bytes_fetched += sector_bytes_;
    std::size_t victim = set.size();
    for (std::size_t i = 0; i < set.size() && victim == set.size(); ++i)
      if (!set[i].valid) victim = i;
    if (victim == set.size()) {
      victim = 0;
      if (policy_ == "lru") {
        for (std::size_t i = 0; i < set.size(); ++i)
          if (set[i].used < set[victim].used) victim = i;
      } else if (policy_ == "fifo") {
        for (std::size_t i = 0; i < set.size(); ++i)
          if (set[i].inserted < set[victim].inserted) victim = i;
      } else {
        rng_ ^= rng_ >> 12;
        rng_ ^= rng_ << 25;
        rng_ ^= rng_ >> 27;
        victim = static_cast<std::size_t>((rng_ * 0x2545F4914F6CDD1Dull) % ways_);
      }
      r.evicted = true;
      r.evicted_line = set[victim].line;
    }
    Way& w = set[victim];
    w.valid = true;
    w.line = line;
    w.inserted = w.used = time_;
    for (std::size_t s = 0; s < w.sectors.size(); ++s) w.sectors[s] = s == sector;
    return r;
  }

  // Drops every valid line with a byte in [first, first + bytes).
  void invalidate(std::uint64_t first, std::uint64_t bytes) {
    for (auto& set : sets_)
      for (Way& w : set)
        if (w.valid && w.line * line_bytes_ < first + bytes && (w.line + 1) * line_bytes_ > first) {
          w.valid = false;
          ++stats.invalidations;
        }
  }

  std::uint64_t line_bytes() const { return line_bytes_; }
  std::uint64_t sector_bytes() const { return sector_bytes_; }
  NaiveLevelStats stats;

 private:
  struct Way {
    bool valid = false;
    std::uint64_t line = 0, inserted = 0, used = 0;
    std::vector<bool> sectors;
  };
  std::uint64_t line_bytes_, sector_bytes_, ways_ = 0, time_ = 0;
  std::string policy_;
  std::uint64_t rng_;
  std::vector<std::vector<Way>> sets_;
};

struct NaiveLevel {
  std::uint64_t size_bytes, line_bytes, assoc;
  std::string policy;
  std::uint64_t sector_bytes = 0;
};

// Level 0 replicated `units` times; accesses are (address, unit) pairs.
class NaiveHierarchy {
 public:
  NaiveHierarchy(const std::vector<NaiveLevel>& levels, std::uint64_t units, bool inclusive,
                 std::uint64_t element_bytes = 4)
      : units_(units), inclusive_(inclusive), element_bytes_(element_bytes) {
    for (std::size_t k = 0; k < levels.size(); ++k) {
      std::vector<NaiveSectoredCache> copies;
      for (std::uint64_t u = 0; u < (k == 0 ? units : 1); ++u)
        copies.emplace_back(levels[k].size_bytes, levels[k].line_bytes, levels[k].assoc, levels[k].policy,
                            levels[k].sector_bytes);
      levels_.push_back(copies);
    }
  }

  void access(std::uint64_t address, std::uint64_t unit) {
    NaiveSectoredCache& l1 = levels_[0][unit];
    l1.stats.bytes_requested += element_bytes_;
    if (l1.access(address).hit) return;
    if (levels_.size() > 1) ask(1, address - address % l1.sector_bytes(), l1.sector_bytes());
  }

  // Per level; level 0 sums its copies.
  std::vector<NaiveLevelStats> stats() const {
    std::vector<NaiveLevelStats> out;
    for (const auto& copies : levels_) {
      NaiveLevelStats sum;
      for (const NaiveSectoredCache& c : copies) {
        sum.accesses += c.stats.accesses;
        sum.misses += c.stats.misses;
        sum.line_misses += c.stats.line_misses;
        sum.bytes_requested += c.stats.bytes_requested;
        sum.bytes_fetched += c.stats.bytes_fetched;
        sum.invalidations += c.stats.invalidations;
      }
      out.push_back(sum);
    }
    return out;
  }

 private:
  void ask(std::size_t k, std::uint64_t first, std::uint64_t bytes) {
    NaiveSectoredCache& c = levels_[k][0];
    c.stats.bytes_requested += bytes;
    const std::uint64_t g = c.sector_bytes();
    for (std::uint64_t a = first - first % g; a < first + bytes; a += g) {
      const NaiveSectoredCache::Result r = c.access(a);
      if (r.hit) continue;
      if (r.evicted && inclusive_)
        for (std::size_t j = 0; j < k; ++j)
          for (NaiveSectoredCache& upper : levels_[j]) upper.invalidate(r.evicted_line * c.line_bytes(), c.line_bytes());
      if (k + 1 < levels_.size()) ask(k + 1, a, g);
    }
  }

  std::uint64_t units_;
  bool inclusive_;
  std::uint64_t element_bytes_;
  std::vector<std::vector<NaiveSectoredCache>> levels_;
};

}  // namespace rastrace::testing
