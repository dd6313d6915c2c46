// The geometry pipeline: primitive assembly, vertex cache and shader invocations, events,
// culling, clipping, errors.
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cache_sim/vertex_cache.h"
#include "core/error.h"
#include "pipeline/pipeline.h"
#include "scenes/procedural.h"
#include "scenes/texture.h"
#include "tests/support/test_data.h"
#include "tests/support/test_meshes.h"
#include "traces/memory_sink.h"

namespace rastrace {
namespace {

constexpr std::uint32_t R = 0xFFFFu;  // the strips' restart index

// Vertices given directly in clip space (identity camera and model, w = 1).
Mesh clip_space_mesh(const std::vector<glm::vec3>& positions) {
  Mesh mesh;
  mesh.name = "test mesh";
  mesh.positions = positions;
  return mesh;
}

// Two strip rows: vertex 2k at (x_k, 0.5), 2k+1 at (x_k, -0.5): the strip 0 1 2 3 ... winds
// counter-clockwise on every triangle once GL's odd-triangle swap is applied.
Mesh strip_row(int columns) {
  std::vector<glm::vec3> p;
  for (int k = 0; k < columns; ++k) {
    const float x = -0.9f + 1.8f * static_cast<float>(k) / static_cast<float>(columns - 1);
    p.emplace_back(x, 0.5f, 0.0f);
    p.emplace_back(x, -0.5f, 0.0f);
  }
  return clip_space_mesh(p);
}

PipelineStats draw(const Mesh& mesh, const DrawCall& call, const PipelineOptions& options, EventSink* sink = nullptr,
                   PrimitiveHook* hook = nullptr) {
  Framebuffer fb(64, 64);
  Pipeline pipeline(fb, options, sink);
  pipeline.set_primitive_hook(hook);
  pipeline.draw(mesh, glm::mat4(1.0f), call, {});
  pipeline.finish();
  return pipeline.stats();
}

TEST(Pipeline, StripWithRestartAndDegeneratesFetchesEveryIndexAndKeepsOneWinding) {
  const Mesh mesh = strip_row(5);
  const std::vector<std::uint32_t> indices = {0, 1, 2, 3, 4, 5, R, 4, 5, 6, 6, 6, 7, 8, 9};
  DrawCall call;
  call.indices = indices;
  call.type = PrimitiveType::TriangleStrip;
  call.restart_index = R;
  PipelineOptions options;
  options.cull = CullMode::Back;
  MemorySink sink;
  const PipelineStats stats = draw(mesh, call, options, &sink);
  // Strip 1: 4 triangles. Strip 2 (4 5 6 6 6 7 8 9): (4 5 6), (6 5 6)x, (6 6 6)x, (6 6 7)x,
  // (6 7 8), (8 7 9): three degenerates keep the parity, so the winding stays counter-clockwise.
  EXPECT_EQ(stats.lookups, 14u);
  EXPECT_EQ(stats.primitives, 10u);
  EXPECT_EQ(stats.triangles, 7u);
  EXPECT_EQ(stats.degenerate, 3u);
  EXPECT_EQ(stats.culled, 0u);  // every odd triangle is swapped back to counter-clockwise
  ASSERT_EQ(sink.fetches.size(), 14u);
  std::vector<std::uint32_t> ids;
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < sink.fetches.size(); ++i) {
    ids.push_back(sink.fetches[i].vertex);
    if (sink.fetches[i].primitive_start) starts.push_back(i);
  }
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 4, 5, 6, 6, 6, 7, 8, 9}));
  EXPECT_EQ(starts, (std::vector<std::size_t>{0, 6}));
  ASSERT_EQ(sink.draws.size(), 1u);
  EXPECT_EQ(sink.draws[0].type, PrimitiveType::TriangleStrip);
  EXPECT_EQ(sink.draws[0].restart_index, R);
  // The same stream through cache_sim's model gives the same counts.
  const VertexStreamStats model =
      simulate_vertex_stream(indices, PrimitiveType::TriangleStrip, VertexCachePolicy::Fifo, 16, R);
  EXPECT_EQ(model.lookups, stats.lookups);
  EXPECT_EQ(model.misses, stats.vertices_shaded);
  EXPECT_EQ(model.triangles, stats.triangles);
  EXPECT_EQ(model.degenerate, stats.degenerate);
  // With front-face culling every triangle goes.
  options.cull = CullMode::Front;
  EXPECT_EQ(draw(mesh, call, options).culled, 7u);
}

