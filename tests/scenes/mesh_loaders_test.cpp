// The loaders keep the file's own vertex sharing and face order, on the real data.
#include <chrono>
#include <cstring>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/error.h"
#include "scenes/mesh_io.h"
#include "scenes/mesh_stats.h"
#include "tests/support/temp_dir.h"
#include "tests/support/test_data.h"

namespace rastrace {
namespace {

using testing::data_file;
using testing::TempDir;

TEST(OffLoader, FandiskHas6475VerticesAnd12946Triangles) {
  const Mesh mesh = load_mesh(data_file("meshes/fandisk.off"));
  EXPECT_EQ(mesh.vertex_count(), 6475u);
  EXPECT_EQ(mesh.face_count(), 12946u);
  EXPECT_TRUE(mesh.normals.empty());
  EXPECT_TRUE(mesh.uvs.empty());
  // First vertex and first face exactly as in the file.
  EXPECT_EQ(mesh.positions[0].x, 0.1696f);
  EXPECT_EQ(mesh.positions[0].y, 0.04095f);
  EXPECT_EQ(mesh.positions[0].z, -0.0471f);
}

TEST(OffLoader, TriceratopsHas2832VerticesAnd5660Triangles) {
  const Mesh mesh = load_mesh(data_file("meshes/triceratops.off"));
  EXPECT_EQ(mesh.vertex_count(), 2832u);
  EXPECT_EQ(mesh.face_count(), 5660u);
}

TEST(OffLoader, Bunny00LoadsWellUnderASecond) {
  const auto start = std::chrono::steady_clock::now();
  const Mesh mesh = load_mesh(data_file("meshes/bunny00.off"));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(mesh.vertex_count(), 37706u);
  EXPECT_EQ(mesh.face_count(), 75408u);
#if defined(NDEBUG) && !defined(__SANITIZE_ADDRESS__)
  EXPECT_LT(seconds, 1.0);
#else
  (void)seconds;
#endif
}

TEST(OffLoader, PolygonsAreFanTriangulatedInFileOrder) {
  TempDir dir;
  const std::string path = dir.write("pentagon.off",
                                     "OFF\n# a comment\n5 2 0\n0 0 0\n1 0 0\n2 1 0\n1 2 0\n0 1 0\n"
                                     "5 0 1 2 3 4\n3 4 3 2 255 0 0\n");
  const Mesh mesh = load_mesh(path);
  ASSERT_EQ(mesh.face_count(), 4u);
  const std::vector<std::uint32_t> expected = {0, 1, 2, 0, 2, 3, 0, 3, 4, 4, 3, 2};
  EXPECT_EQ(mesh.indices, expected);
}

TEST(OffLoader, ReadsNormalsAndTextureCoordinatesOfNoffAndStoff) {
  TempDir dir;
  const Mesh n = load_mesh(dir.write("n.off", "NOFF 3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n"));
  ASSERT_EQ(n.normals.size(), 3u);
  EXPECT_EQ(n.normals[2].z, 1.0f);
  const Mesh st = load_mesh(dir.write("st.off", "STOFF\n3 1 0\n0 0 0 0.25 0.5\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n"));
  ASSERT_EQ(st.uvs.size(), 3u);
  EXPECT_EQ(st.uvs[0].x, 0.25f);
  EXPECT_EQ(st.uvs[0].y, 0.5f);
}

TEST(OffLoader, EveryCgalMeshLoadsOrFailsWithAnInputError) {
  // The whole CGAL data folder: no crash, and the files that load have in-range indices.
  std::size_t loaded = 0;
  for (const auto& entry : std::filesystem::directory_iterator(data_file("meshes"))) {
    if (entry.path().extension() != ".off") continue;
    try {
      const Mesh mesh = load_mesh(entry.path().string());
      for (const std::uint32_t i : mesh.indices) ASSERT_LT(i, mesh.vertex_count()) << entry.path();
      ++loaded;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(entry.path().filename().string()), std::string::npos) << e.what();
    }
  }
  EXPECT_GT(loaded, 50u);
}

TEST(PlyLoader, ReadsAsciiVerticesWithNormalsAndSkipsOtherProperties) {
  const Mesh mesh = load_mesh(data_file("meshes/colored_tetra.ply"));
  EXPECT_EQ(mesh.vertex_count(), 4u);
  EXPECT_EQ(mesh.face_count(), 4u);
  EXPECT_EQ(mesh.normals.size(), 4u);
  const Mesh cloud = load_mesh(data_file("meshes/b9.ply"));
  EXPECT_EQ(cloud.vertex_count(), 22300u);
  EXPECT_EQ(cloud.face_count(), 0u);
  EXPECT_EQ(cloud.positions[0].x, 45.375f);
}

// A two-triangle quad written by hand in both byte orders, with a uchar colour, a uv pair named
// texture_u/texture_v, and a list of size 4 named vertex_index.
std::string binary_quad(bool big_endian) {
  std::string out = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
                    "property float texture_u\nproperty float texture_v\nelement face 1\n"
                    "property list uchar uint vertex_index\nproperty int flags\nend_header\n";
  const auto put = [&out, big_endian](const void* p, std::size_t n) {
    std::string bytes(static_cast<const char*>(p), n);
    if (big_endian) std::reverse(bytes.begin(), bytes.end());
    out += bytes;
  };
  const float xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5f}, {0, 1, 0}};
  for (int v = 0; v < 4; ++v) {
    for (float c : xyz[v]) put(&c, 4);
    const std::uint8_t red = 200;
    put(&red, 1);
    const float u = xyz[v][0], t = xyz[v][1];
    put(&u, 4), put(&t, 4);
  }
  const std::uint8_t four = 4;
  put(&four, 1);
  for (std::uint32_t i : {3u, 0u, 1u, 2u}) put(&i, 4);
  const std::int32_t flags = 7;
  put(&flags, 4);
  return out;
}

