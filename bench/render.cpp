// Rendering speed against Mesa's OSMesa on the same frames, in the same run. Three 1024x768
// trilinear frames: bunny00 with a 1024x1024 checker of 32x32 squares on spherical UVs (75,408
// triangles, small ones), assimp's spider with its own textures, and a checkered plane seen at a
// grazing angle (few large triangles, deep minification). The bunny frame again with its texture
// stored as BC1 and BC7 (one thread and every core, untraced), and BM_TextureCodec: encoding and
// decoding a 1024x1024 level in each compressed format.
//
// Rows: llvmpipe with one thread (LP_NUM_THREADS=0) and with every core (LP_NUM_THREADS = the core
// count), softpipe, each in a child process (one Gallium driver per process, the environment set
// before the context is created) reporting its best of 5 frames, so LLVM's one-time compilation is
// not counted; rastrace with one thread and with every core, untraced, tracing every event into
// memory (MemorySink) and into a trace file (TraceWriter, zstd). Times are wall-clock (multi-threaded
// rows could not be compared otherwise); every row's time is its best frame, the fairest figure on a
// loaded machine. Each rastrace row carries its ratios to the frames it is judged against, measured
// around the row's own frames, so that both sides of a ratio see the same machine (on a shared
// machine a best frame drifts by a third from one minute to the next):
// - vs_llvmpipe_1t (one-thread rows) or vs_llvmpipe_every_core (every-core rows): llvmpipe with the
//   row's threads (LP_NUM_THREADS=0, or the core count), its best of 5 frames just before the row's
//   frames and 5 just after, over rastrace's best frame; one-thread rows add vs_llvmpipe_1t_cpu,
//   the same ratio in CPU time;
// - vs_untraced (traced rows): the row's best frame over the best of as many untraced frames with
//   the same threads, rendered one after each traced frame.
// Each rastrace row first renders one untimed frame (first_frame_cpu_ms: its process CPU time),
// which grows the buffers the timed frames reuse, as llvmpipe's best of 5 leaves out its first
// frame. Fragment rates use rastrace's count of fragments written for the frame (the same frame,
// the same coverage).
// BM_TraceStoreFloor, registered last, is what tracing a frame into memory costs at the least on
// this machine: the frame's event bytes written by one thread with streaming stores (the
// recorders' stores, without the recording), against the untraced one-thread frame. It runs after
// every other row: measured inside the rows, its tens of megabytes of fresh memory made some of
// the llvmpipe frames measured after it twice as fast (on a KVM guest), which no ratio may see.
// RASTRACE_BENCH_FRAMES sets the rastrace rows' timed frames (default 8; more to profile them).
#include <benchmark/benchmark.h>

#include <time.h>

#include <unistd.h>
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <glm/ext/matrix_transform.hpp>

#include "core/streaming_copy.h"
#include "pipeline/render_scene.h"
#include "reference/osmesa_renderer.h"
#include "scenes/bounding_box.h"
#include "scenes/builtin_scenes.h"
#include "scenes/mesh_io.h"
#include "scenes/procedural.h"
#include "scenes/scene_io.h"
#include "scenes/texture_io.h"
#include "texcodec/codec.h"
#include "traces/memory_sink.h"
#include "traces/trace_writer.h"

