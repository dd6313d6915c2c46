// Sampled miss-ratio curves: spatially hashed sampling of cache lines.
//
// SHARDS (Waldspurger, Park, Garthwaite, Ahmad, "Efficient MRC Construction with SHARDS",
// FAST 2015): a line is sampled when hash(line) < T, so either every access to a line is seen or
// none is, at rate R = T / 2^64. LRU stack distances measured among the sampled lines, divided by
// R, estimate the distances of the full trace; a cache of C lines is estimated from the sampled
// accesses at distance >= C * R. Two variants:
//   fixed rate   R stays; the curve is normalised by the expected number of sampled accesses
//                N * R rather than the number seen (the paper's SHARDS_adj correction), which
//                removes the bias of a hot line that happens to be (or not to be) sampled;
//   fixed size   at most `max_lines` sampled lines are tracked: when one more would be, the line
//                of highest hash leaves the stack and T drops to its hash; the counts gathered so
//                far are rescaled by the new rate over the old (memory stays constant).
//
// Miniature simulation (Waldspurger, Saemundsson, Ahmad, Park, "Cache Modeling and Optimization
// using Miniature Simulations", USENIX ATC 2017): for policies without a stack property (FIFO,
// random) and for set-associative caches, the sampled lines are run through the same cache scaled
// by R (R times the sets, the same ways; R times the lines when fully associative). Its miss ratio
// estimates the full cache's.
//
// Each estimator also keeps kSampleParts part samples (the sampled lines split by the low bits of
// their hash, independent of the threshold), each a complete estimate at rate R / kSampleParts,
// from which it states its error (stated_error below): a 99% confidence interval from the parts'
// spread for the sampling noise, and how far the full estimate moved from their mean for the bias
// of a scaled cache that holds few sampled lines. Two halves and their spread alone were the error
// stated before: it does not see the bias, and one pair of halves is a statistic of one degree of
// freedom that about 30% of rows exceed (docs/RELIABILITY.md, "Sampled estimates state their true
// error").
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "cache_sim/byte_cache.h"
#include "cache_sim/cache_config.h"
#include "cache_sim/lru_profile.h"

namespace rastrace {

struct SampleSpec {
  double rate = 0.01;           // 0 < rate <= 1: the fraction of lines sampled (the start rate, fixed size)
  std::uint64_t max_lines = 0;  // 0: fixed rate; otherwise fixed size with at most this many lines
};
// "0.01" or "1%" (fixed rate), "0.01,max=8192" or "1%,max=8192" (fixed size); throws InputError
// naming `option` otherwise.
SampleSpec parse_sample_spec(const std::string& text, const std::string& option);
std::string describe(const SampleSpec& spec);

// The spatial hash: a bijective 64-bit mix of the line number (splitmix64's finaliser).
inline std::uint64_t sample_hash(std::uint64_t line) {
  line ^= line >> 30;
  line *= 0xbf58476d1ce4e5b9ull;
  line ^= line >> 27;
  line *= 0x94d049bb133111ebull;
  return line ^ (line >> 31);
}
// The threshold of a rate: sampled when sample_hash(line) < threshold, or every line at rate 1.
std::uint64_t sample_threshold(double rate);

// The part samples every estimator keeps beside its full sample (a power of two: a part is the
// low bits of a line's hash).
inline constexpr int kSampleParts = 8;

// The error an estimate states from its full sample (rate R) and its kSampleParts parts (rate
// R / K each, independent samples of the lines):
//   noise  t * s / sqrt(K), s the parts' standard deviation and t Student's 99.5% quantile for
//          K - 1 degrees of freedom (3.499 for K = 8): the full estimate's noise at 99%
//          confidence, two-sided;
//   bias   |full - mean(parts)|: the bias of a scaled cache shrinks about as 1 / (C * R), so the
//          parts' bias is K times the full sample's, and the shift from their mean to the full
//          estimate is K - 1 times it; stated whole, not divided by K - 1, for a margin.
// Their sum.
double stated_error(double full, std::span<const double, kSampleParts> parts);

// The accesses of one batch that a rate samples, with their hashes: the filter runs once per batch
// however many estimators of that rate follow (a sweep feeds a ShardsProfile and the
// MiniSimulations of the same lines), and at 1% they see 1% of the accesses.
class SampledBatch {
 public:
  explicit SampledBatch(double rate);
  // Keeps the lines of `lines` the rate samples, in order (replaces the previous batch).
  void sample(std::span<const std::uint64_t> lines);

