// `rastrace report`, the main job: a compact version of every experiment on one scene. It renders
// the frame, compares the vertex cache under each ordering, renders the chosen orderings with
// scanline and tiled traversal, records their texel traces, sweeps texture caches over them
// (sizes, FIFO/LRU/OPT, layouts), measures each render's whole frame traffic (vertex, texture,
// depth and colour, stacked per ordering in a plot) and writes DIR/report.md with the tables, the
// plots (DIR/plots) and the frames (DIR/images). Everything in it is deterministic: running the same report again
// writes the same bytes.
#pragma once

#include <string>

#include "cache_sim/sweep.h"

namespace rastrace {

struct ReportSpec {
  std::string scene = "builtin:bunny";
  std::string output_dir = "out";
  std::string orders = "original,strip,texgroup,tipsy";  // orderings whose frame traffic is measured
  std::string vcache_orders = "original,scanline,morton,hilbert,strip,forsyth,tipsy,kcache,greedy,texgroup";
  // Orderings compared under every vertex reuse preset (FIFO with warps, Kerbl et al.'s batches).
  std::string model_orders = "original,morton,strip,forsyth,tipsy,kcache,greedy,batch";
  SweepSpec sweep;  // the texture caches swept over every trace
};

// Writes DIR/report.md, DIR/plots, DIR/images and DIR/traces, and prints the report's path on
// stdout. Throws InputError for an unknown scene or ordering.
void write_report(const ReportSpec& spec);

}  // namespace rastrace