namespace {

using namespace rastrace;

constexpr int kWidth = 1024, kHeight = 768;
constexpr const char* kSceneNames[] = {"bunny", "spider", "grazing_plane", "bunny bc1", "bunny bc7"};

// The bunny frame with its checker stored as `format` (decoded at load: the sampler reads decoded
// texels, so only the texels' values differ from RGBA8).
Scene bunny_frame(TextureFormat format = TextureFormat::Rgba8) {
  Scene s;
  s.name = std::string("bunny00 checker 1024x768 ") + to_string(format);
  s.width = kWidth;
  s.height = kHeight;
  Texture checker;
  checker.levels = build_mip_chain(make_checker(1024, 32));
  s.textures.push_back(compress_texture(checker, format));
  SceneObject bunny;
  bunny.mesh = load_mesh(std::string(RASTRACE_DATA_DIR) + "/meshes/bunny00.off");
  project_uvs_spherical(bunny.mesh);
  Material material;
  material.texture = 0;
  bunny.mesh.materials = {material};
  bunny.mesh.face_material.clear();
  const BoundingBox box = bounding_box(bunny.mesh.positions);
  s.objects.push_back(bunny);
  s.camera = frame_bounds(box.lo, box.hi, static_cast<float>(kWidth) / kHeight);
  return s;
}

Scene spider_frame() {
  Scene s = make_builtin_scene("spider");
  s.width = kWidth;
  s.height = kHeight;
  const BoundingBox box = bounding_box(s);
  s.camera = frame_bounds(box.lo, box.hi, static_cast<float>(kWidth) / kHeight);
  return s;
}

// A 64x64-cell plane 80 units wide under a 1024x1024 checker, the camera 1 unit above it looking
// 14 units ahead: most of the frame is minified across many mip levels.
Scene grazing_plane_frame() {
  Scene s;
  s.name = "grazing plane 1024x768";
  s.width = kWidth;
  s.height = kHeight;
  Texture checker;
  checker.levels = build_mip_chain(make_checker(1024, 32));
  s.textures.push_back(checker);
  SceneObject plane;
  plane.mesh = make_plane(64, 32.0f);
  Material material;
  material.texture = 0;
  plane.mesh.materials = {material};
  plane.mesh.face_material.clear();
  plane.transform = glm::scale(glm::mat4(1.0f), glm::vec3(40.0f, 1.0f, 40.0f));
  s.objects.push_back(plane);
  s.camera.eye = glm::vec3(0.3f, 1.0f, 38.0f);
  s.camera.target = glm::vec3(0.0f, 0.0f, 24.0f);
  s.camera.fov_y_degrees = 60.0f;
  s.camera.near_plane = 0.5f;
  s.camera.far_plane = 100.0f;
  return s;
}

const Scene& frame(std::int64_t index) {
  static const Scene scenes[] = {bunny_frame(), spider_frame(), grazing_plane_frame(), bunny_frame(TextureFormat::Bc1),
                                 bunny_frame(TextureFormat::Bc7)};
  return scenes[index];
}

unsigned all_cores() { return std::max(1u, std::thread::hardware_concurrency()); }

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct BestFrame {
  double wall = 0.0;
  double cpu = 0.0;
};

BestFrame osmesa_frame(std::int64_t scene, ReferenceDriver driver, int llvmpipe_threads, std::string* renderer) {
  ReferenceOptions options;
  options.driver = driver;
  options.llvmpipe_threads = llvmpipe_threads;
  options.frames = 5;
  const ReferenceImage image = render_reference(frame(scene), options);
  if (renderer) *renderer = image.renderer;
  return {image.best_frame_seconds, image.best_frame_cpu_seconds};
}

// llvmpipe's best of 5 frames of the scene, now, with one thread or every core.
BestFrame llvmpipe_frame(std::int64_t scene, bool every_core) {
  return osmesa_frame(scene, ReferenceDriver::Llvmpipe, every_core ? static_cast<int>(all_cores()) : 0, nullptr);
}

BestFrame best_of(const BestFrame& a, const BestFrame& b) { return {std::min(a.wall, b.wall), std::min(a.cpu, b.cpu)}; }

// The least time one thread takes to write `bytes` into memory written before (as a MemorySink's
// storage is from frame to frame), with the streaming stores the recorders use: best of 5, each a
// 64 KiB block (in the L2) copied over the whole buffer. What tracing a frame's events into memory
// must cost at the least, however little the recording itself did.
double streaming_store_seconds(std::size_t bytes) {
  constexpr std::size_t kBlock = 64 << 10;
  const std::vector<unsigned char> block(kBlock, 0x5A);
  std::vector<unsigned char> buffer(bytes, 0);  // zeroed: every page is touched before timing
  double best = 1e30;
  for (int round = 0; round < 5; ++round) {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t at = 0; at < bytes; at += kBlock)
      copy_bytes_streaming(buffer.data() + at, block.data(), std::min(kBlock, bytes - at));
    streaming_fence();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  benchmark::DoNotOptimize(buffer.data());
  return best;
}

std::uint64_t frame_fragments(std::int64_t scene) {
  static std::map<std::int64_t, std::uint64_t> counted;
  auto it = counted.find(scene);
  if (it == counted.end())
    it = counted.emplace(scene, render_scene(frame(scene), RenderOptions{}, nullptr).raster.fragments_passed).first;
  return it->second;
}

void report(benchmark::State& state, std::uint64_t fragments, double best_seconds) {
  state.counters["fragments"] = static_cast<double>(fragments);
  state.counters["fragments_per_second"] = static_cast<double>(fragments) / best_seconds;
  state.counters["best_frame_ms"] = best_seconds * 1e3;
}

// Timed frames per rastrace row: 8, or RASTRACE_BENCH_FRAMES (1 to 10000). A profile of the
// steady state wants many: --benchmark_repetitions renders the untimed first frame again in every
// repetition, and a traced first frame (page faults, buffers growing) costs several later ones.
std::int64_t timed_frames() {
  const char* text = std::getenv("RASTRACE_BENCH_FRAMES");
  if (!text) return 8;
  const std::string_view value(text);
  std::int64_t frames = 0;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), frames);
  if (error != std::errc() || end != value.data() + value.size() || frames < 1 || frames > 10000) {
    std::fprintf(stderr, "RASTRACE_BENCH_FRAMES=%s: expected a whole number of frames from 1 to 10000\n", text);
    std::exit(2);
  }
  return frames;
}

