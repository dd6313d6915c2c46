// The first-use vertex order (reorder/vertex_order.h) against meshoptimizer's
// meshopt_optimizeVertexFetchRemap / meshopt_optimizeVertexFetch, in the same process and on the
// command line (`rastrace reorder --vertices first-use`).
#include <meshoptimizer.h>

#include <gtest/gtest.h>

#include "core/error.h"
#include "reorder/ordering.h"
#include "reorder/vertex_order.h"
#include "scenes/mesh_io.h"
#include "support/run_rastrace.h"
#include "support/temp_dir.h"
#include "support/test_meshes.h"

namespace rastrace {
namespace {

TEST(VertexOrder, FirstUseRemapEqualsMeshoptOptimizeVertexFetchRemap) {
  for (const char* name : {"fandisk.off", "triceratops.off", "bunny00.off", "elephant-with-holes.off"}) {
    const Mesh& mesh = testing::cached_mesh(name);
    const Ordering tipsy = reorder_tipsy(mesh, ReorderParams{});
    for (const std::vector<std::uint32_t>* indices : {&mesh.indices, &tipsy.indices}) {
      const std::vector<std::uint32_t> ours = first_use_vertex_remap(*indices, mesh.vertex_count());
      std::vector<std::uint32_t> theirs(mesh.vertex_count());
      const std::size_t used =
          meshopt_optimizeVertexFetchRemap(theirs.data(), indices->data(), indices->size(), mesh.vertex_count());
      std::vector<bool> taken(mesh.vertex_count(), false);
      for (std::size_t v = 0; v < ours.size(); ++v) {
        ASSERT_LT(ours[v], mesh.vertex_count());
        EXPECT_FALSE(taken[ours[v]]) << name << ": not a permutation";
        taken[ours[v]] = true;
        if (theirs[v] != ~0u)
          ASSERT_EQ(ours[v], theirs[v]) << name << " vertex " << v;
        else
          EXPECT_GE(ours[v], used) << name << ": an unused vertex goes after the used ones";
      }
    }
  }
  EXPECT_THROW(first_use_vertex_remap(std::vector<std::uint32_t>{0, 1, 5}, 3), InputError);
}

TEST(VertexOrder, RemappedMeshEqualsMeshoptOptimizeVertexFetchOutput) {
  Mesh mesh = testing::cached_mesh("fandisk.off");
  mesh.indices = reorder_tipsy(mesh, ReorderParams{}).indices;
  // fandisk has no normals or UVs: give each vertex its own, to see them move with it.
  mesh.normals.resize(mesh.vertex_count());
  mesh.uvs.resize(mesh.vertex_count());
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    mesh.normals[v] = glm::vec3(float(v), 0.0f, 1.0f);
    mesh.uvs[v] = glm::vec2(0.5f, float(v));
  }
  std::vector<std::uint32_t> indices = mesh.indices;
  std::vector<glm::vec3> positions(mesh.vertex_count());
  const std::size_t used = meshopt_optimizeVertexFetch(positions.data(), indices.data(), indices.size(),
                                                       mesh.positions.data(), mesh.vertex_count(), sizeof(glm::vec3));
  std::vector<glm::vec3> normals(mesh.vertex_count());
  std::vector<std::uint32_t> scratch = mesh.indices;  // meshopt rewrites the indices it is given
  meshopt_optimizeVertexFetch(normals.data(), scratch.data(), scratch.size(), mesh.normals.data(), mesh.vertex_count(),
                              sizeof(glm::vec3));
  ASSERT_EQ(used, 6475u);
  const std::vector<std::uint32_t> original = mesh.indices;
  remap_vertices(mesh, first_use_vertex_remap(original, mesh.vertex_count()));
  EXPECT_EQ(mesh.indices, indices);
  for (std::size_t v = 0; v < used; ++v) {
    ASSERT_EQ(mesh.positions[v], positions[v]) << v;
    ASSERT_EQ(mesh.normals[v], normals[v]) << v;
    ASSERT_EQ(mesh.uvs[v].y, normals[v].x) << v;  // the same vertex's UV
  }
}

TEST(VertexOrder, ReorderCommandWritesFirstUseVertexOrder) {
  const testing::TempDir dir;
  const std::string keep = dir.file("keep.ply"), first_use = dir.file("first-use.ply");
  const std::string input = testing::data_file("meshes/triceratops.off");
  testing::CommandRun r = testing::run_rastrace({"reorder", input, "--algo", "tipsy", "-o", keep});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = testing::run_rastrace({"reorder", input, "--algo", "tipsy", "--vertices", "first-use", "-o", first_use});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("5660 faces in tipsy order"), std::string::npos) << r.out;
  const Mesh kept = load_mesh(keep), moved = load_mesh(first_use);
  ASSERT_EQ(kept.vertex_count(), moved.vertex_count());
  std::vector<std::uint32_t> indices = kept.indices;
  std::vector<glm::vec3> positions(kept.vertex_count());
  const std::size_t used = meshopt_optimizeVertexFetch(positions.data(), indices.data(), indices.size(),
                                                       kept.positions.data(), kept.vertex_count(), sizeof(glm::vec3));
  EXPECT_EQ(moved.indices, indices);
  for (std::size_t v = 0; v < used; ++v) ASSERT_EQ(moved.positions[v], positions[v]) << v;
  EXPECT_EQ(testing::run_rastrace({"reorder", input, "--algo", "tipsy", "--vertices", "last", "-o", keep}).exit_code, 1);
}

}  // namespace
}  // namespace rastrace
