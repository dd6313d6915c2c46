// `sweep --sample`: the rows of a sweep estimated from spatially hashed samples of the cache lines
// (shards.h) in one pass over the trace: fully associative LRU rows from one SHARDS profile per
// (layout, line size), every other row (FIFO, random, set-associative LRU) from its miniature
// simulation. Each row gets its estimated miss count and the error of its miss rate; rows a
// sample would estimate with a bias it cannot state (SampleGuards, sweep.h) are left to the exact
// simulation.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cache_sim/shards.h"
#include "cache_sim/sweep.h"

namespace rastrace {

// Fills rows[i].stats (accesses exact; hits, misses and bytes estimated, no three-C split),
// rows[i].sampled_as and rows[i].expected_error for the rows the sample may estimate, and returns
// the indices of the others, which the caller simulates exactly (their sampled_as is "exact",
// their expected_error 0): every row when `records` (the source's records in the trace, 0 when
// unknown) times `configurations` (the whole sweep's, every shard's: a shard decides as the
// unsharded sweep does) is at most spec.sample_guards.exact_accesses (the trace is not read then),
// otherwise the rows whose cache scaled to the sample's final rate holds fewer than
// spec.sample_guards.min_sampled_lines lines and the set-associative rows of fewer than
// spec.sample_guards.min_sampled_assoc ways. rows[i].layout_index says which of `layouts` the
// row uses (texel source). Throws InputError for OPT rows, and for fixed-size sampling with rows
// that need a miniature simulation (fixed rate only).
std::vector<std::size_t> run_sampled_rows(const std::string& trace_path, const SweepSpec& spec,
                                          const std::vector<LayoutSpec>& layouts, const TextureLevels& textures,
                                          std::uint64_t records, std::size_t configurations, SweepRows& rows,
                                          bool progress);

}  // namespace rastrace
