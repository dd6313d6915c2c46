// Tipsy's overdraw pass (tipsy-overdraw) and the view-sorted cluster orders on real meshes:
// lower view-independent overdraw than Tipsy at an ACMR within lambda of Tipsy's, beside
// meshoptimizer 0.18's meshopt_optimizeOverdraw run on the same Tipsy order in the same process;
// the clusters obey the cutting rule; front-to-back beats back-to-front from its view.
#include <gtest/gtest.h>

#include "cache_sim/vertex_cache.h"
#include "overdraw/meshopt_peer.h"
#include "overdraw/view_independent.h"
#include "reorder/ordering.h"
#include "reorder/overdraw_clusters.h"
#include "scenes/mesh_io.h"
#include "tests/support/test_data.h"
#include "tests/support/test_meshes.h"

namespace rastrace {
namespace {

const Mesh& test_mesh(const std::string& name) {
  static const Mesh spider = load_mesh(testing::data_file("assimp/OBJ/spider.obj"));
  return name == "spider" ? spider : testing::cached_mesh(name + ".off");
}

double acmr(std::span<const std::uint32_t> list) {
  return simulate_vertex_stream(list, PrimitiveType::TriangleList, VertexCachePolicy::Fifo, 16).acmr();
}

double overdraw(const Mesh& mesh, std::span<const std::uint32_t> list, const OverdrawOptions& options = {}) {
  return view_independent_overdraw(mesh.positions, list, options).overdraw();
}

struct Figures {
  const char* mesh;
  double tipsy_acmr, tipsy_overdraw, acmr, overdraw, meshopt_acmr, meshopt_overdraw;
};

// Cache 16, lambda 1.05, axis views at 256 x 256, exact rules. meshopt_optimizeOverdraw gets the
// same Tipsy order and threshold: on bunny00 ours overdraws less at 0.8% more ACMR; on the spider
// (a few large parts) its finer hard boundaries win on overdraw at the same ACMR.
TEST(TipsyOverdraw, LowerOverdrawThanTipsyAtAcmrWithinLambdaOnBunnyAndSpider) {
  constexpr double kTolerance = 0.0001;
  for (const Figures& f : {Figures{"bunny00", 0.6693, 1.0505, 0.7023, 1.0192, 0.6968, 1.0232},
                           Figures{"spider", 0.8202, 1.1916, 0.8480, 1.1560, 0.8494, 1.1403}}) {
    const Mesh& mesh = test_mesh(f.mesh);
    const ReorderParams params;  // cache 16, lambda 1.05
    const Ordering tipsy = reorder_tipsy(mesh, params), ours = reorder_tipsy_overdraw(mesh, params);
    EXPECT_NEAR(acmr(tipsy.indices), f.tipsy_acmr, kTolerance) << f.mesh;
    EXPECT_NEAR(overdraw(mesh, tipsy.indices), f.tipsy_overdraw, kTolerance) << f.mesh;
    EXPECT_NEAR(acmr(ours.indices), f.acmr, kTolerance) << f.mesh;
    EXPECT_NEAR(overdraw(mesh, ours.indices), f.overdraw, kTolerance) << f.mesh;
    EXPECT_LT(overdraw(mesh, ours.indices), overdraw(mesh, tipsy.indices)) << f.mesh;
    EXPECT_LE(acmr(ours.indices), params.overdraw_lambda * acmr(tipsy.indices)) << f.mesh;
    const std::vector<std::uint32_t> peer = meshopt_optimize_overdraw(mesh.positions, tipsy.indices, 1.05f);
    EXPECT_NEAR(acmr(peer), f.meshopt_acmr, kTolerance) << f.mesh;
    EXPECT_NEAR(overdraw(mesh, peer), f.meshopt_overdraw, kTolerance) << f.mesh;
  }
}

// lambda 1 keeps Tipsy's ACMR (to 0.0002) and still sorts; a larger lambda buys overdraw with ACMR.
TEST(TipsyOverdraw, LambdaTradesAcmrForOverdraw) {
  const Mesh& mesh = test_mesh("bunny00");
  const double tipsy_acmr = acmr(reorder_tipsy(mesh, {}).indices);
  double previous_acmr = 0, previous_overdraw = 10;
  for (const double lambda : {1.0, 1.05, 1.2}) {
    ReorderParams params;
    params.overdraw_lambda = lambda;
    const Ordering ours = reorder_tipsy_overdraw(mesh, params);
    const double a = acmr(ours.indices), o = overdraw(mesh, ours.indices);
    EXPECT_LE(a, lambda * tipsy_acmr + 0.0002) << lambda;
    EXPECT_GT(a, previous_acmr) << lambda;
    EXPECT_LT(o, previous_overdraw) << lambda;
    previous_acmr = a;
    previous_overdraw = o;
  }
}

// The clusters partition Tipsy's order; every cluster but the last of its run of cuts was cut
// where its own ACMR from a flushed cache fell below the threshold.
TEST(TipsyOverdraw, ClustersPartitionTipsysOrderAtTheThreshold) {
  const Mesh& mesh = test_mesh("bunny00");
  const OverdrawClusters clusters = tipsy_overdraw_clusters(mesh, ReorderParams{});
  ASSERT_GT(clusters.size(), 100u);
  EXPECT_EQ(clusters.starts.front(), 0u);
  EXPECT_TRUE(std::is_sorted(clusters.starts.begin(), clusters.starts.end()));
  EXPECT_EQ(std::adjacent_find(clusters.starts.begin(), clusters.starts.end()), clusters.starts.end());
  EXPECT_LE(clusters.threshold, 1.05 * clusters.tipsy_acmr);
  EXPECT_GT(clusters.threshold, clusters.tipsy_acmr);
  EXPECT_EQ(clusters.tipsy_faces, reorder_tipsy(mesh, {}).face_order);
}

// For the view they were sorted for (a camera looking down -z sees the +z side), front-to-back
// leaves almost no overdraw, back-to-front the most; tipsy-overdraw lies between.
TEST(ViewSortedClusters, FrontToBackBeatsBackToFrontFromItsView) {
  OverdrawOptions from_z;
  from_z.directions = {glm::vec3(0, 0, 1)};
  for (const char* name : {"bunny00", "spider"}) {
    const Mesh& mesh = test_mesh(name);
    ReorderParams params;
    params.view_direction = glm::vec3(0, 0, -1);
    const double front = overdraw(mesh, reorder_front_to_back(mesh, params).indices, from_z);
    const double back = overdraw(mesh, reorder_back_to_front(mesh, params).indices, from_z);
    const double tipsy_overdraw = overdraw(mesh, reorder_tipsy_overdraw(mesh, params).indices, from_z);
    EXPECT_LT(front, 1.03) << name;
    EXPECT_LT(front, tipsy_overdraw) << name;
    EXPECT_LT(tipsy_overdraw, back) << name;
  }
}

}  // namespace
}  // namespace rastrace
