// The vertex reuse models of cache_sim/vertex_reuse.h: meshoptimizer's warp FIFO against
// meshopt_analyzeVertexCache itself (same process) on every CGAL mesh of at least 2,000 faces, and
// Kerbl et al. 2018's batch models against the behaviour they measured and documented.
#include <meshoptimizer.h>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "cache_sim/cache_spec.h"
#include "cache_sim/live_bank_sink.h"
#include "cache_sim/vertex_reuse.h"
#include "core/error.h"
#include "tests/support/test_data.h"
#include "tests/support/test_meshes.h"

namespace rastrace {
namespace {

std::vector<std::string> cgal_meshes_of_at_least(std::size_t faces) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(testing::data_file("meshes")))
    if (entry.path().extension() == ".off") names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  std::vector<std::string> large;
  for (const std::string& name : names) {
    try {
      if (testing::cached_mesh(name).face_count() >= faces) large.push_back(name);
    } catch (const InputError&) {
      // A few of CGAL's test files are deliberately malformed (prim.off); none is that large.
    }
  }
  return large;
}

TEST(WarpFifo, MissesAndWarpsEqualMeshoptAnalyzeVertexCacheOnEveryCgalMeshInFourOrders) {
  const std::vector<std::string> meshes = cgal_meshes_of_at_least(2000);
  ASSERT_GE(meshes.size(), 50u);  // 54 with the CGAL demo data of Debian 12
  struct Profile {
    unsigned cache, warp, primgroup;
  };
  // meshoptimizer's four profiles (nv-pascal, nv-maxwell, amd-gcn, intel), then no warp or group.
  const Profile profiles[] = {{32, 32, 32}, {16, 32, 32}, {14, 64, 128}, {128, 0, 0}, {16, 0, 0}};
  std::size_t compared = 0;
  for (const std::string& name : meshes) {
    const Mesh& mesh = testing::cached_mesh(name);
    const std::size_t n = mesh.indices.size(), vertices = mesh.positions.size();
    std::vector<std::uint32_t> forsyth(n), tipsy(n), shuffled = mesh.indices;
    meshopt_optimizeVertexCache(forsyth.data(), mesh.indices.data(), n, vertices);
    meshopt_optimizeVertexCacheFifo(tipsy.data(), mesh.indices.data(), n, vertices, 16);
    std::mt19937 rng(7);
    for (std::size_t t = n / 3; t > 1; --t) {
      const std::size_t u = rng() % t;
      std::swap_ranges(shuffled.begin() + 3 * (t - 1), shuffled.begin() + 3 * t, shuffled.begin() + 3 * u);
    }
    for (const std::vector<std::uint32_t>* order :
         std::initializer_list<const std::vector<std::uint32_t>*>{&mesh.indices, &forsyth, &tipsy, &shuffled})
      for (const Profile& p : profiles) {
        const VertexCacheSpec spec = vertex_cache_spec(VertexCachePolicy::Fifo, p.cache, p.warp, p.primgroup);
        const VertexStreamStats ours = simulate_vertex_reuse(*order, PrimitiveType::TriangleList, spec);
        const meshopt_VertexCacheStatistics theirs =
            meshopt_analyzeVertexCache(order->data(), n, vertices, p.cache, p.warp, p.primgroup);
        ASSERT_EQ(ours.misses, theirs.vertices_transformed) << name << " " << vertex_reuse_name(spec);
        ASSERT_EQ(ours.warps, theirs.warps_executed) << name << " " << vertex_reuse_name(spec);
        ++compared;
      }
  }
  EXPECT_EQ(compared, meshes.size() * 4 * 5);
}