TEST(PlyLoader, ReadsBinaryLittleAndBigEndianAlike) {
  TempDir dir;
  for (const bool big : {false, true}) {
    const Mesh mesh = load_mesh(dir.write(big ? "big.ply" : "little.ply", binary_quad(big)));
    ASSERT_EQ(mesh.vertex_count(), 4u);
    ASSERT_EQ(mesh.face_count(), 2u);
    EXPECT_EQ(mesh.positions[2].z, 0.5f);
    ASSERT_EQ(mesh.uvs.size(), 4u);
    EXPECT_EQ(mesh.uvs[2].x, 1.0f);
    const std::vector<std::uint32_t> fan = {3, 0, 1, 3, 1, 2};
    EXPECT_EQ(mesh.indices, fan);
  }
}

TEST(ObjLoader, SpiderLoadsWithItsFiveMaterialsAndTextures) {
  const Mesh mesh = load_mesh(data_file("assimp/OBJ/spider.obj"));
  EXPECT_EQ(mesh.vertex_count(), 974u);
  EXPECT_EQ(mesh.face_count(), 1368u);
  ASSERT_EQ(mesh.materials.size(), 5u);
  EXPECT_EQ(mesh.materials[2].name, "HLeibTex");
  EXPECT_EQ(mesh.materials[2].texture_source.kind, TextureSource::Kind::File);
  EXPECT_EQ(std::filesystem::path(mesh.materials[2].texture_source.path).filename(), "SpiderTex.jpg");
  EXPECT_EQ(std::filesystem::path(mesh.materials[4].texture_source.path).filename(), "engineflare1.jpg");
  EXPECT_FLOAT_EQ(mesh.materials[0].diffuse.r, 0.827451f);
  ASSERT_EQ(mesh.face_material.size(), mesh.face_count());
  std::vector<std::size_t> per_material(5, 0);
  for (const std::uint32_t m : mesh.face_material) ++per_material.at(m);
  // usemtl switches: Skin 4, HLeibTex 1, BeinTex 12, Augentex 2; Brusttex is defined but unused.
  EXPECT_EQ(per_material[1], 0u);
  for (const std::size_t m : {0u, 2u, 3u, 4u}) EXPECT_GT(per_material[m], 0u) << mesh.materials[m].name;
  EXPECT_EQ(mesh.uvs.size(), mesh.vertex_count());
  EXPECT_EQ(compute_mesh_stats(mesh).textures, 5u);
}

