// The builder's geometric quality against meshoptimizer's meshopt_simplify at the same triangle
// count: the symmetric mean surface distance to the original at 50% and 10% of the triangles.
// Fandisk and bunny00 are the acceptance meshes; elephant and mushroom (which has a border)
// check that the same default parameters hold elsewhere. The ratios are printed.
#include <cstdio>

#include <gtest/gtest.h>

#include "lod/progressive_mesh.h"
#include "lod/progressive_mesh_peer.h"
#include "lod/surface_distance.h"
#include "scenes/mesh_io.h"
#include "tests/support/test_data.h"

namespace rastrace {
namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

Triangles mesh_triangles(const Mesh& mesh) {
  Triangles t(mesh.face_count());
  for (std::size_t f = 0; f < t.size(); ++f)
    t[f] = {mesh.indices[3 * f], mesh.indices[3 * f + 1], mesh.indices[3 * f + 2]};
  return t;
}

// Ours / meshoptimizer's mean surface distance at `fraction` of the faces.
double ratio_at(const Mesh& mesh, const ProgressiveMesh& pm, const Mesh& reordered, double fraction) {
  const std::uint32_t target = std::uint32_t(fraction * double(mesh.face_count()));
  const Triangles peer = meshopt_simplified_triangles(mesh, target);
  // Compare at the count meshoptimizer reached (it may stop short of the target).
  const std::size_t n = pm.lod_for_triangle_count(std::uint32_t(peer.size()));
  const Triangles ours = triangles_at_lod(pm, n);
  const SurfaceDistance d_ours = surface_distance(reordered.positions, pm.triangles, ours);
  const SurfaceDistance d_peer = surface_distance(mesh.positions, mesh_triangles(mesh), peer);
  const double diagonal = bounding_box_diagonal(mesh.positions, mesh_triangles(mesh));
  std::printf(
      "%s at %.0f%%: ours %zu triangles mean %.3e max %.3e, meshopt %zu triangles mean %.3e max %.3e "
      "(of the diagonal); mean ratio %.3f\n",
      mesh.name.c_str(), 100 * fraction, ours.size(), d_ours.mean / diagonal, d_ours.max / diagonal, peer.size(),
      d_peer.mean / diagonal, d_peer.max / diagonal, d_ours.mean / d_peer.mean);
  EXPECT_LE(ours.size(), peer.size());
  EXPECT_GE(ours.size() + 3, peer.size());
  return d_ours.mean / d_peer.mean;
}

void expect_within(const std::string& file, double bound) {
  const Mesh mesh = load_mesh(testing::data_file("meshes/" + file));
  const ProgressiveMesh pm = build_progressive_mesh(mesh, {});
  const Mesh reordered = reordered_mesh(mesh, pm);
  EXPECT_LE(ratio_at(mesh, pm, reordered, 0.5), bound) << file << " at 50%";
  EXPECT_LE(ratio_at(mesh, pm, reordered, 0.1), bound) << file << " at 10%";
}

TEST(ProgressiveMeshQuality, FandiskWithinOneAndAHalfOfMeshopt) { expect_within("fandisk.off", 1.5); }
TEST(ProgressiveMeshQuality, Bunny00WithinOneAndAHalfOfMeshopt) { expect_within("bunny00.off", 1.5); }
TEST(ProgressiveMeshQuality, ElephantWithinOneAndAHalfOfMeshopt) { expect_within("elephant.off", 1.5); }
TEST(ProgressiveMeshQuality, MushroomWithinOneAndAHalfOfMeshopt) { expect_within("mushroom.off", 1.5); }

}  // namespace
}  // namespace rastrace