TEST(WarpFifo, LiveBankCountsWhatTheStreamSimulationCounts) {
  // The renderer's and the replay's path: fetches one by one, primitives assembled in the bank.
  const Mesh& mesh = testing::cached_mesh("fandisk.off");
  CacheBankConfig config;
  for (const VertexReusePreset& preset : vertex_reuse_presets()) config.vertex.push_back(preset.spec);
  LiveBankSink bank(config, {});
  bank.begin_draw({0, PrimitiveType::TriangleList, kNoRestart});
  std::vector<VertexFetch> fetches;
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) fetches.push_back({mesh.indices[i], i % 3 == 0});
  bank.vertex_fetches(fetches);
  bank.end_draw();
  bank.finish();
  for (std::size_t i = 0; i < config.vertex.size(); ++i) {
    const VertexStreamStats direct = simulate_vertex_reuse(mesh.indices, PrimitiveType::TriangleList, config.vertex[i]);
    EXPECT_EQ(bank.vertex_stats()[i].misses, direct.misses) << config.vertex[i].preset;
    EXPECT_EQ(bank.vertex_stats()[i].warps, direct.warps) << config.vertex[i].preset;
    EXPECT_EQ(bank.vertex_stats()[i].lane_slots, direct.lane_slots) << config.vertex[i].preset;
  }
}

VertexStreamStats kerbl(const char* preset, const std::vector<std::uint32_t>& indices) {
  return simulate_vertex_reuse(indices, PrimitiveType::TriangleList, find_vertex_reuse_preset(preset)->spec);
}

TEST(KerblBatch, RepeatedTriangleIsShadedThreeTimesUpTo96IndicesAndSixAt99OnNvidia) {
  // Kerbl et al. 2018, section 4: the pattern 0,1,2,0,1,2,... on NVIDIA GPUs.
  for (const char* preset : {"kerbl-nv", "kerbl-nv-gl"}) {
    std::vector<std::uint32_t> indices;
    for (unsigned n = 3; n <= 99; n += 3) {
      indices.insert(indices.end(), {0, 1, 2});
      const VertexStreamStats stats = kerbl(preset, indices);
      EXPECT_EQ(stats.misses, n <= 96 ? 3u : 6u) << preset << " at " << n << " indices";
      EXPECT_EQ(stats.warps, n <= 96 ? 1u : 2u) << preset << " at " << n << " indices";
    }
  }
}

TEST(KerblBatch, BatchLimitsOfEachVendorOnTrianglesWithoutSharedVertices) {
  // 384 indices of unshared triangles: no reuse, so the batch limits alone decide the batches.
  std::vector<std::uint32_t> indices(384);
  std::iota(indices.begin(), indices.end(), 0u);
  // NVIDIA: 10 triangles (30 vertices) per batch, the 11th would make 33: 13 batches, 30/32 lanes.
  const VertexStreamStats nv = kerbl("kerbl-nv", indices);
  EXPECT_EQ(nv.misses, 384u);
  EXPECT_EQ(nv.warps, 13u);
  EXPECT_NEAR(nv.lane_use(), 384.0 / (13 * 32), 1e-12);
  // AMD: cut at the 64th vertex even inside a triangle: 6 full waves of 64.
  const VertexStreamStats amd = kerbl("kerbl-amd", indices);
  EXPECT_EQ(amd.warps, 6u);
  EXPECT_DOUBLE_EQ(amd.lane_use(), 1.0);
  // Intel: 42 triangles (126 vertices) per batch, 16 SIMD8 threads each; the last batch has 6.
  const VertexStreamStats intel = kerbl("kerbl-intel", indices);
  EXPECT_EQ(intel.warps, 3 * 16u + 1u);
}

TEST(KerblBatch, NvidiaReusesAVertexOnlyWhileItsLastUseIsWithinTheWindow) {
  // Vertex 0 at position 0, then `gap` triangles of a strip-like run (3 + t, 4 + t, 5 + t: one new
  // vertex each after the first), then 0 again at position 3 + 3 * gap: 42 indices back is reused
  // (GL: <= 42; D3D, a first corner: < 45), 45 back is shaded again. All in one batch.
  for (const char* preset : {"kerbl-nv", "kerbl-nv-gl"})
    for (const std::uint32_t gap : {13u, 14u}) {
      std::vector<std::uint32_t> indices = {0, 1, 2};
      for (std::uint32_t t = 0; t < gap; ++t) indices.insert(indices.end(), {3 + t, 4 + t, 5 + t});
      indices.insert(indices.end(), {0, 1000, 1001});
      const std::uint64_t expected = 3 + (gap + 2) + (gap == 13 ? 2 : 3);
      EXPECT_EQ(kerbl(preset, indices).misses, expected) << preset << " gap " << gap;
      EXPECT_EQ(kerbl(preset, indices).warps, 1u) << preset << " gap " << gap;
    }
}