// Arguments: scene, threads (0: one, 1: every core), tracing (0: none, 1: memory, 2: file).
void BM_Rastrace(benchmark::State& state) {
  const std::int64_t scene_index = state.range(0);
  const Scene& scene = frame(scene_index);
  const bool every_core = state.range(1) != 0;
  const std::int64_t tracing = state.range(2);
  BestFrame llvmpipe = llvmpipe_frame(scene_index, every_core);
  RenderOptions options;
  options.pipeline.raster.threads = every_core ? all_cores() : 1;
  MemorySink memory;
  const std::string path =
      (std::filesystem::temp_directory_path() / ("bench_render_" + std::to_string(getpid()) + ".rtrace")).string();
  TraceMetadata metadata;
  metadata.scene = scene.name;
  metadata.width = static_cast<std::uint32_t>(scene.width);
  metadata.height = static_cast<std::uint32_t>(scene.height);
  metadata.textures = texture_levels(scene);
  BestFrame best{1e30, 1e30};
  std::uint64_t fragments = 0, events = 0, file_bytes = 0;
  // The render target is kept from frame to frame, as llvmpipe's context keeps its own.
  Framebuffer framebuffer(scene.width, scene.height);
  // One frame, traced as `into` says (0: untraced, 1: memory, 2: file): its wall-clock and process
  // CPU seconds.
  auto render_frame = [&](std::int64_t into) -> BestFrame {
    memory.clear();  // keeps the capacity: the frame's events are stored, not reallocated
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = process_cpu_seconds();
    if (into == 2) {
      TraceWriter writer(path, metadata);
      fragments = render_scene_into(framebuffer, scene, options, &writer).raster.fragments_passed;
      file_bytes = writer.bytes_written();
    } else {
      fragments = render_scene_into(framebuffer, scene, options, into == 1 ? &memory : nullptr).raster.fragments_passed;
      benchmark::DoNotOptimize(framebuffer.colour());
    }
    const double cpu = process_cpu_seconds() - cpu_start;
    return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), cpu};
  };
  // The first frame of a process also grows the sink's buffers and the rasterizer's (which are
  // kept for the next frames, as an application rendering frame after frame keeps them): it is
  // reported on its own, and the timed frames are the ones after it.
  const BestFrame first = render_frame(tracing);
  BestFrame untraced{1e30, 1e30};
  for (auto _ : state) {
    const BestFrame f = render_frame(tracing);
    state.SetIterationTime(f.wall);
    best = best_of(best, f);
    events = memory.fetches.size() + memory.texels.size() + memory.framebuffer.size();
    if (tracing != 0) untraced = best_of(untraced, render_frame(0));  // not timed: the time is manual
  }
  llvmpipe = best_of(llvmpipe, llvmpipe_frame(scene_index, every_core));
  std::filesystem::remove(path);
  report(state, fragments, best.wall);
  state.counters["threads"] = static_cast<double>(options.pipeline.raster.threads);
  state.counters["process_cpu_ms"] = best.cpu * 1e3;       // all of rastrace's threads
  state.counters["first_frame_cpu_ms"] = first.cpu * 1e3;  // growing the buffers the next frames reuse
  if (every_core) {
    state.counters["vs_llvmpipe_every_core"] = llvmpipe.wall / best.wall;
  } else {
    state.counters["vs_llvmpipe_1t"] = llvmpipe.wall / best.wall;
    state.counters["vs_llvmpipe_1t_cpu"] = llvmpipe.cpu / best.cpu;
  }
  if (tracing != 0) state.counters["vs_untraced"] = best.wall / untraced.wall;
  if (tracing == 1) state.counters["events"] = static_cast<double>(events);
  if (tracing == 2) state.counters["file_bytes"] = static_cast<double>(file_bytes);
  state.SetLabel(std::string(kSceneNames[scene_index]) + (every_core ? " every core" : " one thread") +
                 (tracing == 0   ? " untraced"
                  : tracing == 1 ? " traced to memory"
                                 : " traced to file"));
}
BENCHMARK(BM_Rastrace)
    ->ArgNames({"scene", "every_core", "trace"})
    ->ArgsProduct({{0, 1, 2}, {0, 1}, {0, 1, 2}})
    ->UseManualTime()
    ->Iterations(timed_frames())
    ->Unit(benchmark::kMillisecond);
