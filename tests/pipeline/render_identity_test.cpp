// The renderer's output pinned to the bit: for every scene the tests draw (the OSMesa cross-check
// scenes and the built-in scenes) under four raster configurations, the image (colour, depth,
// debug planes), the statistics, the exact sequence of calls an EventSink receives (kinds, batch
// sizes, every field of every event) and the bytes of the trace file written with small chunks
// (so that the order of texel, framebuffer and vertex chunks depends on how events interleave)
// have the digests the single-threaded renderer produced before the multi-threaded one existed.
// Every thread count (1, 2 and 4 here) must reproduce them: a parallel renderer that reorders one event fails here.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "pipeline/render_scene.h"
#include "raster/quad_loop.h"
#include "scenes/builtin_scenes.h"
#include "tests/reference/cross_check_scenes.h"
#include "tests/support/temp_dir.h"
#include "traces/tee_sink.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

// FNV-1a over 64 bits, fed field by field (events have padding bytes that must not count).
class Digest {
 public:
  template <typename T>
  void add(T value) {
    for (std::size_t i = 0; i < sizeof(T); ++i)
      byte(static_cast<std::uint8_t>(static_cast<std::uint64_t>(value) >> (8 * i)));
  }
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    for (std::size_t i = 0; i < size; ++i) byte(p[i]);
  }
  std::uint64_t value() const { return hash_; }

 private:
  void byte(std::uint8_t b) {
    hash_ ^= b;
    hash_ *= 0x100000001b3ull;
  }
  std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

// Digests every call in order, with its batch size: the strongest statement of "the same events".
class CallDigestSink final : public EventSink {
 public:
  void begin_draw(const DrawInfo& draw) override {
    digest.add<std::uint8_t>(1);
    digest.add(draw.draw);
    digest.add(static_cast<std::uint8_t>(draw.type));
    digest.add<std::uint8_t>(draw.restart_index.has_value());
    digest.add(draw.restart_index.value_or(0));
  }
  void vertex_fetches(std::span<const VertexFetch> fetches) override {
    digest.add<std::uint8_t>(2);
    digest.add<std::uint64_t>(fetches.size());
    for (const VertexFetch& f : fetches) {
      digest.add(f.vertex);
      digest.add<std::uint8_t>(f.primitive_start);
    }
  }
  void texel_accesses(std::span<const TexelAccess> accesses) override {
    digest.add<std::uint8_t>(3);
    digest.add<std::uint64_t>(accesses.size());
    for (const TexelAccess& t : accesses) {
      // 32 bits each, as the fields were when the digests were pinned.
      digest.add<std::uint32_t>(t.texture);
      digest.add(t.level);
      digest.add<std::uint32_t>(t.x);
      digest.add<std::uint32_t>(t.y);
      digest.add(t.pixel_x);
      digest.add(t.pixel_y);
      digest.add(t.triangle);
    }
    texels += accesses.size();
  }
  void framebuffer_accesses(std::span<const FramebufferAccess> accesses) override {
    digest.add<std::uint8_t>(4);
    digest.add<std::uint64_t>(accesses.size());
    for (const FramebufferAccess& a : accesses) {
      digest.add(a.x);
      digest.add(a.y);
      digest.add(static_cast<std::uint8_t>(a.op));
      digest.add(a.mask);
      digest.add(a.triangle);
    }
  }
  bool wants_framebuffer_events() const override { return true; }
  void end_draw() override { digest.add<std::uint8_t>(5); }
  void finish() override { digest.add<std::uint8_t>(6); }

  Digest digest;
  std::uint64_t texels = 0;
};

struct Config {
  const char* name;
  Traversal traversal;
  DepthTest depth_test;
  bool hierarchical_z;
  bool debug_planes;
};

constexpr Config kConfigs[] = {
    {"scanline", Traversal::Scanline, DepthTest::Early, false, false},
    {"tiled8+hiz", Traversal::Tiled8, DepthTest::Early, true, false},
    {"scanline+late+debug", Traversal::Scanline, DepthTest::Late, false, true},
    {"tiled8+late", Traversal::Tiled8, DepthTest::Late, false, false},
};

struct FrameDigests {
  std::uint64_t image = 0;
  std::uint64_t calls = 0;
  std::uint64_t trace_file = 0;
  std::uint64_t texels = 0;
};

