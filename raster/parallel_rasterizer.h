// Sort-middle parallel rasterization with the serial renderer's output, to the bit and to the
// event. Triangles are set up on the calling thread and binned to square screen tiles; a
// batch of them is rasterized tile by tile on a WorkerPool, each tile drawing its triangles in
// draw order (the depth buffer, the colours and hierarchical Z are per pixel or per 8x8 tile, so
// tiles are independent). Each tile keeps its events in its own buffers with a mark per quad.
// The batch's events then reach the sink in the serial order: the caller's own events (draws,
// vertex fetches) where they were sent, and each triangle's quads merged across its tiles by their
// key in the traversal order (raster/traversal.h).
//
// How depends on the sink. A sink that lends storage (traces/sink.h: a MemorySink) keeps only
// each kind's sequence of events, so the calling thread only plans the merge (a list of runs of
// consecutive quads of one tile, with their places in the output, no event copied), borrows one
// span per kind for the whole batch, and the pool copies the runs into it in parallel. Any
// other sink sees batches and the interleaving of kinds (a trace file's chunks), so the calling
// thread replays the frame through recorders that batch exactly as the serial rasterizer's do:
// the sink receives the same calls, with the same batches, at any thread count, and a trace
// file's bytes do not change.
//
// Batches are double-buffered: while the workers draw one, the calling thread sets up and bins
// the next; when that one is full it joins the workers on what is left of the first, hands its
// events over, and hands over the second. Tiles of one batch are drawn only after every tile of
// the one before.
//
// The threads and the batches' buffers (a workspace) outlive the rasterizer: a finished frame
// returns its workspace to a process-wide cache, and the next frame with the same thread count
// takes it back, as a GL driver keeps its threads and scene buffers per context. A frame then
// neither starts threads nor touches fresh memory (on a loaded or virtualised machine a page
// fault costs microseconds, and one frame's buffers are megabytes).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "core/huge_page_allocator.h"
#include "raster/framebuffer.h"
#include "raster/framebuffer_recorder.h"
#include "raster/quad_loop.h"
#include "raster/rasterizer.h"
#include "raster/texel_recorder.h"
#include "raster/worker_pool.h"
#include "traces/sink.h"

namespace rastrace {

class ParallelRasterizer {
 public:
  // The side of a screen tile, in pixels: a power of two (the traversals' aligned blocks stay
  // whole, and hierarchical Z's 8x8 tiles with them). Every tile a triangle touches runs the quad
  // loop for it (setup, coefficients, the pipeline filling), so tiles are as large as the frame
  // allows while each thread still has kTilesPerThread of them to share out: 128 for a 1024x768
  // frame on two threads (48 tiles), 64 on four or more, never below 64 (32 cost the spider and the
  // grazing plane 6-7% on two threads).
  static constexpr int kLargestScreenTile = 128;
  static constexpr int kSmallestScreenTile = 64;
  static constexpr int kTilesPerThread = 16;
  static int screen_tile(int width, int height, unsigned threads);
  static constexpr std::size_t kBatchTriangles = 16384;  // triangles binned before a batch is drawn

  // Draws with options.threads threads (the calling one included).
  ParallelRasterizer(Framebuffer& framebuffer, const RasterOptions& options, EventSink* sink);
  ~ParallelRasterizer();

  EventSink* event_sink();
  void draw(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c, const TriangleState& state);
  // Draws the triangles sent so far, then has the workers other than the calling thread clear
  // the framebuffer, each a band of rows, while the calling thread returns to set up and bin
  // the next triangles; the next batch starts when the clear is done. The clear (a tenth of a
  // small frame) so overlaps the setup and binning of the first batch instead of preceding it.
  void clear(const glm::vec4& colour, float depth);
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
  template <typename Event>
  using TileBuffer = std::vector<Event, UnsetHugePageAllocator<Event>>;  // lent to the worker's recorders
  struct TileEvents {
    TileBuffer<TexelAccess> texels;
    TileBuffer<FramebufferAccess> framebuffer;
    std::vector<QuadMark> quads;
    std::vector<std::uint32_t> triangle_ends;  // per binned triangle: its end in quads
  };
  // The replay's place in each tile.
  struct TileCursor {
    std::size_t triangle = 0, quad = 0, texel = 0, event = 0;
  };
  // A run of one tile's events that stays contiguous in the merged order (lending sinks).
  struct Run {
    std::uint32_t tile;
    std::uint32_t texel_begin, texel_end, event_begin, event_end;  // in the tile's buffers
    std::size_t texel_to, event_to;                                // in the batch's merged events
    // Where the next run's events go in the merged events.
    std::size_t texel_after() const { return texel_to + (texel_end - texel_begin); }
    std::size_t event_after() const { return event_to + (event_end - event_begin); }
  };
  enum class StepKind : std::uint8_t { BeginDraw, Fetches, Triangle, Flush, EndDraw };
  struct Step {
    StepKind kind;
    std::uint32_t first, last;  // Fetches: range in the batch's fetches; Triangle: its index; BeginDraw: in draws
  };

