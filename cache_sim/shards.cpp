#include "cache_sim/shards.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <queue>
#include <stdexcept>

#include "core/error.h"
#include "core/function_clones.h"
#include "core/units.h"

namespace rastrace {

namespace {

constexpr double kTwo64 = 18446744073709551616.0;

// Scaled distances of the fixed-size variant in log-linear buckets: exact below 2 * kSub, then
// kSub buckets per octave (relative width 1/kSub), so memory stays constant however small the
// rate gets.
constexpr std::uint64_t kSubBits = 8, kSub = std::uint64_t{1} << kSubBits;
std::size_t bucket_of(std::uint64_t d) {
  if (d < 2 * kSub) return static_cast<std::size_t>(d);
  const unsigned octave = static_cast<unsigned>(std::bit_width(d)) - 1 - kSubBits;  // >= 1
  return static_cast<std::size_t>((octave + 1) * kSub + ((d >> octave) - kSub));
}
// The smallest distance of a bucket.
std::uint64_t bucket_floor(std::size_t b) {
  if (b < 2 * kSub) return b;
  const std::uint64_t octave = b / kSub - 1;
  return (kSub + b % kSub) << octave;
}

}  // namespace

std::uint64_t sample_threshold(double rate) {
  if (rate >= 1.0) return ~std::uint64_t{0};
  return static_cast<std::uint64_t>(std::ldexp(rate, 64));
}

SampledBatch::SampledBatch(double rate) : rate_(rate), threshold_(sample_threshold(rate)), all_(rate >= 1.0) {}

namespace {

// Hashes every line (a loop without dependences between lines, which the AVX-512 clone runs 8
// lines at a time with vpmullq), then keeps the sampled ones in place: each line is written and
// the end advances only past the kept ones, so the rate needs no predicted branch.
RASTRACE_CLONES("arch=x86-64-v4", "default")
std::size_t hash_and_keep(const std::uint64_t* lines, std::size_t n, std::uint64_t threshold, bool all,
                          std::uint64_t* kept, std::uint64_t* hashes) {
  for (std::size_t i = 0; i < n; ++i) hashes[i] = sample_hash(lines[i]);
  if (all) {
    std::copy(lines, lines + n, kept);
    return n;
  }
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t h = hashes[i];  // read before a kept hash may overwrite it (count <= i)
    kept[count] = lines[i];
    hashes[count] = h;
    count += h < threshold;
  }
  return count;
}

}  // namespace

void SampledBatch::sample(std::span<const std::uint64_t> lines) {
  if (lines_.size() < lines.size()) {
    lines_.resize(lines.size());
    hashes_.resize(lines.size());
  }
  accesses_ = lines.size();
  count_ = hash_and_keep(lines.data(), lines.size(), threshold_, all_, lines_.data(), hashes_.data());
}

SampleSpec parse_sample_spec(const std::string& text, const std::string& option) {
  const auto fail = [&] {
    throw InputError(option + " '" + text.substr(0, 40) +
                     "': expected a rate in (0, 1] as a fraction or percentage (0.01, 1%), optionally with a "
                     "fixed size ,max=LINES (e.g. 1%,max=8192)");
  };
  SampleSpec spec;
  std::string rate = text;
  if (const std::size_t comma = text.find(','); comma != std::string::npos) {
    rate = text.substr(0, comma);
    const std::string rest = text.substr(comma + 1);
    if (rest.rfind("max=", 0) != 0) fail();
    try {
      spec.max_lines = parse_count(rest.substr(4));
    } catch (const InputError&) {
      fail();
    }
    if (spec.max_lines < 2) fail();
  }
  const bool percent = !rate.empty() && rate.back() == '%';
  if (percent) rate.pop_back();
  if (rate.empty() || rate.find_first_not_of("0123456789.eE-") != std::string::npos) fail();
  try {
    std::size_t used = 0;
    spec.rate = std::stod(rate, &used) / (percent ? 100.0 : 1.0);
    if (used != rate.size()) fail();
  } catch (const std::logic_error&) {
    fail();
  }
  if (!(spec.rate > 0.0 && spec.rate <= 1.0) || spec.rate * kTwo64 < 4.0) fail();
  return spec;
}

std::string describe(const SampleSpec& spec) {
  char rate[32];
  std::snprintf(rate, sizeof rate, "%g", spec.rate);
  return spec.max_lines ? std::string("fixed size, at most ") + std::to_string(spec.max_lines) +
                              " lines, start rate " + rate
                        : std::string("fixed rate ") + rate;
}

