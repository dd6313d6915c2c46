// Sort-middle parallel rasterization with the serial renderer's output, to the bit and to the
// event. Triangles are set up on the calling thread and binned to 32x32-pixel screen tiles; a
// batch of them is rasterized tile by tile on a WorkerPool, each tile drawing its triangles in
// draw order (the depth buffer, the colours and hierarchical Z are per pixel or per 8x8 tile, so
// tiles are independent). Each tile keeps its events in its own buffers with a mark per quad; the
// calling thread then replays the frame in the serial order: the caller's own events (draws,
// vertex fetches) where they were sent, and each triangle's quads merged across its tiles by their
// key in the traversal order (raster/traversal.h), through recorders that batch exactly as the
// serial rasterizer's do. The sink therefore receives the same calls, with the same batches, at
// any thread count, and a trace file's bytes do not change.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "raster/framebuffer.h"
#include "raster/framebuffer_recorder.h"
#include "raster/quad_stage.h"
#include "raster/rasterizer.h"
#include "raster/texel_recorder.h"
#include "raster/worker_pool.h"
#include "traces/sink.h"

namespace rastrace {

class ParallelRasterizer {
 public:
  static constexpr int kScreenTile = 32;             // pixels; a multiple of 8 (hierarchical Z tiles)
  static constexpr std::size_t kBatchTriangles = 16384;  // triangles binned before a batch is drawn

  // Draws with options.threads threads (the calling one included).
  ParallelRasterizer(Framebuffer& framebuffer, const RasterOptions& options, EventSink* sink);
  ~ParallelRasterizer();

  EventSink* event_sink();
  void draw(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c, const TriangleState& state);
  void flush();
  void finish();
  RasterStats stats() const;

 private:
  class OrderedSink;
  class TileSink;
  struct Worker;
  struct Binned {
    TriangleSetup setup;
    TriangleState state;
    bool textured;
  };
  struct QuadMark {
    std::uint32_t key;         // quad_order_key
    std::uint32_t texel_end;   // end of its texel events in the tile's buffer
    std::uint32_t events_end;  // end of its framebuffer events
  };
  struct TileEvents {
    std::vector<TexelAccess> texels;
    std::vector<FramebufferAccess> framebuffer;
    std::vector<QuadMark> quads;
    std::vector<std::uint32_t> triangle_ends;  // per binned triangle: its end in quads
  };
  // The replay's place in each tile.
  struct TileCursor {
    std::size_t triangle = 0, quad = 0, texel = 0, event = 0;
  };
  enum class StepKind : std::uint8_t { BeginDraw, Fetches, Triangle, Flush, EndDraw };
  struct Step {
    StepKind kind;
    std::uint32_t first, last;  // Fetches: range in fetches_; Triangle: index in batch_; BeginDraw: in draws_
  };

  void tile_range(const TriangleSetup& s, int& tx0, int& ty0, int& tx1, int& ty1) const;
  void run_batch();
  void rasterize_tile(Worker& worker, std::size_t tile);
  template <bool kTextured, bool kDebug>
  void rasterize_in_tile(Worker& worker, const Binned& triangle, const PixelRect& clip, TileEvents& out,
                         std::uint64_t texel_base, std::uint64_t event_base);
  void replay();
  void emit_triangle(std::uint32_t triangle);
  void emit_quad(const TileEvents& tile, TileCursor& cursor, const QuadMark& mark);

  Framebuffer& framebuffer_;
  RasterOptions options_;
  EventSink* sink_;
  bool recording_;  // a sink is attached: tiles keep their events for the replay
  std::unique_ptr<OrderedSink> ordered_;
  std::unique_ptr<HierarchicalZ> hiz_;
  WorkerPool pool_;
  std::vector<std::unique_ptr<Worker>> workers_;
  int tile_columns_, tile_rows_;
  std::uint64_t triangles_ = 0;

  // The pending batch.
  std::vector<Binned> batch_;
  std::vector<std::vector<std::uint32_t>> bins_;  // per tile: indices into batch_, in draw order
  std::vector<std::size_t> busy_tiles_;
  std::vector<TileEvents> tile_events_;
  std::vector<TileCursor> cursors_;
  std::vector<Step> steps_;
  std::vector<DrawInfo> draws_;
  std::vector<VertexFetch> fetches_;

  // The replay's recorders: batch the merged events as the serial rasterizer's recorders do.
  TexelRecorder texels_out_;
  FramebufferRecorder events_out_;
};

}  // namespace rastrace