TEST(ObjLoader, AVertexIsADistinctTripleInOrderOfFirstAppearance) {
  TempDir dir;
  // Two positions used with two different texture coordinates each; negative indices.
  const std::string path = dir.write("split.obj",
                                     "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvt 0.5 0.5\n"
                                     "f 1/1 2/2 3/3\nf -3/-4 -1/-2 -2/-1\n");
  const Mesh mesh = load_mesh(path);
  // Corners: (1,1) (2,2) (3,3) | (2,2) (4,4) (3,5): (3,5) differs from (3,3) in vt.
  ASSERT_EQ(mesh.vertex_count(), 5u);
  const std::vector<std::uint32_t> expected = {0, 1, 2, 1, 3, 4};
  EXPECT_EQ(mesh.indices, expected);
  EXPECT_EQ(mesh.positions[4], glm::vec3(0, 1, 0));
  EXPECT_EQ(mesh.uvs[4], glm::vec2(0.5f, 0.5f));
}

TEST(ObjLoader, UsemtlGivesPerFaceMaterialsAndMapKdResolvesBesideTheMtl) {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "materials" / "images");
  dir.write("materials/images/wood.png", "not read by the mesh loader");
  dir.write("materials/lib.mtl", "newmtl red\nKd 1 0 0\nnewmtl wood\nKd 1 1 1\nmap_Kd -s 1 1 1 images\\wood.png\n");
  const Mesh mesh = load_mesh(dir.write("m.obj",
                                        "mtllib materials/lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                                        "f 1 2 3\nusemtl wood\nf 2 4 3\nusemtl red\nf 1 2 4\n"));
  ASSERT_EQ(mesh.materials.size(), 3u);  // red, wood, and the default for the first face
  EXPECT_EQ(mesh.materials[2].name, "default");
  const std::vector<std::uint32_t> expected = {2, 1, 0};
  EXPECT_EQ(mesh.face_material, expected);
  EXPECT_EQ(std::filesystem::path(mesh.materials[1].texture_source.path),
            (dir.path() / "materials" / "images" / "wood.png").lexically_normal());
  EXPECT_EQ(mesh.materials[0].diffuse, glm::vec4(1, 0, 0, 1));
}

TEST(AssimpLoader, ColladaDuckLoadsWithItsTexture) {
  const Mesh mesh = load_mesh(data_file("assimp/Collada/duck.dae"));
  EXPECT_GT(mesh.vertex_count(), 2000u);
  EXPECT_EQ(mesh.face_count(), 4212u);
  ASSERT_FALSE(mesh.materials.empty());
  EXPECT_EQ(mesh.uvs.size(), mesh.vertex_count());
  bool textured = false;
  for (const Material& m : mesh.materials)
    textured |= std::filesystem::path(m.texture_source.path).filename() == "duckCM.tga";
  EXPECT_TRUE(textured);
}

TEST(AssimpLoader, GltfCesiumMilkTruckLoadsWithItsTexture) {
  const Mesh mesh = load_mesh(data_file("assimp/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf"));
  EXPECT_GT(mesh.face_count(), 1000u);
  bool textured = false;
  for (const Material& m : mesh.materials)
    textured |= std::filesystem::path(m.texture_source.path).filename() == "CesiumMilkTruck.png";
  EXPECT_TRUE(textured);
  for (const std::uint32_t i : mesh.indices) ASSERT_LT(i, mesh.vertex_count());
}

}  // namespace
}  // namespace rastrace
