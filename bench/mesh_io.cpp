// Mesh loading and writing speed on CGAL's bunny00.off (37,706 vertices, 75,408 faces), and mip
// chain construction. Target: loading the bunny well under a second in Release.
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>
#include <unistd.h>

#include "scenes/mesh_io.h"
#include "scenes/texture_io.h"

namespace {

std::string bunny() { return std::string(RASTRACE_DATA_DIR) + "/meshes/bunny00.off"; }

std::string temp(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("rastrace_bench_" + std::to_string(::getpid()) + name)).string();
}

void BM_LoadOff(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(rastrace::load_mesh(bunny()));
}
BENCHMARK(BM_LoadOff)->Unit(benchmark::kMillisecond);

void BM_LoadFormat(benchmark::State& state, const char* extension, bool ascii) {
  const std::string path = temp(extension);
  rastrace::save_mesh(rastrace::load_mesh(bunny()), path, rastrace::MeshWriteOptions{.ascii = ascii});
  for (auto _ : state) benchmark::DoNotOptimize(rastrace::load_mesh(path));
  std::filesystem::remove(path);
}
BENCHMARK_CAPTURE(BM_LoadFormat, binary_ply, ".ply", false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadFormat, ascii_ply, ".ply", true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadFormat, obj, ".obj", false)->Unit(benchmark::kMillisecond);

void BM_SaveOff(benchmark::State& state) {
  const rastrace::Mesh mesh = rastrace::load_mesh(bunny());
  const std::string path = temp(".off");
  for (auto _ : state) rastrace::save_mesh(mesh, path);
  std::filesystem::remove(path);
}
BENCHMARK(BM_SaveOff)->Unit(benchmark::kMillisecond);

void BM_MipChain(benchmark::State& state) {
  const rastrace::Image base = rastrace::make_checker(static_cast<int>(state.range(0)), 16);
  for (auto _ : state) benchmark::DoNotOptimize(rastrace::build_mip_chain(base));
}
BENCHMARK(BM_MipChain)->Arg(1024)->Arg(1023)->Unit(benchmark::kMillisecond);

}  // namespace
