// Vertex-buffer fetch (cache_sim/vertex_fetch.h): the definition on hand-made streams, and exact
// agreement with meshoptimizer's meshopt_analyzeVertexFetch on every CGAL mesh of the data folder
// with at least 2,000 faces, in file order and three other orders.
#include <meshoptimizer.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>

#include <gtest/gtest.h>

#include "cache_sim/vertex_fetch.h"
#include "core/error.h"
#include "tests/support/test_data.h"
#include "tests/support/test_meshes.h"

namespace rastrace {
namespace {

TEST(VertexFetch, CountsEveryLineAVertexStraddles) {
  // 32-byte vertices in 64-byte lines: vertices 0-1 in line 0, 2-3 in line 1. Two lines, 128
  // bytes, for four distinct vertices of 32 bytes: overfetch 1.
  const std::vector<std::uint32_t> list = {0, 1, 2, 2, 1, 3};
  VertexFetchStats stats = simulate_vertex_fetch(list, PrimitiveType::TriangleList, kNoRestart, 32, meshopt_fetch_cache());
  EXPECT_EQ(stats.fetches, 6u);
  EXPECT_EQ(stats.line_accesses, 6u);
  EXPECT_EQ(stats.misses, 2u);
  EXPECT_EQ(stats.bytes_fetched, 128u);
  EXPECT_EQ(stats.vertices, 4u);
  EXPECT_DOUBLE_EQ(stats.overfetch(), 1.0);
  // 48-byte vertices: vertex 1 is bytes 48-95 (lines 0 and 1), vertex 2 is 96-143 (lines 1 and
  // 2): ten line reads, three lines, 192 bytes for 192 bytes of vertices.
  stats = simulate_vertex_fetch(list, PrimitiveType::TriangleList, kNoRestart, 48, meshopt_fetch_cache());
  EXPECT_EQ(stats.line_accesses, 10u);
  EXPECT_EQ(stats.misses, 3u);
  EXPECT_DOUBLE_EQ(stats.overfetch(), 1.0);
  // Vertex 1 alone straddles two lines: 128 bytes for 48.
  const std::vector<std::uint32_t> one = {1, 1, 1};
  stats = simulate_vertex_fetch(one, PrimitiveType::TriangleList, kNoRestart, 48, meshopt_fetch_cache());
  EXPECT_EQ(stats.bytes_fetched, 128u);
  EXPECT_DOUBLE_EQ(stats.overfetch(), 128.0 / 48.0);
  // A direct-mapped cache of two 64-byte lines: lines 0 and 2 collide in set 0.
  const CacheConfig tiny{128, 64, 1, ReplacementPolicy::Lru, 1};
  const std::vector<std::uint32_t> ping = {0, 4, 0, 4};  // lines 0, 2, 0, 2 at 32 bytes
  EXPECT_EQ(simulate_vertex_fetch(ping, PrimitiveType::TriangleList, kNoRestart, 32, tiny).misses, 4u);
  // Restart indices are sent, not fetched.
  const std::vector<std::uint32_t> strip = {0, 1, 2, 0xFFFFFFFFu, 3, 4, 5};
  stats = simulate_vertex_fetch(strip, PrimitiveType::TriangleStrip, RestartIndex{0xFFFFFFFFu}, 32,
                                meshopt_fetch_cache());
  EXPECT_EQ(stats.fetches, 6u);
  EXPECT_EQ(stats.vertices, 6u);
  EXPECT_THROW(simulate_vertex_fetch(list, PrimitiveType::TriangleList, kNoRestart, 0, tiny), InputError);
}

TEST(VertexFetch, FetchCacheIsThePresetOrOneByteCache) {
  const CacheConfig meshopt = parse_fetch_cache("meshopt", "--fetch");
  EXPECT_EQ(meshopt.size_bytes, 128u * 1024u);
  EXPECT_EQ(meshopt.line_bytes, 64u);
  EXPECT_EQ(meshopt.assoc, 1u);
  const CacheConfig spec = parse_fetch_cache("size=16KiB,line=128B,assoc=4,policy=fifo", "--fetch");
  EXPECT_EQ(spec.size_bytes, 16u * 1024u);
  EXPECT_EQ(spec.line_bytes, 128u);
  EXPECT_EQ(spec.policy, ReplacementPolicy::Fifo);
  EXPECT_THROW(parse_fetch_cache("entries=16", "--fetch"), InputError);
  EXPECT_THROW(parse_fetch_cache("size=16KiB/32KiB", "--fetch"), InputError);
  EXPECT_THROW(parse_fetch_cache("meshop", "--fetch"), InputError);
}

// The face count an OFF header states (0 if unreadable): parsing every small mesh of the folder
// only to skip it would take most of the test's time.
std::size_t off_header_faces(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string token;
  std::size_t counts[3] = {0, 0, 0};
  int read = 0;
  while (read < 3 && in >> token) {
    if (token[0] == '#') {
      std::getline(in, token);
      continue;
    }
    if (token.find("OFF") != std::string::npos) continue;
    try {
      counts[read++] = std::stoul(token);
    } catch (const std::exception&) {
      return 0;
    }
  }
  return counts[1];
}

TEST(VertexFetch, BytesEqualMeshoptAnalyzeVertexFetchOnEveryCgalMeshInFourOrders) {
  int meshes = 0;
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(testing::data_file("meshes")))
    if (entry.path().extension() == ".off" && off_header_faces(entry.path()) >= 2000)
      names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  for (const std::string& name : names) {
    const Mesh& mesh = testing::cached_mesh(name);
    if (mesh.face_count() < 2000) continue;  // polygons fanned into triangles count here
    ++meshes;
    const std::size_t n = mesh.indices.size(), vertices = mesh.vertex_count();
    std::vector<std::uint32_t> forsyth(n), tipsy(n), shuffled = mesh.indices;
    meshopt_optimizeVertexCache(forsyth.data(), mesh.indices.data(), n, vertices);
    meshopt_optimizeVertexCacheFifo(tipsy.data(), mesh.indices.data(), n, vertices, 16);
    std::vector<std::uint32_t> faces(n / 3);
    for (std::uint32_t f = 0; f < faces.size(); ++f) faces[f] = f;
    std::shuffle(faces.begin(), faces.end(), std::mt19937(7));
    for (std::size_t f = 0; f < faces.size(); ++f)
      for (int k = 0; k < 3; ++k) shuffled[3 * f + k] = mesh.indices[3 * faces[f] + k];
    for (const std::vector<std::uint32_t>* order :
         std::initializer_list<const std::vector<std::uint32_t>*>{&mesh.indices, &forsyth, &tipsy, &shuffled})
      for (const std::uint32_t vertex_bytes : {32u, 12u, 48u}) {
        const VertexFetchStats ours =
            simulate_vertex_fetch(*order, PrimitiveType::TriangleList, kNoRestart, vertex_bytes, meshopt_fetch_cache());
        const meshopt_VertexFetchStatistics theirs = meshopt_analyzeVertexFetch(order->data(), n, vertices, vertex_bytes);
        ASSERT_EQ(ours.bytes_fetched, theirs.bytes_fetched) << name << " " << vertex_bytes << "-byte vertices";
        ASSERT_NEAR(ours.overfetch(), theirs.overfetch, 1e-5 * theirs.overfetch) << name;
      }
  }
  EXPECT_EQ(meshes, 54);
}

TEST(VertexFetch, FirstUseVertexOrderLowersTipsyFandiskFetch) {
  // Tipsy's order with the vertex buffer still in file order, then renumbered in first-use order
  // (meshopt_optimizeVertexFetchRemap): 3,320 lines instead of the 3,238 that hold the vertices,
  // a few read again after 2,048 others evicted them from the direct-mapped cache.
  const Mesh& mesh = testing::cached_mesh("fandisk.off");
  const std::size_t n = mesh.indices.size();
  std::vector<std::uint32_t> tipsy(n);
  meshopt_optimizeVertexCacheFifo(tipsy.data(), mesh.indices.data(), n, mesh.vertex_count(), 16);
  const VertexFetchStats before =
      simulate_vertex_fetch(tipsy, PrimitiveType::TriangleList, kNoRestart, 32, meshopt_fetch_cache());
  std::vector<std::uint32_t> remap(mesh.vertex_count());
  meshopt_optimizeVertexFetchRemap(remap.data(), tipsy.data(), n, mesh.vertex_count());
  for (std::uint32_t& index : tipsy) index = remap[index];
  const VertexFetchStats after =
      simulate_vertex_fetch(tipsy, PrimitiveType::TriangleList, kNoRestart, 32, meshopt_fetch_cache());
  EXPECT_EQ(before.vertices, 6475u);
  EXPECT_EQ(before.bytes_fetched, 3453u * 64u);  // 220,992 bytes
  EXPECT_EQ(after.bytes_fetched, 3320u * 64u);
  EXPECT_NEAR(after.overfetch(), 212480.0 / (6475.0 * 32.0), 1e-12);
  EXPECT_GT(before.overfetch(), after.overfetch());
}

}  // namespace
}  // namespace rastrace