TEST(Pipeline, StripWithoutRestartTreats0xFFFFFFFFAsAVertexNotARestart) {
  const Mesh mesh = strip_row(3);
  const std::vector<std::uint32_t> indices = {0, 1, 2, kStripRestart, 3, 4, 5};
  DrawCall call;
  call.indices = indices;
  call.type = PrimitiveType::TriangleStrip;
  // Restarting at 0xFFFFFFFF: two strips, two triangles.
  call.restart_index = kStripRestart;
  EXPECT_EQ(draw(mesh, call, PipelineOptions{}).triangles, 2u);
  // Without restart the index is a vertex, and out of range.
  call.restart_index = kNoRestart;
  try {
    draw(mesh, call, PipelineOptions{});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "test mesh: draw 0, index 3: vertex 4294967295 >= vertex count 6");
  }
}

TEST(Pipeline, ShaderInvocationsAreTheVertexCacheMissesOnBunny00) {
  const Mesh& bunny = testing::cached_mesh("bunny00.off");
  for (const VertexCachePolicy policy : {VertexCachePolicy::Fifo, VertexCachePolicy::Lru}) {
    for (const unsigned entries : {8u, 16u, 32u}) {
      PipelineOptions options;
      options.cache_policy = policy;
      options.cache_entries = entries;
      DrawCall call;
      call.indices = bunny.indices;
      Framebuffer fb(32, 32);
      Pipeline pipeline(fb, options, nullptr);
      pipeline.set_camera(glm::mat4(0.0f), glm::mat4(1.0f));  // everything collapses to w = 0: nothing drawn
      pipeline.draw(bunny, glm::mat4(1.0f), call, {});
      const VertexStreamStats model =
          simulate_vertex_stream(bunny.indices, PrimitiveType::TriangleList, policy, entries);
      EXPECT_EQ(pipeline.stats().vertices_shaded, model.misses) << to_string(policy) << entries;
      EXPECT_EQ(pipeline.stats().triangles, model.triangles);
      EXPECT_NEAR(pipeline.stats().acmr(), model.acmr(), 1e-12);
    }
  }
}

TEST(Pipeline, CastanoScanlineGridGivesAcmr1062WithFifo16) {
  const Mesh grid = make_grid(16, 16);
  DrawCall call;
  call.indices = grid.indices;
  const PipelineStats stats = draw(grid, call, PipelineOptions{});
  EXPECT_EQ(stats.triangles, 512u);
  EXPECT_EQ(stats.vertices_shaded, 544u);
  EXPECT_NEAR(stats.acmr(), 1.0625, 1e-12);
}

class RecordingHook final : public PrimitiveHook {
 public:
  void primitive(const AssembledPrimitive& p) override {
    indices.emplace_back(p.indices.begin(), p.indices.end());
    triangles.push_back(p.triangle_indices);
    clip_w.push_back(p.shaded[p.triangle_indices[0]].clip.w);
  }
  std::vector<std::vector<std::uint32_t>> indices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<float> clip_w;
};