// One SHARDS estimate over the lines whose hash lies in [lo, hi) (and, for a part sample, whose
// hash's low bits are the part's number).
struct ShardsProfile::Estimate {
  std::uint64_t lo, hi;
  bool to_end;  // hi is 2^64 (rate 1)
  int part = -1;  // -1: every line in range; else the part's number
  std::uint64_t max_lines;
  LruStackProfile stack;
  std::priority_queue<std::pair<std::uint64_t, std::uint64_t>> by_hash;  // fixed size: (hash, line)
  std::vector<double> histogram;  // fixed rate: by sampled distance; fixed size: buckets of scaled distance
  double cold = 0, total = 0, scale = 1;

  Estimate(std::uint64_t lo_, std::uint64_t hi_, bool to_end_, std::uint64_t max, int part_ = -1)
      : lo(lo_), hi(hi_), to_end(to_end_), part(part_), max_lines(max) {}

  double rate() const {
    return ((to_end ? kTwo64 : double(hi)) - double(lo)) / kTwo64 / (part < 0 ? 1.0 : double(kSampleParts));
  }
  bool takes(std::uint64_t h) const {
    return h >= lo && (to_end || h < hi) && (part < 0 || int(h & (kSampleParts - 1)) == part);
  }

  void access(std::uint64_t line, std::uint64_t h) {
    if (!takes(h)) return;
    const std::uint64_t d = stack.touch(line);
    if (d == LruStackProfile::kFirstUse && max_lines) {
      by_hash.emplace(h, line);
      if (by_hash.size() > max_lines) {
        const auto [top_hash, top_line] = by_hash.top();
        by_hash.pop();
        stack.forget(top_line);
        const double before = rate();
        hi = top_hash;
        to_end = false;
        scale *= rate() / before;
        if (top_line == line) return;  // its own hash is now above the threshold
      }
    }
    const double weight = 1.0 / scale;
    total += weight;
    if (d == LruStackProfile::kFirstUse) {
      cold += weight;
      return;
    }
    const std::size_t b =
        max_lines ? bucket_of(static_cast<std::uint64_t>(double(d) / rate())) : static_cast<std::size_t>(d);
    if (b >= histogram.size()) histogram.resize(b + 1, 0.0);
    histogram[b] += weight;
  }

  // Estimated misses (in sampled, rescaled units) of a fully associative LRU cache of C lines.
  double misses(std::uint64_t cache_lines) const {
    double misses = cold;
    if (max_lines == 0) {
      // A sampled access at sampled distance d stands for distance d / R: a hit when d < C * R.
      const double limit = double(cache_lines) * rate();
      const std::size_t first = static_cast<std::size_t>(std::ceil(limit));
      for (std::size_t d = first; d < histogram.size(); ++d) misses += histogram[d];
      return misses;
    }
    for (std::size_t b = 0; b < histogram.size(); ++b) {
      const double low = double(bucket_floor(b)), high = double(bucket_floor(b + 1));
      if (low >= double(cache_lines))
        misses += histogram[b];
      else if (high > double(cache_lines))  // the bucket straddles C: its share above C
        misses += histogram[b] * (high - double(cache_lines)) / (high - low);
    }
    return misses;
  }

  double miss_ratio(std::uint64_t cache_lines, std::uint64_t accesses) const {
    // Fixed rate: normalised by the expected sampled accesses (SHARDS_adj); fixed size: by the
    // rescaled total.
    const double denominator = max_lines ? total * scale : double(accesses) * rate();
    if (denominator <= 0) return 0.0;
    const double ratio = misses(cache_lines) * (max_lines ? scale : 1.0) / denominator;
    return std::clamp(ratio, 0.0, 1.0);
  }
};

double stated_error(double full, std::span<const double, kSampleParts> parts) {
  static_assert(kSampleParts == 8, "the quantile below is for 7 degrees of freedom");
  constexpr double kStudent995 = 3.499;  // Student's t, 99.5% quantile, 7 degrees of freedom
  const double k = double(parts.size());
  double mean = 0;
  for (const double p : parts) mean += p;
  mean /= k;
  double squares = 0;
  for (const double p : parts) squares += (p - mean) * (p - mean);
  const double deviation = std::sqrt(squares / (k - 1));
  return kStudent995 * deviation / std::sqrt(k) + std::abs(full - mean);
}

ShardsProfile::ShardsProfile(SampleSpec spec) : spec_(spec) {
  const std::uint64_t threshold = sample_threshold(spec.rate);
  const bool all = spec.rate >= 1.0;
  const std::uint64_t part_max = spec.max_lines ? std::max<std::uint64_t>(1, spec.max_lines / kSampleParts) : 0;
  full_ = std::make_unique<Estimate>(0, threshold, all, spec.max_lines);
  for (int p = 0; p < kSampleParts; ++p) part_[p] = std::make_unique<Estimate>(0, threshold, all, part_max, p);
}

ShardsProfile::~ShardsProfile() = default;

void ShardsProfile::access_lines(std::span<const std::uint64_t> lines) {
  if (!batch_) batch_ = std::make_unique<SampledBatch>(spec_.rate);
  batch_->sample(lines);
  access_sampled(*batch_);
}

