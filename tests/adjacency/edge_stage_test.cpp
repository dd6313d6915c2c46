#include <algorithm>
#include <cmath>
#include <map>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "adjacency_fixture.h"
#include "cache_sim/vertex_cache.h"
#include "experiments/adjacency_experiment.h"
#include "reorder/adjacency/order.h"
#include "reorder/mesh_topology.h"
#include "scenes/procedural.h"

namespace rastrace {
namespace {

// The edge stage with every processed edge and face kept.
EdgeStageOptions recording() {
  EdgeStageOptions options;
  options.record = true;
  return options;
}

TEST(EdgeStage, ProcessesEveryFaceAndEveryEdgeOfBunnyExactlyOnce) {
  const auto& built = testing::built_mesh("bunny00.off");
  const Mesh& mesh = built.mesh;
  const AdjacencyPrimitives ordered = permute_primitives(
      built.build.primitives, order_adjacency(AdjacencyOrder::Fast, mesh, built.build.primitives, 24));
  const auto camera = frame_mesh(mesh, {0.3f, 0.2f, 1.0f}, 1.0f);
  const auto result = draw_edge_stage(mesh, ordered.indices, camera, recording(), 24, nullptr);

  EXPECT_EQ(result.edges.primitives, ordered.size());
  EXPECT_EQ(result.edges.faces(), mesh.face_count());
  EXPECT_EQ(result.edges.assigned_faces, mesh.face_count() - ordered.size());
  const MeshTopology topology = build_mesh_topology(mesh);
  EXPECT_EQ(result.edges.edges, topology.edge_count());  // 113112
  EXPECT_EQ(result.edges.boundary_edges, 0u);
  std::vector<int> seen(topology.edge_count(), 0);
  for (const ProcessedEdge& e : result.processed) ++seen[topology.find_edge(e.from, e.to)];
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(topology.edge_count()));

  // Vertex shader invocations are the post-transform cache misses of the index stream.
  const VertexStreamStats stats =
      simulate_vertex_stream(ordered.indices, PrimitiveType::TriangleListAdjacency, VertexCachePolicy::Fifo, 24);
  EXPECT_EQ(result.pipeline.vertices_shaded, stats.misses);
  EXPECT_EQ(result.pipeline.lookups, 6 * ordered.size());

  // A silhouette of a closed mesh: every silhouette vertex has an even number of silhouette edges.
  std::map<std::uint32_t, int> degree;
  for (const ProcessedEdge& e : result.processed)
    if (e.flags & kEdgeSilhouette) {
      ++degree[e.from];
      ++degree[e.to];
    }
  EXPECT_GT(result.edges.silhouette_edges, 1000u);
  for (const auto& [vertex, count] : degree) ASSERT_EQ(count % 2, 0) << vertex;
}

TEST(EdgeStage, SilhouetteAndSharpEdgesMatchABruteForceOverAllFaces) {
  const auto& built = testing::built_mesh("fandisk.off");
  const Mesh& mesh = built.mesh;
  const auto camera = frame_mesh(mesh, {1.0f, 0.5f, 0.7f}, 1.0f);
  const auto result = draw_edge_stage(mesh, built.build.primitives.indices, camera, recording(), 24, nullptr);

  // Brute force: facing of every face from its eye-space normal against the eye direction.
  const MeshTopology topology = build_mesh_topology(mesh);
  const glm::mat4 mvp = camera.projection * camera.view;
  auto front = [&](std::uint32_t f) {
    glm::vec4 c[3];
    for (int k = 0; k < 3; ++k) c[k] = mvp * glm::vec4(mesh.positions[mesh.indices[3 * f + k]], 1.0f);
    const glm::vec2 a(c[0].x / c[0].w, c[0].y / c[0].w), b(c[1].x / c[1].w, c[1].y / c[1].w),
        d(c[2].x / c[2].w, c[2].y / c[2].w);
    return (b.x - a.x) * (d.y - a.y) - (d.x - a.x) * (b.y - a.y) > 0.0f;
  };
  std::uint64_t silhouettes = 0, sharp = 0;
  for (std::uint32_t e = 0; e < topology.edge_count(); ++e) {
    const auto faces = topology.faces_of_edge(e);
    ASSERT_EQ(faces.size(), 2u);
    silhouettes += front(faces[0]) != front(faces[1]);
    const auto normal = [&](std::uint32_t f) {
      const glm::vec3* p = mesh.positions.data();
      const std::uint32_t* i = mesh.indices.data() + 3 * f;
      return glm::normalize(glm::cross(p[i[1]] - p[i[0]], p[i[2]] - p[i[0]]));
    };
    sharp += glm::dot(normal(faces[0]), normal(faces[1])) < std::cos(glm::radians(60.0f));
  }
  // Facing from det[x y w] and from the divided NDC area can differ only for edge-on faces.
  EXPECT_NEAR(double(result.edges.silhouette_edges), double(silhouettes), 2.0);
  EXPECT_EQ(result.edges.sharp_edges, sharp);
  EXPECT_GT(sharp, 100u);  // fandisk's creases
}

TEST(EdgeStage, GridBoundaryIsDrawnAsLinesAndRejectsOtherPrimitives) {
  const Mesh mesh = make_grid(8, 8);
  const AdjacencyBuild build = build_adjacency_primitives(mesh);
  const auto camera = frame_mesh(mesh, {0.0f, 0.0f, 1.0f}, 1.0f);
  Framebuffer lines(128, 128);
  lines.clear(glm::vec4(0.0f));
  const auto result = draw_edge_stage(mesh, build.primitives.indices, camera, {}, 24, &lines);
  EXPECT_EQ(result.edges.boundary_edges, 32u);
  EXPECT_EQ(result.edges.silhouette_edges, 0u);  // a flat grid seen from the front
  EXPECT_EQ(result.edges.lines_drawn, 32u);
  EXPECT_GT(result.edges.pixels, 4u * 60u);  // the frame's four sides, each over 60 pixels long
  EXPECT_EQ(result.edges.faces(), mesh.face_count());

  // A plain triangle list through the same hook: nothing is processed.
  EdgeStage stage(mesh, {}, nullptr);
  Framebuffer scratch(32, 32);
  Pipeline pipeline(scratch, {}, nullptr);
  pipeline.set_primitive_hook(&stage);
  DrawCall call;
  call.indices = mesh.indices;
  pipeline.draw(mesh, glm::mat4(1.0f), call, {});
  EXPECT_EQ(stage.stats().primitives, 0u);
}

}  // namespace
}  // namespace rastrace