TEST(KerblBatch, AgreesWithThePublishedSimulatorOnCgalMeshes) {
  // Shader invocations of the paper's simulator (GPUPeople/vertex_batch_optimization,
  // simulateInvocations) for the same index buffers, file order: NVIDIA D3D, NVIDIA GL, AMD, Intel.
  struct Expected {
    const char* mesh;
    std::uint64_t nv, nv_gl, amd, intel;
  };
  for (const Expected& e : {Expected{"fandisk.off", 14064, 14062, 13406, 13088},
                            Expected{"elephant.off", 12903, 12891, 12875, 11533}}) {
    const Mesh& mesh = testing::cached_mesh(e.mesh);
    EXPECT_EQ(kerbl("kerbl-nv", mesh.indices).misses, e.nv) << e.mesh;
    EXPECT_EQ(kerbl("kerbl-nv-gl", mesh.indices).misses, e.nv_gl) << e.mesh;
    EXPECT_EQ(kerbl("kerbl-amd", mesh.indices).misses, e.amd) << e.mesh;
    EXPECT_EQ(kerbl("kerbl-intel", mesh.indices).misses, e.intel) << e.mesh;
  }
}

TEST(VertexReuseSpec, PresetsCarryTheirFullParameters) {
  const std::vector<VertexCacheSpec> all = vertex_caches(parse_cache_spec("model=all", "--cache"));
  ASSERT_EQ(all.size(), 8u);
  EXPECT_EQ(all[0].preset, "nv-pascal");
  EXPECT_EQ(all[0].entries, 32u);
  EXPECT_EQ(all[0].warp, 32u);
  EXPECT_EQ(all[0].primgroup, 32u);
  EXPECT_EQ(all[2].preset, "amd-gcn");
  EXPECT_EQ(all[2].entries, 14u);
  EXPECT_EQ(all[2].warp, 64u);
  EXPECT_EQ(all[2].primgroup, 128u);
  EXPECT_EQ(all[3].preset, "intel");
  EXPECT_EQ(all[3].entries, 128u);
  EXPECT_EQ(all[3].kind, VertexReuseKind::Cache);
  EXPECT_EQ(all[4].kind, VertexReuseKind::KerblBatch);
  EXPECT_EQ(format_cache_spec(all[4]), "model=kerbl-nv");
  const std::vector<VertexCacheSpec> spelled =
      vertex_caches(parse_cache_spec("entries=16/32,warp=32,primgroup=0/32", "--cache"));
  ASSERT_EQ(spelled.size(), 4u);
  EXPECT_EQ(vertex_reuse_name(spelled[3]), "entries=32,policy=fifo,warp=32,primgroup=32");
  EXPECT_EQ(vertex_reuse_parameters(spelled[1]), "FIFO 16 entries, flushed per warp of 32 vertices or 32 primitives");
}

TEST(VertexReuseSpec, BadCombinationsAreErrorsThatSayWhatToWrite) {
  const auto message = [](const std::string& text) {
    try {
      parse_cache_spec(text, "--cache");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("model=nv-pascal,entries=16").find("drop entries="), std::string::npos);
  EXPECT_NE(message("model=kerbl-nv,policy=lru").find("drop policy="), std::string::npos);
  EXPECT_NE(message("model=nv-volta").find("nv-pascal, nv-maxwell, amd-gcn"), std::string::npos);
  EXPECT_NE(message("entries=16,policy=lru,warp=32").find("expected policy=fifo"), std::string::npos);
  EXPECT_NE(message("entries=16,warp=2").find("3..1024"), std::string::npos);
  EXPECT_NE(message("warp=32").find("missing entries="), std::string::npos);
  EXPECT_NE(message("model=kerbl-nv,size=16KiB").find("cannot be mixed"), std::string::npos);
}

}  // namespace
}  // namespace rastrace