TEST(Pipeline, AdjacencyPrimitivesDrawTriangle024AndFetchAllSixIndices) {
  // Triangle 0 2 4 with its three neighbours' far vertices 1 3 5.
  const Mesh mesh =
      clip_space_mesh({{-0.5f, -0.5f, 0}, {0, -1, 0}, {0.5f, -0.5f, 0}, {1, 1, 0}, {0, 0.5f, 0}, {-1, 1, 0}});
  const std::vector<std::uint32_t> indices = {0, 1, 2, 3, 4, 5};
  DrawCall call;
  call.indices = indices;
  call.type = PrimitiveType::TriangleListAdjacency;
  MemorySink sink;
  RecordingHook hook;
  PipelineOptions options;
  options.cull = CullMode::Back;
  Framebuffer fb(64, 64, true);
  Pipeline pipeline(fb, options, &sink);
  pipeline.set_primitive_hook(&hook);
  pipeline.draw(mesh, glm::mat4(1.0f), call, {});
  pipeline.finish();
  EXPECT_EQ(pipeline.stats().lookups, 6u);
  EXPECT_EQ(pipeline.stats().vertices_shaded, 6u);
  EXPECT_EQ(pipeline.stats().triangles, 1u);
  EXPECT_EQ(pipeline.stats().rasterized, 1u);
  ASSERT_EQ(sink.fetches.size(), 6u);
  EXPECT_TRUE(sink.fetches[0].primitive_start);
  for (int i = 1; i < 6; ++i) EXPECT_FALSE(sink.fetches[i].primitive_start);
  ASSERT_EQ(hook.indices.size(), 1u);
  EXPECT_EQ(hook.indices[0], indices);
  EXPECT_EQ(hook.triangles[0], (std::array<std::uint32_t, 3>{0, 2, 4}));
  EXPECT_FLOAT_EQ(hook.clip_w[0], 1.0f);
  // Only the inner triangle is drawn: (-0.5,-0.5), (0.5,-0.5), (0,0.5) covers a quarter of the
  // viewport's area at most; the adjacency vertices' outer triangles would cover more.
  std::uint64_t pixels = 0;
  for (int i = 0; i < 64 * 64; ++i) pixels += fb.write_count()[i];
  EXPECT_NEAR(static_cast<double>(pixels), 0.5 * 32 * 32, 40.0);
}

TEST(Pipeline, NearPlaneClippingDrawsOnlyWhatIsInFrontOfTheCamera) {
  // A triangle from z = -0.5 (in front, GL looks down -z) to z = +2 (behind the eye) through a
  // perspective camera: the near plane cuts it, nothing behind the eye is projected.
  Mesh mesh = clip_space_mesh({{-1, -0.5f, -3}, {1, -0.5f, -3}, {0, -0.5f, 2}});
  const std::vector<std::uint32_t> indices = {0, 1, 2};
  DrawCall call;
  call.indices = indices;
  Framebuffer fb(64, 64, true);
  Pipeline pipeline(fb, PipelineOptions{}, nullptr);
  const glm::mat4 projection = glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, -1.0202f, -1),
                                         glm::vec4(0, 0, -0.20202f, 0));
  pipeline.set_camera(glm::mat4(1.0f), projection);  // perspective, near 0.1, far 10
  pipeline.draw(mesh, glm::mat4(1.0f), call, {});
  EXPECT_EQ(pipeline.stats().clipped, 1u);
  EXPECT_EQ(pipeline.stats().outside, 0u);
  EXPECT_GE(pipeline.stats().rasterized, 1u);
  // The floor at y = -0.5 below the eye covers only the bottom half of the image.
  std::uint64_t top = 0, bottom = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) (y < 32 ? top : bottom) += fb.write_count()[y * 64 + x];
  EXPECT_EQ(top, 0u);
  EXPECT_GT(bottom, 500u);
  for (int i = 0; i < 64 * 64; ++i) EXPECT_LE(fb.write_count()[i], 1);
}

TEST(Pipeline, GuardBandAndFullSideClippingCoverTheSamePixels) {
  // A triangle ten times the viewport: the guard band draws it whole, full clipping cuts it into
  // a fan at the viewport sides; the covered pixels are the same, each written once.
  const Mesh mesh = clip_space_mesh({{-5, -5, 0}, {15, -5, 0}, {-5, 15.3f, 0}});
  const std::vector<std::uint32_t> indices = {0, 1, 2};
  DrawCall call;
  call.indices = indices;
  std::vector<std::uint16_t> counts[2];
  for (int full = 0; full < 2; ++full) {
    PipelineOptions options;
    options.guard_band = full ? 0.0f : 4096.0f;
    Framebuffer fb(64, 64, true);
    Pipeline pipeline(fb, options, nullptr);
    pipeline.draw(mesh, glm::mat4(1.0f), call, {});
    EXPECT_EQ(pipeline.stats().clipped, full ? 1u : 0u);
    if (full)
      EXPECT_GE(pipeline.stats().rasterized, 2u);  // the viewport square as a fan
    else
      EXPECT_EQ(pipeline.stats().rasterized, 1u);
    counts[full].assign(fb.write_count(), fb.write_count() + 64 * 64);
  }
  EXPECT_EQ(counts[0], counts[1]);
  std::uint64_t written = 0;
  for (const std::uint16_t c : counts[1]) {
    EXPECT_LE(c, 1);
    written += c;
  }
  EXPECT_EQ(written, 64u * 64u);  // the viewport lies inside the triangle
}

