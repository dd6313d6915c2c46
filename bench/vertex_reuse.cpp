// Vertex reuse models (docs/PERFORMANCE.md, "Vertex reuse models"):
//   - meshoptimizer's warp FIFO (cache_sim/warp_fifo.h) at its four profiles against
//     meshopt_analyzeVertexCache with the same (cache, warp, primgroup) on the same index buffer,
//     in the same binary: the ratio of the two rates is the figure (goal: >= 0.8)
//   - Kerbl et al.'s batch models (cache_sim/kerbl_batch.h), NVIDIA, AMD and Intel, on the same
//     buffer (no peer: the paper's simulator is a hash-map model for Windows; ours must simply not
//     be the bottleneck of a table, goal 50 M indices/s)
//   - the batch-aware order (reorder/batch.cpp) against Tipsy, both on bunny00
// Input: CGAL's bunny00 (75,408 triangles) in meshoptimizer's vertex cache order.
#include <meshoptimizer.h>

#include <algorithm>

#include <benchmark/benchmark.h>

#include "cache_sim/vertex_reuse.h"
#include "reorder/ordering.h"
#include "scenes/mesh_io.h"

namespace rastrace {
namespace {

const Mesh& bunny() {
  static const Mesh mesh = load_mesh(RASTRACE_DATA_DIR "/meshes/bunny00.off");
  return mesh;
}

const std::vector<std::uint32_t>& bunny_indices() {
  static const std::vector<std::uint32_t> indices = [] {
    std::vector<std::uint32_t> out(bunny().indices.size());
    meshopt_optimizeVertexCache(out.data(), bunny().indices.data(), out.size(), bunny().positions.size());
    return out;
  }();
  return indices;
}

struct Profile {
  const char* name;
  unsigned cache, warp, primgroup;
};
constexpr Profile kProfiles[] = {{"nv-pascal", 32, 32, 32}, {"nv-maxwell", 16, 32, 32}, {"amd-gcn", 14, 64, 128},
                                 {"intel", 128, 0, 0}};

void BM_WarpFifo_Rastrace(benchmark::State& state) {
  const Profile& p = kProfiles[state.range(0)];
  const VertexCacheSpec spec = vertex_cache_spec(VertexCachePolicy::Fifo, p.cache, p.warp, p.primgroup);
  const auto& indices = bunny_indices();
  for (auto _ : state) {
    const VertexStreamStats s = simulate_vertex_reuse(indices, PrimitiveType::TriangleList, spec);
    benchmark::DoNotOptimize(s.misses);
  }
  state.SetLabel(p.name);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * indices.size()));
}
BENCHMARK(BM_WarpFifo_Rastrace)->DenseRange(0, 3);

void BM_WarpFifo_Meshopt(benchmark::State& state) {
  const Profile& p = kProfiles[state.range(0)];
  const auto& indices = bunny_indices();
  for (auto _ : state) {
    const meshopt_VertexCacheStatistics s = meshopt_analyzeVertexCache(indices.data(), indices.size(),
                                                                       bunny().positions.size(), p.cache, p.warp,
                                                                       p.primgroup);
    benchmark::DoNotOptimize(s.vertices_transformed);
  }
  state.SetLabel(p.name);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * indices.size()));
}
BENCHMARK(BM_WarpFifo_Meshopt)->DenseRange(0, 3);

void BM_KerblBatch(benchmark::State& state) {
  const char* names[] = {"kerbl-nv", "kerbl-amd", "kerbl-intel"};
  const VertexCacheSpec& spec = find_vertex_reuse_preset(names[state.range(0)])->spec;
  const auto& indices = bunny_indices();
  for (auto _ : state) {
    const VertexStreamStats s = simulate_vertex_reuse(indices, PrimitiveType::TriangleList, spec);
    benchmark::DoNotOptimize(s.misses);
  }
  state.SetLabel(names[state.range(0)]);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * indices.size()));
}
BENCHMARK(BM_KerblBatch)->DenseRange(0, 2);

void BM_Order(benchmark::State& state) {
  const char* names[] = {"batch", "tipsy"};
  const ReorderAlgorithm& algorithm = find_reorder_algorithm(names[state.range(0)]);
  for (auto _ : state) {
    const Ordering ordering = algorithm.run(bunny(), ReorderParams{});
    benchmark::DoNotOptimize(ordering.indices.data());
  }
  state.SetLabel(names[state.range(0)]);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * bunny().face_count()));
}
BENCHMARK(BM_Order)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rastrace