void ShardsProfile::access_sampled(const SampledBatch& batch) {
  // The fixed-size variant's rate only falls from spec_.rate: a batch at that rate holds every
  // line the profile can still take.
  if (batch.rate() < spec_.rate)
    throw std::invalid_argument("ShardsProfile: a batch sampled at a lower rate than the profile's");
  accesses_ += batch.accesses();
  const std::span<const std::uint64_t> lines = batch.lines(), hashes = batch.hashes();
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::uint64_t h = hashes[i];
    // Each estimate takes the lines under its own threshold: a fixed size's thresholds fall
    // independently, so a part may still take a line the full sample has dropped.
    part_[h & (kSampleParts - 1)]->access(lines[i], h);
    full_->access(lines[i], h);
  }
}

double ShardsProfile::rate() const { return full_->rate(); }
double ShardsProfile::sampled_accesses() const { return full_->total * full_->scale; }
std::uint64_t ShardsProfile::tracked_lines() const { return full_->stack.live_lines(); }

double ShardsProfile::miss_ratio(std::uint64_t cache_lines) const { return full_->miss_ratio(cache_lines, accesses_); }

double ShardsProfile::part_miss_ratio(int part, std::uint64_t cache_lines) const {
  return part_[part]->miss_ratio(cache_lines, accesses_);
}

double ShardsProfile::expected_error(std::uint64_t cache_lines) const {
  double parts[kSampleParts];
  for (int p = 0; p < kSampleParts; ++p) parts[p] = part_miss_ratio(p, cache_lines);
  return stated_error(miss_ratio(cache_lines), parts);
}

CacheConfig scale_cache(const CacheConfig& config, double rate) {
  CacheConfig scaled = config;
  if (config.assoc == 0) {
    const std::uint64_t lines = std::max<std::uint64_t>(1, std::llround(double(config.lines()) * rate));
    scaled.size_bytes = lines * config.line_bytes;
  } else {
    const std::uint64_t sets = std::max<std::uint64_t>(1, std::llround(double(config.sets()) * rate));
    scaled.size_bytes = sets * config.assoc * config.line_bytes;
  }
  return scaled;
}

struct MiniSimulations::Mini {
  CacheConfig scaled;
  std::unique_ptr<ByteCache> cache[1 + kSampleParts];  // full rate, then each part
};

MiniSimulations::MiniSimulations(const std::vector<CacheConfig>& caches, double rate)
    : rate_(rate), threshold_(sample_threshold(rate)) {
  for (const CacheConfig& config : caches) {
    validate(config);
    if (config.policy == ReplacementPolicy::Opt)
      throw InputError("sampled sweep: opt has no miniature simulation here; drop opt or --sample");
    Mini mini;
    mini.scaled = scale_cache(config, rate);
    mini.cache[0] = std::make_unique<ByteCache>(mini.scaled);
    for (int p = 1; p <= kSampleParts; ++p)
      mini.cache[p] = std::make_unique<ByteCache>(scale_cache(config, rate / kSampleParts));
    minis_.push_back(std::move(mini));
  }
}

MiniSimulations::~MiniSimulations() = default;

void MiniSimulations::access_lines(std::span<const std::uint64_t> lines) {
  if (!batch_) batch_ = std::make_unique<SampledBatch>(rate_);
  batch_->sample(lines);
  access_sampled(*batch_);
}

void MiniSimulations::access_sampled(const SampledBatch& batch) {
  if (batch.rate() < rate_)
    throw std::invalid_argument("MiniSimulations: a batch sampled at a lower rate than the simulations'");
  accesses_ += batch.accesses();
  for (auto& s : sampled_) s.clear();
  const bool all = rate_ >= 1.0;
  const std::span<const std::uint64_t> lines = batch.lines(), hashes = batch.hashes();
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::uint64_t h = hashes[i];
    if (!all && h >= threshold_) continue;
    sampled_[0].push_back(lines[i]);
    sampled_[1 + (h & (kSampleParts - 1))].push_back(lines[i]);
  }
  for (Mini& mini : minis_)
    for (int s = 0; s <= kSampleParts; ++s) mini.cache[s]->access_lines(sampled_[s]);
}

double MiniSimulations::miss_ratio(std::size_t cache) const {
  return minis_[cache].cache[0]->stats().miss_rate();
}

double MiniSimulations::part_miss_ratio(std::size_t cache, int part) const {
  return minis_[cache].cache[1 + part]->stats().miss_rate();
}

double MiniSimulations::expected_error(std::size_t cache) const {
  double parts[kSampleParts];
  for (int p = 0; p < kSampleParts; ++p) parts[p] = part_miss_ratio(cache, p);
  return stated_error(miss_ratio(cache), parts);
}

const CacheConfig& MiniSimulations::scaled(std::size_t cache) const { return minis_[cache].scaled; }

}  // namespace rastrace
