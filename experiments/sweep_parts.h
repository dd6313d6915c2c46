// A sweep split over machines: `sweep --shard K/N -o PART.json` computes the K-th of N disjoint
// parts of the configuration set (cache_sim/sweep.h, SweepShard) and writes it with everything a
// merge must check (the configuration set, the trace's digest, the tool's version, the shard) and
// the full table's title, parameters and columns; `rastrace merge PARTS...` puts the rows back in
// the unsharded order, so the merged table renders byte for byte as the unsharded sweep's in every
// format.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "cache_sim/sweep.h"
#include "core/table.h"

namespace rastrace {

struct SweepPart {
  std::string version;        // of the rastrace that computed it
  std::string trace_digest;   // core/file_digest.h
  std::string configuration;  // the swept set as given: cache spec and flags that change the rows
  SweepShard shard;
  std::size_t configurations = 0;               // in the whole set, impossible combinations included
  Table table;                                  // this part's rows under the whole sweep's title, parameters, columns
  std::vector<std::size_t> row_configurations;  // index in the whole set of each table row
  std::vector<std::string> skipped;             // this part's impossible combinations
};

// One JSON object ("rastrace_sweep_part": 1, ...); every number exact (doubles round-trip).
std::string sweep_part_json(const SweepPart& part);
// Throws InputError naming the file and the key or JSON position that is wrong.
SweepPart read_sweep_part(const std::string& path);

struct MergedSweep {
  Table table;
  std::vector<std::string> skipped;  // in configuration order
};
// Throws InputError (naming the files) unless the parts are all N shards of one configuration set,
// once each, computed by one version from one trace.
MergedSweep merge_sweep_parts(const std::vector<SweepPart>& parts, const std::vector<std::string>& paths);

}  // namespace rastrace