TEST(Pipeline, GouraudLightingMatchesTheFixedFunctionFormula) {
  Lighting lighting;
  lighting.enabled = true;
  lighting.direction = glm::vec3(0.0f, 0.0f, 2.0f);  // normalised by the shader
  lighting.ambient = 0.25f;
  const VertexShader shader(glm::mat4(1.0f), glm::mat4(1.0f), lighting);
  const glm::vec3 facing(0, 0, 1), tilted(0, 0.6f, 0.8f), away(0, 0, -1);
  EXPECT_FLOAT_EQ(shader.shade(glm::vec3(0), &facing, nullptr).light, 1.25f);
  EXPECT_FLOAT_EQ(shader.shade(glm::vec3(0), &tilted, nullptr).light, 0.25f + 0.8f);
  EXPECT_FLOAT_EQ(shader.shade(glm::vec3(0), &away, nullptr).light, 0.25f);
}

// Texel events hold 16-bit texture numbers and texel coordinates: a draw that could record more
// is refused before anything is drawn, naming the material and the limit.
TEST(Pipeline, TexturesBeyondWhatTexelEventsHoldAreInputErrors) {
  Mesh mesh = strip_row(2);
  mesh.uvs.assign(mesh.positions.size(), glm::vec2(0.5f));
  mesh.materials.resize(1);
  Framebuffer fb(8, 8);
  const auto draw_with = [&](std::span<const Texture> textures) -> std::string {
    Pipeline pipeline(fb, PipelineOptions{}, nullptr);
    try {
      pipeline.draw(mesh, glm::mat4(1.0f), DrawCall{}, textures);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  Texture wide;
  wide.name = "wide";
  wide.levels.push_back(Image{65537, 1, std::vector<std::uint8_t>(65537 * 4, 255)});
  mesh.materials[0].texture = 0;
  EXPECT_EQ(draw_with(std::span(&wide, 1)),
            "test mesh: material 0 uses texture 'wide' of 65537x1 texels: expected at most 65536 a side (texel "
            "events hold 16-bit coordinates)");
  wide.levels[0] = Image{65536, 1, std::vector<std::uint8_t>(65536 * 4, 255)};  // the widest allowed
  EXPECT_EQ(draw_with(std::span(&wide, 1)), "");

  std::vector<Texture> many(65537);
  for (Texture& t : many) t.levels.push_back(Image{1, 1, {255, 255, 255, 255}});
  mesh.materials[0].texture = 65536;
  EXPECT_EQ(draw_with(many),
            "test mesh: material 0 uses texture 65536: expected at most 65536 textures (texel events number them in "
            "16 bits)");
  mesh.materials[0].texture = 65535;
  EXPECT_EQ(draw_with(many), "");
}

TEST(Pipeline, IndexOutOfRangeIsAnInputErrorNamingThePlace) {
  const Mesh mesh = strip_row(2);
  const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 1, 7};
  DrawCall call;
  call.indices = indices;
  try {
    draw(mesh, call, PipelineOptions{});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "test mesh: draw 0, index 5: vertex 7 >= vertex count 4");
  }
  EXPECT_THROW(parse_cull_mode("sideways"), InputError);
  PipelineOptions zero;
  zero.cache_entries = 0;
  EXPECT_THROW(draw(mesh, DrawCall{}, zero), InputError);
}

}  // namespace
}  // namespace rastrace
