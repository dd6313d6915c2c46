// A MemorySink lends its storage: with one thread the recorders write into it, with several the
// tiles' events are copied into it in parallel, in an order planned without a replay. Either way
// it must hold exactly the events a sink that does not lend receives through the batch calls
// (RenderIdentity pins those), at every thread count, in every depth test and traversal.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "pipeline/render_scene.h"
#include "scenes/builtin_scenes.h"
#include "traces/memory_sink.h"
#include "traces/tee_sink.h"

namespace rastrace {
namespace {

void expect_same_events(const MemorySink& got, const MemorySink& want) {
  ASSERT_EQ(got.draws.size(), want.draws.size());
  for (std::size_t i = 0; i < want.draws.size(); ++i) {
    EXPECT_EQ(got.draws[i].draw, want.draws[i].draw);
    EXPECT_EQ(got.draw_first_fetch[i], want.draw_first_fetch[i]);
  }
  ASSERT_EQ(got.fetches.size(), want.fetches.size());
  for (std::size_t i = 0; i < want.fetches.size(); ++i) {
    ASSERT_EQ(got.fetches[i].vertex, want.fetches[i].vertex) << i;
    ASSERT_EQ(got.fetches[i].primitive_start, want.fetches[i].primitive_start) << i;
  }
  ASSERT_EQ(got.texels.size(), want.texels.size());
  for (std::size_t i = 0; i < want.texels.size(); ++i) {
    const TexelAccess &a = got.texels[i], &b = want.texels[i];
    ASSERT_TRUE(a.texture == b.texture && a.level == b.level && a.x == b.x && a.y == b.y && a.pixel_x == b.pixel_x &&
                a.pixel_y == b.pixel_y && a.triangle == b.triangle)
        << "texel " << i;
  }
  ASSERT_EQ(got.framebuffer.size(), want.framebuffer.size());
  for (std::size_t i = 0; i < want.framebuffer.size(); ++i) {
    const FramebufferAccess &a = got.framebuffer[i], &b = want.framebuffer[i];
    ASSERT_TRUE(a.x == b.x && a.y == b.y && a.op == b.op && a.mask == b.mask && a.triangle == b.triangle)
        << "framebuffer event " << i;
  }
}

TEST(InPlaceTrace, LentStorageHoldsTheBatchCallsEventsAtOneTwoAndFourThreads) {
  // The grid's large triangles have quads in several screen tiles, which alternate row by row in
  // scanline order and tile by tile in the others.
  for (const char* name : {"bunny", "spider", "grid"}) {
    const Scene scene = make_builtin_scene(name);
    for (const DepthTest depth : {DepthTest::Early, DepthTest::Late}) {
      for (const Traversal traversal : {Traversal::Tiled8, Traversal::Scanline, Traversal::Hilbert8}) {
        SCOPED_TRACE(std::string(name) + " " + to_string(depth) + " " + to_string(traversal));
        RenderOptions options;
        options.pipeline.raster.depth_test = depth;
        options.pipeline.raster.traversal = traversal;
        options.pipeline.raster.threads = 1;
        MemorySink batched;
        TeeSink tee({&batched});  // does not lend: the recorders' batch calls fill `batched`
        render_scene(scene, options, &tee);
        ASSERT_GT(batched.texels.size(), 10000u);
        ASSERT_GT(batched.framebuffer.size(), 1000u);
        MemorySink lent;  // one sink across thread counts, cleared: as a benchmark keeps it
        for (const unsigned threads : {1u, 2u, 4u}) {
          SCOPED_TRACE(std::to_string(threads) + " threads");
          options.pipeline.raster.threads = threads;
          lent.clear();
          render_scene(scene, options, &lent);
          expect_same_events(lent, batched);
        }
      }
    }
  }
}

// A triangle lying in one 64x64 screen tile, drawn 400 times in one draw under the late depth test
// (every repetition is textured): its tile's quads follow each other in the serial order, so the
// merge plans them as one run of over 400,000 texel events, far longer than the pieces the
// copy is cut into (32768 events).
TEST(InPlaceTrace, ARunOfOneTileLongerThanACopyPieceKeepsItsEventsAtTwoAndFourThreads) {
  const Scene scene = make_builtin_scene("grid");
  RenderOptions options;
  options.pipeline.raster.depth_test = DepthTest::Late;
  options.pipeline.raster.traversal = Traversal::Hilbert8;
  MemorySink frame;
  render_scene(scene, options, &frame);
  // Each triangle's texel events, and whether its pixels all lie in one tile.
  struct Footprint {
    std::size_t texels = 0;
    int tile = -1;
    bool one_tile = true;
  };
  std::map<std::uint32_t, Footprint> footprints;
  for (const TexelAccess& t : frame.texels) {
    Footprint& f = footprints[t.triangle];
    const int tile = (t.pixel_y / 64) * 1024 + t.pixel_x / 64;
    if (f.tile >= 0 && f.tile != tile) f.one_tile = false;
    f.tile = tile;
    ++f.texels;
  }
  std::uint32_t chosen = 0;
  std::size_t most = 0;
  for (const auto& [triangle, f] : footprints)
    if (f.one_tile && f.texels > most) {
      chosen = triangle;
      most = f.texels;
    }
  ASSERT_GE(most, 1000u);  // 400 repetitions: over 400,000 events in the run

  const Mesh& mesh = scene.objects.at(0).mesh;
  std::vector<std::uint32_t> indices, materials;
  for (int r = 0; r < 400; ++r) {
    indices.insert(indices.end(), mesh.indices.begin() + 3 * chosen, mesh.indices.begin() + 3 * chosen + 3);
    materials.push_back(mesh.material_of(chosen));
  }
  DrawCall call;
  call.indices = indices;
  call.primitive_materials = materials;
  const DrawCall calls[] = {call};
  options.object_draws = calls;
  options.pipeline.raster.threads = 1;
  MemorySink batched;
  TeeSink tee({&batched});
  render_scene(scene, options, &tee);
  ASSERT_EQ(batched.texels.size(), 400 * most);
  for (const unsigned threads : {2u, 4u}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    options.pipeline.raster.threads = threads;
    MemorySink lent;
    render_scene(scene, options, &lent);
    expect_same_events(lent, batched);
  }
}

}  // namespace
}  // namespace rastrace