FrameDigests render_digests(const Scene& scene, const Config& config, unsigned threads, const testing::TempDir& dir) {
  RenderOptions options;
  options.pipeline.raster.threads = threads;
  options.pipeline.raster.traversal = config.traversal;
  options.pipeline.raster.depth_test = config.depth_test;
  options.pipeline.raster.hierarchical_z = config.hierarchical_z;
  options.debug_planes = config.debug_planes;

  TraceMetadata metadata;
  metadata.scene = scene.name;
  metadata.width = static_cast<std::uint32_t>(scene.width);
  metadata.height = static_cast<std::uint32_t>(scene.height);
  metadata.tool_version = "render-identity-test";  // not the build's version: the bytes must not move
  metadata.textures = texture_levels(scene);
  const std::string path = dir.file("frame.rtrace");
  TraceWriterOptions writer_options;
  writer_options.chunk_records = 1021;  // a prime: chunk ends fall inside the renderer's batches
  TraceWriter writer(path, metadata, writer_options);
  CallDigestSink calls;
  TeeSink tee({&calls, &writer});
  const RenderResult result = render_scene(scene, options, &tee);

  FrameDigests out;
  Digest image;
  const Framebuffer& fb = result.framebuffer;
  const std::size_t pixels = static_cast<std::size_t>(fb.width()) * static_cast<std::size_t>(fb.height());
  image.bytes(fb.colour(), pixels * 4);
  image.bytes(fb.depth(), pixels * sizeof(float));
  if (fb.has_debug_planes()) {
    image.bytes(fb.write_count(), pixels * sizeof(std::uint16_t));
    image.bytes(fb.centre_on_edge(), pixels);
  }
  const RasterStats& r = result.raster;
  for (const std::uint64_t v : {r.triangles, r.quads, r.fragments, r.fragments_passed, r.fragments_shaded,
                                r.fragments_rejected_early, r.quads_rejected_hiz, r.texel_reads})
    image.add(v);
  out.image = image.value();
  out.calls = calls.digest.value();
  out.texels = calls.texels;
  std::ifstream in(path, std::ios::binary);
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Digest trace;
  trace.bytes(file.data(), file.size());
  out.trace_file = trace.value();
  return out;
}

struct Expected {
  const char* scene;
  const char* config;
  FrameDigests digests;
};

// Generated by the single-threaded renderer before the parallel renderer existed
// (RASTRACE_PRINT_DIGESTS=1 prints this table). The trace-file digests were generated again when
// trace version 4 (run columns) changed the files' bytes; the image, call and texel digests are
// the originals, unchanged by it.
const std::vector<Expected> kExpected = {
#include "render_identity_digests.inc"
};

std::vector<std::pair<std::string, Scene>> identity_scenes() {
  std::vector<std::pair<std::string, Scene>> scenes;
  scenes.emplace_back("flat_triangles", testing::flat_triangles_scene());
  scenes.emplace_back("fan", testing::fan_scene());
  scenes.emplace_back("near_clip", testing::near_clip_scene());
  scenes.emplace_back("grazing_plane", testing::grazing_plane_scene());
  scenes.emplace_back("bunny_checker", testing::bunny_checker_scene(320, 240));
  for (const std::string& name : builtin_scene_names())
    scenes.emplace_back("builtin:" + name, make_builtin_scene(name));
  return scenes;
}

const FrameDigests* expected(const std::string& scene, const std::string& config) {
  for (const Expected& e : kExpected)
    if (scene == e.scene && config == e.config) return &e.digests;
  return nullptr;
}

// Renders every scene in every configuration with `threads` raster threads and compares.
void expect_pinned_digests(unsigned threads) {
  const testing::TempDir dir;
  const bool print = std::getenv("RASTRACE_PRINT_DIGESTS") != nullptr;
  for (const auto& [name, scene] : identity_scenes()) {
    for (const Config& config : kConfigs) {
      SCOPED_TRACE(name + " " + config.name + " threads " + std::to_string(threads));
      const FrameDigests got = render_digests(scene, config, threads, dir);
      if (print) {
        std::printf("    {\"%s\", \"%s\", {0x%016llxull, 0x%016llxull, 0x%016llxull, %llu}},\n", name.c_str(),
                    config.name, static_cast<unsigned long long>(got.image), static_cast<unsigned long long>(got.calls),
                    static_cast<unsigned long long>(got.trace_file), static_cast<unsigned long long>(got.texels));
        continue;
      }
      const FrameDigests* want = expected(name, config.name);
      ASSERT_NE(want, nullptr) << "no pinned digests";
      EXPECT_EQ(got.texels, want->texels);
      EXPECT_EQ(got.image, want->image);
      EXPECT_EQ(got.calls, want->calls);
      EXPECT_EQ(got.trace_file, want->trace_file);
    }
  }
}

TEST(RenderIdentity, OneThreadEqualsThePinnedImagesEventsAndTraceFilesToTheBit) { expect_pinned_digests(1); }

TEST(RenderIdentity, TwoThreadsEqualThePinnedImagesEventsAndTraceFilesToTheBit) { expect_pinned_digests(2); }

TEST(RenderIdentity, FourThreadsEqualThePinnedImagesEventsAndTraceFilesToTheBit) { expect_pinned_digests(4); }

// The quad loop's baseline copy (raster/quad_loop.h), in the same process as the x86-64-v4 copy
// the tests above ran where the processor has it: the two must give the same bits.
TEST(RenderIdentity, TheBaselineQuadLoopGivesThePinnedDigestsAtOneAndTwoThreads) {
  struct Restore {
    bool wide = wide_quad_loop();
    ~Restore() { use_wide_quad_loop(wide); }
  } restore;
  use_wide_quad_loop(false);
  ASSERT_FALSE(wide_quad_loop());
  expect_pinned_digests(1);
  expect_pinned_digests(2);
}

}  // namespace
}  // namespace rastrace
