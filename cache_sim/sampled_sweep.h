// `sweep --sample`: the rows of a sweep estimated from spatially hashed samples of the cache lines
// (shards.h) in one pass over the trace: fully associative LRU rows from one SHARDS profile per
// (layout, line size), every other row (FIFO, random, set-associative LRU) from its miniature
// simulation. Each row gets its estimated miss count and the expected error of its miss rate.
#pragma once

#include <string>
#include <vector>

#include "cache_sim/shards.h"
#include "cache_sim/sweep.h"

namespace rastrace {

// Fills rows[i].stats (accesses exact; hits, misses and bytes estimated, no three-C split) and
// rows[i].expected_error; rows[i].layout_index says which of `layouts` the row uses (texel source).
// Throws InputError for OPT rows, and for fixed-size sampling with rows that need a
// miniature simulation (fixed rate only).
void run_sampled_rows(const std::string& trace_path, const SweepSpec& spec, const std::vector<LayoutSpec>& layouts,
                      const TextureLevels& textures, SweepRows& rows, bool progress);

}  // namespace rastrace
