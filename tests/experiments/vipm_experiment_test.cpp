// The VIPM experiment behind `rastrace vipm`: the summary figures on triceratops (FIFO 16, every
// 100th LoD), the JSON keys, Forsyth's six rows with his words, the agreement rule and bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "experiments/vipm_experiment.h"
#include "scenes/mesh_io.h"
#include "scenes/mesh_spec.h"
#include "support/test_data.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;

const VipmExperiment& triceratops() {
  static const VipmExperiment experiment = [] {
    VipmExperimentSpec spec;
    spec.lod_step = 100;
    return run_vipm_experiment(load_mesh(testing::data_file("meshes/triceratops.off")), "triceratops.off", spec);
  }();
  return experiment;
}

const VipmSummary& summary(const std::string& method) {
  for (const VipmSummary& s : triceratops().summaries)
    if (s.method == method) return s;
  throw std::runtime_error("no method " + method);
}

TEST(VipmExperiment, TriceratopsSummaryAtFifo16) {
  const VipmExperiment& e = triceratops();
  ASSERT_EQ(e.methods, vipm_method_names());
  ASSERT_EQ(e.summaries.size(), 6u);
  // Our figures for the builder's collapses at every 100th LoD (29 LoDs); 16-bit indices.
  const std::pair<const char*, double> acmr[] = {{"vanilla", 2.308}, {"skipstrips", 0.730},  {"skiplists", 0.704},
                                                 {"mixed", 1.554},   {"mixedstrips", 0.904}, {"sliding", 0.960}};
  for (const auto& [method, expected] : acmr) {
    EXPECT_NEAR(summary(method).mean_vertices_per_triangle, expected, 0.0005) << method;
    EXPECT_EQ(summary(method).lods_measured, 29u) << method;
    EXPECT_EQ(summary(method).index_bits, 16u) << method;
  }
  EXPECT_NEAR(summary("vanilla").index_writes_per_collapse, 3.238, 0.0005);
  EXPECT_NEAR(summary("skiplists").index_writes_per_collapse, 6.851, 0.0005);
  EXPECT_NEAR(summary("sliding").index_writes_per_collapse, 0.0, 1e-12);
  EXPECT_NEAR(summary("skipstrips").mean_degenerate_fraction, 0.424, 0.0005);
  EXPECT_NEAR(summary("mixed").mean_draw_calls, 2.0, 1e-12);
  EXPECT_EQ(summary("vanilla").global_bytes, 159198u);
  EXPECT_EQ(summary("sliding").global_bytes, 499572u);
  EXPECT_EQ(summary("sliding").max_instance_bytes, 4u);
  EXPECT_EQ(summary("skipstrips").levels, 6u);
  EXPECT_EQ(e.collapses, 2774u);
  EXPECT_EQ(e.sliding_levels_tolerance_0, 149u);
  EXPECT_EQ(e.sliding_levels, 50u);
}

TEST(VipmExperiment, ForsythTableHasHisSixRowsAndWords) {
  const std::vector<ForsythQuality> q = forsyth_qualities(triceratops());
  ASSERT_EQ(q.size(), 6u);
  const char* names[] = {"Vertex cache use",    "Global memory use", "Instance memory use",
                         "LoD-change CPU cost", "API efficiency",    "List efficiency"};
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(q[i].quality, names[i]);
    EXPECT_EQ(q[i].values.size(), 6u);
  }
  // Methods: vanilla, skipstrips, skiplists, mixed, mixedstrips, sliding.
  EXPECT_EQ(q[0].words, (std::vector<std::string>{"Poor", "Excellent", "Excellent", "Good", "Good", "Good"}));
  EXPECT_EQ(q[3].words[5], "Tiny");
  EXPECT_EQ(q[2].words[0], "High");
  const Table table = vipm_forsyth_table(triceratops());
  ASSERT_EQ(table.rows.size(), 6u);
  EXPECT_THAT(std::get<std::string>(table.rows[0][1].value), HasSubstr("v/tri (Poor)"));
}

TEST(VipmExperiment, AgreementRanksAgainstMethodsRatedOtherwise) {
  ForsythQuality q{"Vertex cache use", "v/tri", "", true, {0.9, 0.7, 0.8}, {"Poor", "Excellent", "Good"}};
  const std::vector<std::string> names = {"vanilla", "skipstrips", "mixed"};
  EXPECT_EQ(forsyth_agreement(q, 0, names), "agrees");
  EXPECT_EQ(forsyth_agreement(q, 1, names), "agrees");
  q.values = {0.9, 0.8, 0.7};  // mixed beats skip strips, which he rates higher
  EXPECT_EQ(forsyth_agreement(q, 1, names), "disagrees (vs mixed)");
  EXPECT_EQ(forsyth_agreement(q, 0, names), "agrees");
}

TEST(VipmExperiment, JsonHasLodsAndSummaryKeys) {
  const nlohmann::json json = nlohmann::json::parse(vipm_json(triceratops()));
  ASSERT_TRUE(json["lods"].is_array());
  ASSERT_FALSE(json["lods"].empty());
  for (const char* key : {"method", "lod", "triangles", "acmr", "degenerate", "index_bytes", "draw_calls"})
    EXPECT_TRUE(json["lods"][0].contains(key)) << key;
  ASSERT_EQ(json["summary"].size(), 6u);
  for (const char* key :
       {"method", "mean_acmr", "global_bytes", "instance_bytes", "index_writes_per_collapse", "levels"})
    EXPECT_TRUE(json["summary"][0].contains(key)) << key;
  EXPECT_EQ(json["parameters"]["index_width"], "16-bit");
  EXPECT_EQ(json["parameters"]["sliding_levels_tolerance_0"], triceratops().sliding_levels_tolerance_0);
  EXPECT_EQ(json["parameters"]["sliding_levels_at_tolerance"], triceratops().sliding_levels);
}

TEST(VipmExperiment, UnknownMethodNamesTheAcceptedOnes) {
  VipmExperimentSpec spec;
  spec.methods = "vanilla,strips";
  try {
    run_vipm_experiment(load_mesh_spec("grid:4x4"), "grid:4x4", spec);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("'strips'"));
    EXPECT_THAT(e.what(), HasSubstr("vanilla, skipstrips, skiplists, mixed, mixedstrips, sliding"));
  }
  spec.methods = "all";
  spec.lod_step = 0;
  EXPECT_THROW(run_vipm_experiment(load_mesh_spec("grid:4x4"), "grid:4x4", spec), InputError);
}

}  // namespace
}  // namespace rastrace