  double rate() const { return rate_; }
  std::uint64_t accesses() const { return accesses_; }  // all of the batch's, sampled or not
  std::span<const std::uint64_t> lines() const { return {lines_.data(), count_}; }
  std::span<const std::uint64_t> hashes() const { return {hashes_.data(), count_}; }

 private:
  double rate_;
  std::uint64_t threshold_;
  bool all_;
  std::uint64_t accesses_ = 0;
  std::size_t count_ = 0;
  // Sized to the largest batch seen and never shrunk: the filter writes every line and advances
  // past the sampled ones (no branch to mispredict, no zero-filling per batch).
  std::vector<std::uint64_t> lines_, hashes_;
};

// SHARDS: the LRU miss ratio of every fully associative size, from one sampled pass.
class ShardsProfile {
 public:
  explicit ShardsProfile(SampleSpec spec);
  ~ShardsProfile();
  void access_lines(std::span<const std::uint64_t> lines);
  // The same for a batch already sampled at a rate of at least this profile's (start) rate;
  // throws std::invalid_argument otherwise.
  void access_sampled(const SampledBatch& batch);

  std::uint64_t accesses() const { return accesses_; }      // all, sampled or not
  double rate() const;                                      // the final rate
  double sampled_accesses() const;                          // rescaled (fixed size)
  double miss_ratio(std::uint64_t cache_lines) const;       // estimated, fully associative LRU
  double expected_error(std::uint64_t cache_lines) const;   // stated_error() of the full and part samples
  double part_miss_ratio(int part, std::uint64_t cache_lines) const;  // part 0 .. kSampleParts - 1
  std::uint64_t tracked_lines() const;

 private:
  struct Estimate;
  SampleSpec spec_;
  std::uint64_t accesses_ = 0;
  std::unique_ptr<Estimate> full_, part_[kSampleParts];
  std::unique_ptr<SampledBatch> batch_;  // access_lines()'s
};

// Miniature simulations of byte caches of any policy and geometry over one sampled line stream
// (fixed rate only).
class MiniSimulations {
 public:
  // Throws InputError on an invalid cache.
  MiniSimulations(const std::vector<CacheConfig>& caches, double rate);
  ~MiniSimulations();
  void access_lines(std::span<const std::uint64_t> lines);
  // The same for a batch already sampled at a rate of at least this one's; throws
  // std::invalid_argument otherwise.
  void access_sampled(const SampledBatch& batch);

  std::uint64_t accesses() const { return accesses_; }
  double miss_ratio(std::size_t cache) const;
  double expected_error(std::size_t cache) const;  // stated_error() of the full and part samples
  double part_miss_ratio(std::size_t cache, int part) const;  // part 0 .. kSampleParts - 1
  // The scaled cache that stands for cache i ("16KiB/64B/4-way/lru" -> "160B/64B/...").
  const CacheConfig& scaled(std::size_t cache) const;

 private:
  struct Mini;
  double rate_;
  std::uint64_t threshold_;
  std::uint64_t accesses_ = 0;
  std::vector<Mini> minis_;
  std::vector<std::uint64_t> sampled_[1 + kSampleParts];  // this batch's sampled lines: all, then each part
  std::unique_ptr<SampledBatch> batch_;    // access_lines()'s
};

// The cache of the same policy and ways scaled to `rate`: sets * rate sets (full: lines * rate
// lines), at least one set (one line).
CacheConfig scale_cache(const CacheConfig& config, double rate);

}  // namespace rastrace
