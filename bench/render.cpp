// Rendering speed: fragments per second for a 1024x768 trilinear textured frame of bunny00
// (75,408 triangles, a 1024x1024 checker of 32x32 squares on spherical UVs), rastrace without
// events, rastrace tracing every vertex fetch, texel access and framebuffer access into memory, and Mesa's OSMesa drawing the same frame
// with llvmpipe (LP_NUM_THREADS=0: single-threaded) and softpipe. Each OSMesa measurement runs
// in a child process (one Gallium driver per process) and reports its best of 5 frames in CPU
// time (the machine is shared: rastrace's rows are CPU time too), so the one-time LLVM
// compilation is not counted. Fragment rates use rastrace's count of shaded
// fragments for the frame (the same frame, the same coverage).
#include <benchmark/benchmark.h>

#include "pipeline/render_scene.h"
#include "reference/osmesa_renderer.h"
#include "scenes/bounding_box.h"
#include "scenes/mesh_io.h"
#include "scenes/procedural.h"
#include "scenes/scene_io.h"
#include "scenes/texture_io.h"
#include "traces/memory_sink.h"

namespace {

using namespace rastrace;

const Scene& bunny_frame() {
  static const Scene scene = [] {
    Scene s;
    s.name = "bunny00 checker 1024x768";
    s.width = 1024;
    s.height = 768;
    Texture checker;
    checker.levels = build_mip_chain(make_checker(1024, 32));
    s.textures.push_back(checker);
    SceneObject bunny;
    bunny.mesh = load_mesh(std::string(RASTRACE_DATA_DIR) + "/meshes/bunny00.off");
    project_uvs_spherical(bunny.mesh);
    Material material;
    material.texture = 0;
    bunny.mesh.materials = {material};
    bunny.mesh.face_material.clear();
    const BoundingBox box = bounding_box(bunny.mesh.positions);
    s.objects.push_back(bunny);
    s.camera = frame_bounds(box.lo, box.hi, 1024.0f / 768.0f);
    return s;
  }();
  return scene;
}

std::uint64_t frame_fragments() {
  static const std::uint64_t fragments = render_scene(bunny_frame(), RenderOptions{}, nullptr).raster.fragments_passed;
  return fragments;
}

void report(benchmark::State& state, std::uint64_t fragments) {
  state.counters["fragments"] = static_cast<double>(fragments);
  state.counters["fragments_per_second"] =
      benchmark::Counter(static_cast<double>(fragments), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Rastrace(benchmark::State& state) {
  const Scene& scene = bunny_frame();
  RenderOptions options;
  options.pipeline.raster.traversal = state.range(0) ? Traversal::Tiled8 : Traversal::Scanline;
  std::uint64_t fragments = 0;
  for (auto _ : state) {
    const RenderResult result = render_scene(scene, options, nullptr);
    fragments = result.raster.fragments_passed;
    benchmark::DoNotOptimize(result.framebuffer.colour());
  }
  report(state, fragments);
}
BENCHMARK(BM_Rastrace)->ArgName("tiled")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_RastraceTracingToMemory(benchmark::State& state) {
  const Scene& scene = bunny_frame();
  RenderOptions options;
  MemorySink sink;
  std::uint64_t fragments = 0, events = 0;
  for (auto _ : state) {
    state.PauseTiming();
    sink.fetches.clear();  // keep the capacity: the frame's events are stored, not reallocated
    sink.texels.clear();
    sink.framebuffer.clear();
    sink.draws.clear();
    sink.draw_first_fetch.clear();
    state.ResumeTiming();
    const RenderResult result = render_scene(scene, options, &sink);
    fragments = result.raster.fragments_passed;
    events = sink.fetches.size() + sink.texels.size() + sink.framebuffer.size();
  }
  report(state, fragments);
  state.counters["events"] = static_cast<double>(events);
}
BENCHMARK(BM_RastraceTracingToMemory)->Unit(benchmark::kMillisecond);

void BM_OSMesa(benchmark::State& state) {
  ReferenceOptions options;
  options.driver = state.range(0) ? ReferenceDriver::Llvmpipe : ReferenceDriver::Softpipe;
  options.llvmpipe_threads = 0;
  options.frames = 5;
  std::string renderer;
  for (auto _ : state) {
    const ReferenceImage image = render_reference(bunny_frame(), options);
    state.SetIterationTime(image.best_frame_cpu_seconds);
    renderer = image.renderer;
  }
  state.SetLabel(renderer);
  report(state, frame_fragments());
}
BENCHMARK(BM_OSMesa)
    ->ArgName("llvmpipe")
    ->Arg(0)
    ->Arg(1)
    ->UseManualTime()
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond);

}  // namespace
