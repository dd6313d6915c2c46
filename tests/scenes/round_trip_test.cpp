// Writers keep vertex order, face order and every position bit-exact:
// OFF -> PLY (binary) -> OBJ -> OFF gives back the same bits and the same index buffer.
#include <cmath>
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "scenes/mesh_io.h"
#include "scenes/procedural.h"
#include "tests/support/temp_dir.h"
#include "tests/support/test_data.h"

namespace rastrace {
namespace {

using testing::TempDir;

void expect_same_bits(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.vertex_count(), b.vertex_count());
  ASSERT_EQ(a.indices, b.indices);  // every index, faces in the same order
  EXPECT_EQ(std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(glm::vec3)), 0);
}

Mesh round_trip(const Mesh& original, const TempDir& dir) {
  const std::string off = dir.file("a.off"), ply = dir.file("b.ply"), obj = dir.file("c.obj"), back = dir.file("d.off");
  save_mesh(original, off);
  const Mesh from_off = load_mesh(off);
  save_mesh(from_off, ply);
  const Mesh from_ply = load_mesh(ply);
  save_mesh(from_ply, obj);
  const Mesh from_obj = load_mesh(obj);
  save_mesh(from_obj, back);
  return load_mesh(back);
}

TEST(RoundTrip, FandiskOffPlyObjOffIsBitExact) {
  TempDir dir;
  const Mesh original = load_mesh(testing::data_file("meshes/fandisk.off"));
  expect_same_bits(original, round_trip(original, dir));
}

TEST(RoundTrip, ProceduralGridOffPlyObjOffIsBitExact) {
  TempDir dir;
  Mesh grid = make_grid(16, 16);
  // Positions that need all nine digits, and ones with no short decimal form.
  grid.positions[5] = glm::vec3(1.0f / 3.0f, std::nextafter(1.0f, 2.0f), -0.0f);
  grid.positions[7] = glm::vec3(std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::max(), 1e-38f);
  const Mesh back = round_trip(grid, dir);
  expect_same_bits(grid, back);
  EXPECT_TRUE(std::signbit(back.positions[5].z));
}

TEST(RoundTrip, BinaryPlyKeepsNormalsAndUvsExactly) {
  TempDir dir;
  const Mesh sphere = make_icosphere(2);
  save_mesh(sphere, dir.file("s.ply"));
  const Mesh back = load_mesh(dir.file("s.ply"));
  expect_same_bits(sphere, back);
  ASSERT_EQ(back.normals.size(), sphere.normals.size());
  ASSERT_EQ(back.uvs.size(), sphere.uvs.size());
  EXPECT_EQ(std::memcmp(back.normals.data(), sphere.normals.data(), sphere.normals.size() * sizeof(glm::vec3)), 0);
  EXPECT_EQ(std::memcmp(back.uvs.data(), sphere.uvs.data(), sphere.uvs.size() * sizeof(glm::vec2)), 0);
}

TEST(RoundTrip, AsciiPlyIsBitExactToo) {
  TempDir dir;
  const Mesh original = load_mesh(testing::data_file("meshes/triceratops.off"));
  save_mesh(original, dir.file("t.ply"), MeshWriteOptions{.ascii = true});
  expect_same_bits(original, load_mesh(dir.file("t.ply")));
}

TEST(RoundTrip, ObjKeepsUnreferencedVerticesAndMaterials) {
  TempDir dir;
  Mesh mesh = make_plane(2, 3.0f);
  mesh.positions.emplace_back(9.0f, 9.0f, 9.0f);  // referenced by no face
  mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
  mesh.uvs.emplace_back(0.0f, 0.0f);
  mesh.materials.push_back(Material{});
  mesh.materials.back().name = "second";
  mesh.face_material.assign(mesh.face_count(), 0);
  mesh.face_material[3] = 1;
  save_mesh(mesh, dir.file("p.obj"));
  const Mesh back = load_mesh(dir.file("p.obj"));
  expect_same_bits(mesh, back);
  EXPECT_EQ(back.face_material, mesh.face_material);
  ASSERT_EQ(back.materials.size(), 2u);
  EXPECT_EQ(back.materials[1].name, "second");
  EXPECT_EQ(back.uvs, mesh.uvs);
}

TEST(RoundTrip, SpiderObjReadsBackWithTheSameTexturesAfterSavingElsewhere) {
  TempDir dir;
  const Mesh spider = load_mesh(testing::data_file("assimp/OBJ/spider.obj"));
  save_mesh(spider, dir.file("spider.obj"));
  const Mesh back = load_mesh(dir.file("spider.obj"));
  expect_same_bits(spider, back);
  ASSERT_EQ(back.materials.size(), spider.materials.size());
  for (std::size_t m = 0; m < spider.materials.size(); ++m)
    EXPECT_EQ(std::filesystem::weakly_canonical(back.materials[m].texture_source.path),
              std::filesystem::weakly_canonical(spider.materials[m].texture_source.path));
}

}  // namespace
}  // namespace rastrace