// The bunny frame with BC1 and BC7 textures, to set beside the rows of scene 0 (RGBA8).
BENCHMARK(BM_Rastrace)
    ->ArgNames({"scene", "every_core", "trace"})
    ->ArgsProduct({{3, 4}, {0, 1}, {0}})
    ->UseManualTime()
    ->Iterations(timed_frames())
    ->Unit(benchmark::kMillisecond);

// Encoding then decoding one 1024x1024 level (a gradient with noise, so no block is flat) in
// each compressed format: the load-time cost of a compressed texture's base level.
void BM_TextureCodec(benchmark::State& state) {
  const auto format = static_cast<TextureFormat>(state.range(0));
  static const Image image = [] {
    Image noisy = make_uv_gradient(1024);
    std::uint32_t seed = 1;
    for (std::uint8_t& v : noisy.rgba) {
      seed = seed * 1664525u + 1013904223u;
      v = static_cast<std::uint8_t>(std::clamp(int(v) + int(seed >> 28) - 8, 0, 255));
    }
    return noisy;
  }();
  double encode = 1e30, decode = 1e30;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<std::uint8_t> blocks = texcodec::encode_level(format, image.width, image.height, image.rgba);
    const auto middle = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(texcodec::decode_level(format, image.width, image.height, blocks).data());
    const auto end = std::chrono::steady_clock::now();
    encode = std::min(encode, std::chrono::duration<double>(middle - start).count());
    decode = std::min(decode, std::chrono::duration<double>(end - middle).count());
    state.SetIterationTime(std::chrono::duration<double>(end - start).count());
  }
  state.counters["encode_ms"] = encode * 1e3;
  state.counters["decode_ms"] = decode * 1e3;
  state.SetLabel(std::string(to_string(format)) + " 1024x1024");
}
BENCHMARK(BM_TextureCodec)
    ->ArgName("format")
    ->DenseRange(static_cast<int>(TextureFormat::Bc1), static_cast<int>(TextureFormat::Astc8x8))
    ->UseManualTime()
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond);

// Arguments: scene, driver (0: softpipe, 1: llvmpipe one thread, 2: llvmpipe every core).
void BM_OSMesa(benchmark::State& state) {
  const std::int64_t scene_index = state.range(0);
  const std::int64_t driver = state.range(1);
  std::string renderer;
  BestFrame best{1e30, 1e30};
  for (auto _ : state) {
    const BestFrame f = driver == 0 ? osmesa_frame(scene_index, ReferenceDriver::Softpipe, -1, &renderer)
                                    : osmesa_frame(scene_index, ReferenceDriver::Llvmpipe,
                                                   driver == 1 ? 0 : static_cast<int>(all_cores()), &renderer);
    state.SetIterationTime(f.wall);
    best.wall = std::min(best.wall, f.wall);
    best.cpu = std::min(best.cpu, f.cpu);
  }
  state.SetLabel(std::string(kSceneNames[scene_index]) + " " + renderer +
                 (driver == 0   ? ""
                  : driver == 1 ? " LP_NUM_THREADS=0"
                                : " LP_NUM_THREADS=" + std::to_string(all_cores())));
  report(state, frame_fragments(scene_index), best.wall);
  state.counters["cpu_ms"] = best.cpu * 1e3;
}
BENCHMARK(BM_OSMesa)
    ->ArgNames({"scene", "driver"})
    ->ArgsProduct({{0, 1, 2}, {0, 1, 2}})
    ->UseManualTime()
    ->Iterations(2)
    ->Unit(benchmark::kMillisecond);

// Anisotropic filtering on the grazing plane, where it matters: rastrace at maximum anisotropy 1
// and 16 (one thread, untraced) against llvmpipe at 16 (LP_NUM_THREADS=0, best of 5, measured
// once in this run). vs_llvmpipe_aniso16 is llvmpipe's best frame over rastrace's, wall-clock and
// CPU time. Both filter the same ellipses (raster/anisotropy.h), so the ratio compares the same
// work.
constexpr std::int64_t kGrazingPlane = 2;

