// The adjacency evaluation behind `rastrace adjacency`: the command adds nothing to the
// experiment's table, the camera frames the whole mesh, and the edge stage sees every face and
// edge of a closed mesh once.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "experiments/adjacency_experiment.h"
#include "scenes/mesh_io.h"
#include "support/run_rastrace.h"
#include "support/test_data.h"

namespace rastrace {
namespace {

AdjacencyExperiment careful_with_edges(const std::string& mesh_spec) {
  AdjacencyExperiment experiment;
  experiment.mesh_spec = mesh_spec;
  experiment.orders = {AdjacencyOrder::Careful};
  experiment.edges = true;
  experiment.size = 256;
  experiment.with_time = false;
  return experiment;
}

TEST(AdjacencyExperiment, TheCommandPrintsTheExperimentsTable) {
  const std::string path = testing::data_file("meshes/triceratops.off");
  const Mesh mesh = load_mesh(path);
  const AdjacencyResult result = run_adjacency_experiment(mesh, careful_with_edges(path), nullptr);
  const testing::CommandRun run = testing::run_rastrace(
      {"adjacency", path, "--order", "careful", "--edges", "--size", "256", "--no-time", "--format", "json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(render_table(result.table, TableFormat::Json), run.out);

  const nlohmann::json rows = nlohmann::json::parse(run.out);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].at("order"), "careful");
  EXPECT_EQ(rows[0].at("cover"), 3125);
  EXPECT_EQ(rows[0].at("faces_processed"), 5660);
  EXPECT_EQ(rows[0].at("edges_processed"), 8490);
  EXPECT_EQ(result.first_order, "careful");
  EXPECT_EQ(result.first_indices.size(), 6u * 3125u);
}

TEST(AdjacencyExperiment, TheFramedCameraSeesEveryVertex) {
  const Mesh mesh = load_mesh(testing::data_file("meshes/triceratops.off"));
  const MeshView camera = frame_mesh(mesh, {0.3f, 0.2f, 1.0f}, 1.0f);
  const glm::mat4 mvp = camera.projection * camera.view;
  for (const glm::vec3& p : mesh.positions) {
    const glm::vec4 clip = mvp * glm::vec4(p, 1.0f);
    ASSERT_GT(clip.w, 0.0f);
    ASSERT_LE(std::abs(clip.x), clip.w);
    ASSERT_LE(std::abs(clip.y), clip.w);
    ASSERT_LE(std::abs(clip.z), clip.w);
  }
}

TEST(AdjacencyExperiment, AMeshWithoutFacesIsAClearError) {
  Mesh empty;
  empty.positions = {{0, 0, 0}, {1, 0, 0}};
  try {
    run_adjacency_experiment(empty, careful_with_edges("two-points.off"), nullptr);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "two-points.off: the mesh has no faces");
  }
}

}  // namespace
}  // namespace rastrace
