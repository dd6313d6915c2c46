// `rastrace vipm`: every VIPM representation of one mesh's progressive mesh (Forsyth, "Comparison
// of VIPM Methods", Game Programming Gems 2, 2001) measured at sampled LoDs through one
// post-transform vertex cache, as tables: one row per method and LoD, one summary row per method,
// and Forsyth's Table 4.1.1 (six qualities, one column per method) with our number beside his word.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cache_sim/live_bank_sink.h"
#include "core/table.h"
#include "lod/vipm_measure.h"
#include "scenes/mesh.h"

namespace rastrace {

struct VipmExperimentSpec {
  std::string methods = "all";  // all, or a comma-separated list of vipm_method_names()
  VertexCacheSpec cache = vertex_cache_spec(VertexCachePolicy::Fifo, 16);
  std::uint32_t lod_step = 1;
  double tolerance = 0.1;           // sliding window's relaxation, of the mean collapse error
  std::uint32_t min_triangles = 0;  // the builder's; 0: its default
};

struct VipmExperiment {
  std::string mesh;  // as named on the command line
  VipmExperimentSpec spec;
  std::vector<std::string> methods;  // command-line names, in the order measured
  std::vector<VipmLodRow> rows;
  std::vector<VipmSummary> summaries;  // one per method, same order
  std::uint32_t collapses = 0;
  std::uint64_t full_triangles = 0;
  // Sliding window's levels: in the builder's order, relaxed with tolerance 0, and with spec.tolerance.
  std::uint32_t sliding_levels_strict = 0, sliding_levels_tolerance_0 = 0, sliding_levels = 0;
};

// vanilla, skipstrips, skiplists, mixed (lists), mixedstrips, sliding.
const std::vector<std::string>& vipm_method_names();
// Forsyth's column for a method: Vanilla, Skip Strips, Mixed-Mode or Sliding Window.
std::string forsyth_column(const std::string& method);
// The representation's method() name (lod/vipm_representation.h) for a command-line name;
// throws InputError naming `flag` and the accepted names.
std::string vipm_representation_of(const std::string& method, const char* flag);

// Throws InputError for an unknown method (naming the accepted ones), a lod step of 0, or a mesh
// the progressive-mesh builder refuses.
VipmExperiment run_vipm_experiment(const Mesh& mesh, const std::string& mesh_name, const VipmExperimentSpec& spec);

Table vipm_lod_table(const VipmExperiment& experiment);
Table vipm_summary_table(const VipmExperiment& experiment);

// Forsyth's six rows (vertex cache use, global memory, instance memory, LoD-change CPU cost, API
// efficiency, list efficiency): the measured figure and unit, and his word for the method.
struct ForsythQuality {
  std::string quality;  // "Vertex cache use"
  std::string unit;     // "vertices/triangle"
  std::string measure;  // what the number is
  bool lower_is_better = true;
  std::vector<double> values;      // one per method
  std::vector<std::string> words;  // Forsyth's, one per method
};
std::vector<ForsythQuality> forsyth_qualities(const VipmExperiment& experiment);
// Whether our number for `method` (an index into quality.values) agrees with Forsyth's word, by
// forsyth_agreement_rule(): "agrees", or "disagrees (vs a, b)" naming the methods ranked otherwise.
std::string forsyth_agreement(const ForsythQuality& quality, std::size_t method, const std::vector<std::string>& names);
std::string forsyth_agreement_rule();
Table vipm_forsyth_table(const VipmExperiment& experiment);

// One JSON object: "lods" (the LoD rows) and "summary" (one row per method), with the parameters.
std::string vipm_json(const VipmExperiment& experiment);

// Vertices per drawn triangle against drawn triangles, one line per method, and memory (global and
// mean instance bytes) per method, side by side. PNG or SVG by extension, through gnuplot.
void write_vipm_plot(const std::string& path, const VipmExperiment& experiment);

}  // namespace rastrace