const BestFrame& llvmpipe_aniso16() {
  static const BestFrame measured = [] {
    ReferenceOptions options;
    options.driver = ReferenceDriver::Llvmpipe;
    options.llvmpipe_threads = 0;
    options.frames = 5;
    options.sampler.max_anisotropy = 16;
    const ReferenceImage image = render_reference(frame(kGrazingPlane), options);
    return BestFrame{image.best_frame_seconds, image.best_frame_cpu_seconds};
  }();
  return measured;
}

// Argument: rastrace's maximum anisotropy (1 or 16); 0: llvmpipe's own row at 16.
void BM_Anisotropic(benchmark::State& state) {
  const int aniso = static_cast<int>(state.range(0));
  const BestFrame llvmpipe = llvmpipe_aniso16();
  RenderOptions options;
  options.pipeline.raster.threads = 1;
  options.pipeline.raster.sampler.max_anisotropy = std::max(aniso, 1);
  BestFrame best{1e30, 1e30};
  RasterStats raster;
  const Scene& plane = frame(kGrazingPlane);
  Framebuffer framebuffer(plane.width, plane.height);  // kept, as llvmpipe's context keeps its own
  if (aniso > 0) raster = render_scene_into(framebuffer, plane, options, nullptr).raster;  // untimed: grows the buffers
  for (auto _ : state) {
    BestFrame f = llvmpipe;
    if (aniso > 0) {
      const auto start = std::chrono::steady_clock::now();
      const double cpu_start = process_cpu_seconds();
      raster = render_scene_into(framebuffer, plane, options, nullptr).raster;
      f = {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
           process_cpu_seconds() - cpu_start};
    }
    state.SetIterationTime(f.wall);
    best.wall = std::min(best.wall, f.wall);
    best.cpu = std::min(best.cpu, f.cpu);
  }
  report(state, frame_fragments(kGrazingPlane), best.wall);
  state.counters["cpu_ms"] = best.cpu * 1e3;
  state.counters["vs_llvmpipe_aniso16"] = llvmpipe.wall / best.wall;
  state.counters["vs_llvmpipe_aniso16_cpu"] = llvmpipe.cpu / best.cpu;
  if (raster.fragments_textured)
    state.counters["texels_per_fragment"] =
        static_cast<double>(raster.texel_reads) / static_cast<double>(raster.fragments_textured);
  state.SetLabel(aniso > 0 ? "grazing_plane rastrace one thread aniso " + std::to_string(aniso)
                           : std::string("grazing_plane llvmpipe LP_NUM_THREADS=0 aniso 16"));
}
BENCHMARK(BM_Anisotropic)
    ->ArgName("aniso")
    ->Arg(0)
    ->Arg(1)
    ->Arg(16)
    ->UseManualTime()
    ->Iterations(4)
    ->Unit(benchmark::kMillisecond);

// The least that tracing the frame into memory can cost here (see the top of the file): its event
// bytes, the time one thread takes to write them with streaming stores (best of 5), and the
// vs_untraced of a traced-to-memory row if that were all tracing cost.
void BM_TraceStoreFloor(benchmark::State& state) {
  const Scene& scene = frame(state.range(0));
  RenderOptions options;
  options.pipeline.raster.threads = 1;
  Framebuffer framebuffer(scene.width, scene.height);
  std::size_t bytes = 0;
  {  // the untraced frames below run without the traced frame's memory
    MemorySink memory;
    render_scene_into(framebuffer, scene, options, &memory);
    bytes = memory.fetches.size() * sizeof(VertexFetch) + memory.texels.size() * sizeof(TexelAccess) +
            memory.framebuffer.size() * sizeof(FramebufferAccess);
  }
  double untraced = 1e30;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    render_scene_into(framebuffer, scene, options, nullptr);
    const double frame_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    untraced = std::min(untraced, frame_seconds);
    state.SetIterationTime(frame_seconds);
  }
  const double floor = streaming_store_seconds(bytes);
  state.counters["event_mb"] = static_cast<double>(bytes) / 1e6;
  state.counters["store_floor_ms"] = floor * 1e3;
  state.counters["untraced_ms"] = untraced * 1e3;
  state.counters["floor_vs_untraced"] = (untraced + floor) / untraced;
  state.counters["store_gb_per_s"] = static_cast<double>(bytes) / floor / 1e9;
  state.SetLabel(std::string(kSceneNames[state.range(0)]) + " one thread");
}
BENCHMARK(BM_TraceStoreFloor)
    ->ArgNames({"scene"})
    ->DenseRange(0, 2)
    ->UseManualTime()
    ->Iterations(10)
    ->Unit(benchmark::kMillisecond);

}  // namespace