  void tile_range(const TriangleSetup& s, int& tx0, int& ty0, int& tx1, int& ty1) const;
  struct Batch;
  struct Workspace;
  struct WorkspaceCache;
  // Takes an idle workspace of `threads` threads from the cache (or makes one) for `tiles` screen
  // tiles; returns it to the cache when the rasterizer is done.
  static std::unique_ptr<Workspace> acquire_workspace(unsigned threads, std::size_t tiles);
  static void release_workspace(std::unique_ptr<Workspace> workspace);
  static WorkspaceCache& workspace_cache();
  // Starts drawing the filled batch on the workers (after finishing the one before); with
  // `wait`, draws it to the end.
  void run_batch(bool wait);
  // Joins the workers on the batch being drawn, waits for it, replays it.
  void complete_drawing();
  void rasterize_tile(Worker& worker, Batch& batch, std::size_t tile);
  template <bool kTextured, bool kDebug>
  void rasterize_in_tile(Worker& worker, const Binned& triangle, const PixelRect& clip, TileEvents& out,
                         std::uint64_t texel_base, std::uint64_t event_base);
  // Hands the drawn batch's events to the sink: merge_in_place() for a lending sink, else a replay.
  void hand_over(Batch& batch);
  void replay(Batch& batch);
  void merge_in_place(Batch& batch);
  // Sends the batch's draws and fetches to the sink in order; calls triangle(index) and flush()
  // where those steps are.
  template <typename Triangle, typename Flush>
  void walk_steps(Batch& batch, Triangle&& triangle, Flush&& flush);
  // Calls stretch(tile, tile_events, cursor, end) for each stretch of the triangle's quads that
  // are consecutive in one tile and in the serial order, in that order: the quads from
  // cursor.quad to end. The callee moves the cursor to end.
  template <typename Stretch>
  void merge_triangle(Batch& batch, std::uint32_t triangle, Stretch&& stretch);
  void emit_quad(const TileEvents& tile, TileCursor& cursor, const QuadMark& mark);
  // Adds the stretch of the tile's quads from cursor.quad to end to the runs.
  void plan_run(std::size_t tile, const TileEvents& events, TileCursor& cursor, std::size_t end);
  void copy_runs(const Batch& batch);
  void clear(Batch& batch);
  // Waits for a clear() the workers are doing.
  void finish_clear();

  Framebuffer& framebuffer_;
  RasterOptions options_;
  EventSink* sink_;
  bool recording_;         // a sink is attached: tiles keep their events for the replay
  bool lending_;           // and it lends storage: tiles' events are copied into it in parallel
  bool streaming_copies_;  // with streaming stores: it reads them after the frame
  std::unique_ptr<OrderedSink> ordered_;
  std::unique_ptr<HierarchicalZ> hiz_;
  std::vector<std::unique_ptr<Worker>> workers_;
  int screen_tile_;  // screen_tile() of the frame and thread count
  int tile_columns_, tile_rows_;
  std::uint64_t triangles_ = 0;

  // A batch of triangles with everything its replay needs.
  struct Batch {
    // kBatchTriangles entries, allocated (and initialised) once per workspace; the first
    // triangle_count are this batch's.
    std::vector<Binned> triangles;
    std::uint32_t triangle_count = 0;
    std::vector<std::vector<std::uint32_t>> bins;  // per tile: indices into triangles, in draw order
    std::vector<std::size_t> busy_tiles;
    std::vector<TileEvents> tile_events;
    std::vector<Step> steps;
    std::vector<DrawInfo> draws;
    std::vector<VertexFetch> fetches;
  };
  struct Workspace {
    explicit Workspace(unsigned threads) : pool(threads) {}
    WorkerPool pool;
    Batch batches[2];
    std::vector<TileCursor> cursors;  // the replay's, per tile
    std::vector<Run> runs;            // merge_in_place()'s plan
  };
  std::unique_ptr<Workspace> workspace_;
  WorkerPool& pool_;
  Batch* batches_;  // workspace_'s two
  std::vector<TileCursor>& cursors_;
  Batch* filling_;            // receives triangles and steps
  Batch* drawing_ = nullptr;  // being drawn by the workers, if any
  // The busy tiles of *drawing_ no worker has claimed: [first, end) as first << 32 | end.
  std::atomic<std::uint64_t> unclaimed_tiles_{0};
  // Claims the first unclaimed tile, or the last with from_end; false when none is left.
  bool claim_tile(bool from_end, std::size_t& index);
  std::function<void(unsigned)> draw_tiles_;  // the workers' job: tiles of *drawing_
  // merge_in_place()'s: the runs claimed so far, the spans the sink lent, the workers' job.
  std::atomic<std::size_t> next_run_{0};
  std::span<TexelAccess> texels_to_;
  std::span<FramebufferAccess> events_to_;
  const Batch* merging_ = nullptr;
  std::function<void(unsigned)> copy_runs_;
  bool clearing_ = false;                     // the workers are clearing the framebuffer
  std::function<void(unsigned)> clear_rows_;  // their job

  // The replay's recorders: batch the merged events as the serial rasterizer's recorders do.
  TexelRecorder texels_out_;
  FramebufferRecorder events_out_;
};

}  // namespace rastrace
