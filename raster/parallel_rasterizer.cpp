#include "raster/parallel_rasterizer.h"

#include <algorithm>
#include <atomic>
#include <iterator>
#include <mutex>

#include "core/streaming_copy.h"

namespace rastrace {

// Holds the caller's events as steps of the replay, in the order they were sent.
class ParallelRasterizer::OrderedSink final : public EventSink {
 public:
  explicit OrderedSink(ParallelRasterizer& owner) : owner_(owner) {}
  void begin_draw(const DrawInfo& draw) override {
    Batch& batch = *owner_.filling_;
    batch.steps.push_back({StepKind::BeginDraw, static_cast<std::uint32_t>(batch.draws.size()), 0});
    batch.draws.push_back(draw);
  }
  void vertex_fetches(std::span<const VertexFetch> fetches) override {
    Batch& batch = *owner_.filling_;
    const auto first = static_cast<std::uint32_t>(batch.fetches.size());
    batch.fetches.insert(batch.fetches.end(), fetches.begin(), fetches.end());
    batch.steps.push_back({StepKind::Fetches, first, static_cast<std::uint32_t>(batch.fetches.size())});
  }
  void texel_accesses(std::span<const TexelAccess> accesses) override {
    owner_.finish();
    owner_.sink_->texel_accesses(accesses);
  }
  void framebuffer_accesses(std::span<const FramebufferAccess> accesses) override {
    owner_.finish();
    owner_.sink_->framebuffer_accesses(accesses);
  }
  bool wants_framebuffer_events() const override { return owner_.sink_->wants_framebuffer_events(); }
  void end_draw() override { owner_.filling_->steps.push_back({StepKind::EndDraw, 0, 0}); }
  void address_accesses(std::span<const AddressAccess> accesses) override {
    owner_.finish();
    owner_.sink_->address_accesses(accesses);
  }
  void finish() override {
    owner_.finish();
    owner_.sink_->finish();
  }

 private:
  ParallelRasterizer& owner_;
};

// A worker's recorders store straight into the buffers of the tile it is drawing. With `streams`
// (the runs are copied with streaming stores, for a sink that reads its events after the frame)
// they store with streaming stores too: a batch's events (the grazing plane's 61 MB) have left the
// caches by the time the copy reads them, so ordinary stores would first fetch every line they
// fill. Streamed, two threads tracing to memory cost 1.77x the untraced frame on the grazing
// plane instead of 1.87, and 1.39x on the bunny instead of 1.44 (an AMD EPYC); while the copy was
// a memcpy, streaming here had gained nothing.
class ParallelRasterizer::TileSink final : public EventSink {
 public:
  TileSink(bool framebuffer_events, bool streams) : framebuffer_events_(framebuffer_events), streams_(streams) {}
  bool wants_framebuffer_events() const override { return framebuffer_events_; }
  bool lends_storage() const override { return true; }
  bool streams_lent_storage() const override { return streams_; }
  std::span<TexelAccess> texel_slots(std::size_t count) override { return texels_.lend(tile->texels, count); }
  void commit_texels(std::size_t used) override { texels_.commit(tile->texels, used); }
  std::span<FramebufferAccess> framebuffer_slots(std::size_t count) override {
    return events_.lend(tile->framebuffer, count);
  }
  void commit_framebuffer(std::size_t used) override { events_.commit(tile->framebuffer, used); }

  TileEvents* tile = nullptr;

 private:
  bool framebuffer_events_;
  bool streams_;
  VectorLender<TileBuffer<TexelAccess>> texels_;
  VectorLender<TileBuffer<FramebufferAccess>> events_;
};

struct ParallelRasterizer::Worker {
  Worker(EventSink* real_sink, bool streaming_copies)
      : sink(real_sink && real_sink->wants_framebuffer_events(), streaming_copies),
        texels(real_sink ? &sink : nullptr),
        framebuffer_events(real_sink ? &sink : nullptr) {}
  TileSink sink;
  TexelRecorder texels;
  FramebufferRecorder framebuffer_events;
  RasterStats stats;
};

// Idle workspaces, most recently returned last. A few are kept: one per thread count a process
// renders with, in practice; the oldest go beyond that.
struct ParallelRasterizer::WorkspaceCache {
  static constexpr std::size_t kIdle = 4;
  std::mutex mutex;
  std::vector<std::unique_ptr<Workspace>> idle;
};

namespace {
// Empties a batch whatever state an interrupted frame left it in.
void reset_bins(std::vector<std::vector<std::uint32_t>>& bins, std::size_t tiles) {
  bins.resize(tiles);
  for (auto& bin : bins) bin.clear();
}
}  // namespace

ParallelRasterizer::WorkspaceCache& ParallelRasterizer::workspace_cache() {
  static WorkspaceCache cache;
  return cache;
}

std::unique_ptr<ParallelRasterizer::Workspace> ParallelRasterizer::acquire_workspace(unsigned threads,
                                                                                     std::size_t tiles) {
  std::unique_ptr<Workspace> workspace;
  {
    WorkspaceCache& cache = workspace_cache();
    const std::lock_guard lock(cache.mutex);
    for (auto it = cache.idle.rbegin(); it != cache.idle.rend(); ++it)
      if ((*it)->pool.size() == threads) {
        workspace = std::move(*it);
        cache.idle.erase(std::next(it).base());
        break;
      }
  }
  if (!workspace) {
    workspace = std::make_unique<Workspace>(threads);
    for (Batch& batch : workspace->batches) batch.triangles.resize(kBatchTriangles);
  }
  for (Batch& batch : workspace->batches) {
    reset_bins(batch.bins, tiles);
    batch.tile_events.resize(tiles);
    batch.triangle_count = 0;
    batch.busy_tiles.clear();
    batch.steps.clear();
    batch.draws.clear();
    batch.fetches.clear();
  }
  workspace->cursors.resize(tiles);
  return workspace;
}

void ParallelRasterizer::release_workspace(std::unique_ptr<Workspace> workspace) {
  std::unique_ptr<Workspace> dropped;  // joined outside the lock
  WorkspaceCache& cache = workspace_cache();
  const std::lock_guard lock(cache.mutex);
  cache.idle.push_back(std::move(workspace));
  if (cache.idle.size() > WorkspaceCache::kIdle) {
    dropped = std::move(cache.idle.front());
    cache.idle.erase(cache.idle.begin());
  }
}

ParallelRasterizer::ParallelRasterizer(Framebuffer& framebuffer, const RasterOptions& options, EventSink* sink)
    : framebuffer_(framebuffer),
      options_(options),
      sink_(sink),
      recording_(sink != nullptr),
      lending_(sink != nullptr && sink->lends_storage()),
      streaming_copies_(lending_ && sink->streams_lent_storage()),
      screen_tile_(screen_tile(framebuffer.width(), framebuffer.height(), std::max(1u, options.threads))),
      tile_columns_((framebuffer.width() + screen_tile_ - 1) / screen_tile_),
      tile_rows_((framebuffer.height() + screen_tile_ - 1) / screen_tile_),
      workspace_(acquire_workspace(std::max(1u, options.threads),
                                   static_cast<std::size_t>(tile_columns_) * static_cast<std::size_t>(tile_rows_))),
      pool_(workspace_->pool),
      batches_(workspace_->batches),
      cursors_(workspace_->cursors),
      filling_(&batches_[0]),
      texels_out_(sink),
      events_out_(sink) {
  if (sink_) ordered_ = std::make_unique<OrderedSink>(*this);
  if (options_.hierarchical_z) {
    hiz_ = std::make_unique<HierarchicalZ>();
    hiz_->build(framebuffer_);
  }
  for (unsigned w = 0; w < pool_.size(); ++w) workers_.push_back(std::make_unique<Worker>(sink_, streaming_copies_));
  draw_tiles_ = [this](unsigned w) {
    Batch& batch = *drawing_;
    // Odd workers take tiles from the end of the row-major list, even ones from the start, so
    // that each core draws a region of the screen (and reads its textures) of its own until they
    // meet.
    const bool from_end = (w & 1u) != 0;
    for (std::size_t i = 0; claim_tile(from_end, i);) rasterize_tile(*workers_[w], batch, batch.busy_tiles[i]);
  };
  copy_runs_ = [this](unsigned) { copy_runs(*merging_); };
  clear_rows_ = [this](unsigned w) {
    if (w == 0) return;  // the calling thread goes on with the next triangles
    const int helpers = static_cast<int>(pool_.size()) - 1, rows = framebuffer_.height();
    const int band = (rows + helpers - 1) / helpers, first = (static_cast<int>(w) - 1) * band;
    framebuffer_.clear_rows(first, first + band);
  };
}

ParallelRasterizer::~ParallelRasterizer() {
  if (drawing_ || clearing_) pool_.wait();  // an exception left a batch or a clear on the workers
  release_workspace(std::move(workspace_));
}

EventSink* ParallelRasterizer::event_sink() { return ordered_.get(); }

int ParallelRasterizer::screen_tile(int width, int height, unsigned threads) {
  for (int side = kLargestScreenTile; side > kSmallestScreenTile; side /= 2) {
    const long tiles = static_cast<long>((width + side - 1) / side) * ((height + side - 1) / side);
    if (tiles >= static_cast<long>(kTilesPerThread) * threads) return side;
  }
  return kSmallestScreenTile;
}

bool ParallelRasterizer::claim_tile(bool from_end, std::size_t& index) {
  std::uint64_t range = unclaimed_tiles_.load(std::memory_order_relaxed);
  for (;;) {
    const auto first = static_cast<std::uint32_t>(range >> 32), end = static_cast<std::uint32_t>(range);
    if (first >= end) return false;
    const std::uint64_t rest =
        from_end ? (std::uint64_t{first} << 32 | (end - 1)) : (std::uint64_t{first + 1} << 32 | end);
    if (unclaimed_tiles_.compare_exchange_weak(range, rest, std::memory_order_relaxed)) {
      index = from_end ? end - 1 : first;
      return true;
    }
  }
}

void ParallelRasterizer::tile_range(const TriangleSetup& s, int& tx0, int& ty0, int& tx1, int& ty1) const {
  tx0 = s.x0 / screen_tile_;
  ty0 = s.y0 / screen_tile_;
  tx1 = s.x1 / screen_tile_;
  ty1 = s.y1 / screen_tile_;
}

void ParallelRasterizer::draw(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                              const TriangleState& state) {
  Batch& batch = *filling_;
  // Set up in place, in storage allocated with the workspace: no per-triangle initialisation.
  const std::uint32_t index = batch.triangle_count;
  Binned& binned = batch.triangles[index];
  if (!setup_triangle(a, b, c, framebuffer_.width(), framebuffer_.height(), traversal_alignment(options_.traversal),
                      binned.setup))
    return;
  ++batch.triangle_count;
  ++triangles_;
  binned.state = state;
  binned.textured = state.texture != nullptr && !state.texture->levels.empty();
  int tx0, ty0, tx1, ty1;
  tile_range(binned.setup, tx0, ty0, tx1, ty1);
  for (int ty = ty0; ty <= ty1; ++ty)
    for (int tx = tx0; tx <= tx1; ++tx)
      batch.bins[static_cast<std::size_t>(ty) * static_cast<std::size_t>(tile_columns_) + static_cast<std::size_t>(tx)]
          .push_back(index);
  if (recording_) batch.steps.push_back({StepKind::Triangle, index, 0});
  if (batch.triangle_count >= kBatchTriangles) run_batch(false);
}

void ParallelRasterizer::flush() {
  if (recording_) filling_->steps.push_back({StepKind::Flush, 0, 0});
}

void ParallelRasterizer::clear(const glm::vec4& colour, float depth) {
  if (drawing_ || filling_->triangle_count > 0) run_batch(true);  // draw what came before the clear
  finish_clear();
  framebuffer_.set_clear(colour, depth);
  if (hiz_) hiz_->reset(depth);
  clearing_ = true;
  pool_.start(clear_rows_);
}

void ParallelRasterizer::finish_clear() {
  if (!clearing_) return;
  clearing_ = false;
  pool_.wait();
}

void ParallelRasterizer::finish() { run_batch(true); }

RasterStats ParallelRasterizer::stats() const {
  RasterStats total;
  total.triangles = triangles_;
  for (const auto& w : workers_) {
    const RasterStats& s = w->stats;
    total.quads += s.quads;
    total.fragments += s.fragments;
    total.fragments_passed += s.fragments_passed;
    total.fragments_shaded += s.fragments_shaded;
    total.fragments_rejected_early += s.fragments_rejected_early;
    total.quads_rejected_hiz += s.quads_rejected_hiz;
    total.fragments_textured += s.fragments_textured;
    total.texel_reads += w->texels.reads();
  }
  return total;
}

void ParallelRasterizer::complete_drawing() {
  if (!drawing_) return;
  std::exception_ptr own;
  try {
    draw_tiles_(0);
  } catch (...) {
    own = std::current_exception();
  }
  Batch& batch = *drawing_;
  pool_.wait();
  drawing_ = nullptr;  // only now: a worker that starts late still reads it
  if (own) std::rethrow_exception(own);
  if (recording_) hand_over(batch);
  clear(batch);
}

void ParallelRasterizer::run_batch(bool wait) {
  finish_clear();
  complete_drawing();
  Batch& batch = *filling_;
  batch.busy_tiles.clear();
  for (std::size_t t = 0; t < batch.bins.size(); ++t)
    if (!batch.bins[t].empty()) batch.busy_tiles.push_back(t);
  drawing_ = &batch;
  unclaimed_tiles_.store(static_cast<std::uint64_t>(batch.busy_tiles.size()), std::memory_order_relaxed);
  filling_ = filling_ == &batches_[0] ? &batches_[1] : &batches_[0];
  pool_.start(draw_tiles_);
  if (wait) complete_drawing();
}

void ParallelRasterizer::clear(Batch& batch) {
  for (const std::size_t t : batch.busy_tiles) batch.bins[t].clear();
  batch.busy_tiles.clear();
  batch.triangle_count = 0;
  batch.steps.clear();
  batch.draws.clear();
  batch.fetches.clear();
}

void ParallelRasterizer::rasterize_tile(Worker& worker, Batch& batch, std::size_t tile) {
  TileEvents& out = batch.tile_events[tile];
  out.texels.clear();
  out.framebuffer.clear();
  out.quads.clear();
  out.triangle_ends.clear();
  worker.sink.tile = &out;
  const int tx = static_cast<int>(tile % static_cast<std::size_t>(tile_columns_));
  const int ty = static_cast<int>(tile / static_cast<std::size_t>(tile_columns_));
  const PixelRect clip{tx * screen_tile_, ty * screen_tile_,
                       std::min(framebuffer_.width(), (tx + 1) * screen_tile_) - 1,
                       std::min(framebuffer_.height(), (ty + 1) * screen_tile_) - 1};
  const std::uint64_t texel_base = worker.texels.reads();
  const std::uint64_t event_base = worker.framebuffer_events.records();
  const bool debug = framebuffer_.has_debug_planes();
  const std::vector<std::uint32_t>& bin = batch.bins[tile];
  for (std::size_t i = 0; i < bin.size(); ++i) {
    const Binned& triangle = batch.triangles[bin[i]];
    // The calling thread wrote the next triangle's setup (its 5 cache lines) from another core:
    // ask for them while this one is drawn, instead of stalling on each when it is read.
    if (i + 1 < bin.size()) {
      const char* next = reinterpret_cast<const char*>(&batch.triangles[bin[i + 1]]);
      for (std::size_t line = 0; line < sizeof(Binned); line += 64) __builtin_prefetch(next + line);
    }
    if (triangle.textured) {
      if (debug)
        rasterize_in_tile<true, true>(worker, triangle, clip, out, texel_base, event_base);
      else
        rasterize_in_tile<true, false>(worker, triangle, clip, out, texel_base, event_base);
    } else {
      if (debug)
        rasterize_in_tile<false, true>(worker, triangle, clip, out, texel_base, event_base);
      else
        rasterize_in_tile<false, false>(worker, triangle, clip, out, texel_base, event_base);
    }
    if (recording_) out.triangle_ends.push_back(static_cast<std::uint32_t>(out.quads.size()));
  }
  worker.texels.flush();
  worker.framebuffer_events.flush();
  worker.sink.tile = nullptr;
}

template <bool kTextured, bool kDebug>
void ParallelRasterizer::rasterize_in_tile(Worker& worker, const Binned& triangle, const PixelRect& clip,
                                           TileEvents& out, std::uint64_t texel_base, std::uint64_t event_base) {
  QuadStage stage{framebuffer_, options_, hiz_.get(), worker.texels, worker.framebuffer_events, worker.stats};
  const Traversal traversal = options_.traversal;
  const unsigned hilbert_bits = traversal_hilbert_bits(framebuffer_.width(), framebuffer_.height());
  visit_quads<kTextured, kDebug>(
      stage, triangle.setup, triangle.state, traversal, clip,
      hilbert_bits, [&](int qx, int qy) __attribute__((always_inline)) {
        if (!recording_) return;
        const auto texel_end = static_cast<std::uint32_t>(worker.texels.reads() - texel_base);
        const auto events_end = static_cast<std::uint32_t>(worker.framebuffer_events.records() - event_base);
        const QuadMark* last = out.quads.empty() ? nullptr : &out.quads.back();
        if (last ? (texel_end != last->texel_end || events_end != last->events_end) : (texel_end | events_end) != 0)
          out.quads.push_back({quad_order_key(traversal, qx, qy, hilbert_bits), texel_end, events_end});
      });
}

void ParallelRasterizer::emit_quad(const TileEvents& tile, TileCursor& cursor, const QuadMark& mark) {
  const std::span<const TexelAccess> texels(tile.texels.data() + cursor.texel, mark.texel_end - cursor.texel);
  const std::span<const FramebufferAccess> events(tile.framebuffer.data() + cursor.event,
                                                  mark.events_end - cursor.event);
  cursor.texel = mark.texel_end;
  cursor.event = mark.events_end;
  ++cursor.quad;
  // Early depth test: the depth read comes before the texels; late: after them.
  if (options_.depth_test == DepthTest::Early && !events.empty()) {
    events_out_.append(events.first(1));
    texels_out_.append(texels);
    events_out_.append(events.subspan(1));
  } else {
    texels_out_.append(texels);
    events_out_.append(events);
  }
}

template <typename Stretch>
void ParallelRasterizer::merge_triangle(Batch& batch, std::uint32_t triangle, Stretch&& stretch) {
  int tx0, ty0, tx1, ty1;
  tile_range(batch.triangles[triangle].setup, tx0, ty0, tx1, ty1);
  // The tiles with quads of this triangle, and where its quads end in each.
  constexpr int kInline = 16;
  std::size_t tiles_inline[kInline], ends_inline[kInline];
  std::vector<std::size_t> tiles_heap, ends_heap;
  const int count = (tx1 - tx0 + 1) * (ty1 - ty0 + 1);
  std::size_t* tiles = tiles_inline;
  std::size_t* ends = ends_inline;
  if (count > kInline) {
    tiles_heap.resize(static_cast<std::size_t>(count));
    ends_heap.resize(static_cast<std::size_t>(count));
    tiles = tiles_heap.data();
    ends = ends_heap.data();
  }
  int active = 0;
  for (int ty = ty0; ty <= ty1; ++ty)
    for (int tx = tx0; tx <= tx1; ++tx) {
      const std::size_t t =
          static_cast<std::size_t>(ty) * static_cast<std::size_t>(tile_columns_) + static_cast<std::size_t>(tx);
      TileCursor& cursor = cursors_[t];
      const std::size_t end = batch.tile_events[t].triangle_ends[cursor.triangle++];
      if (end == cursor.quad) continue;
      tiles[active] = t;
      ends[active] = end;
      ++active;
    }
  if (active == 1) {
    stretch(tiles[0], batch.tile_events[tiles[0]], cursors_[tiles[0]], ends[0]);
    return;
  }
  // Several tiles: their quads interleave by their place in the traversal order. Each stretch
  // runs from the tile holding the first quad up to the first quad of any other tile (keys are
  // distinct: one per quad position), so the search over the tiles is per stretch, not per quad:
  // a quad row of a tile under Scanline, a row of its 8x8-pixel blocks under Tiled8, the whole
  // tile under Hilbert8 (whose curve fills each aligned power-of-two block before it leaves it).
  for (;;) {
    int best = -1;
    std::uint64_t best_key = 0, next_key = std::uint64_t{1} << 32;  // next_key: the others' first
    for (int i = 0; i < active; ++i) {
      const TileCursor& cursor = cursors_[tiles[i]];
      if (cursor.quad == ends[i]) continue;
      const std::uint64_t key = batch.tile_events[tiles[i]].quads[cursor.quad].key;
      if (best < 0 || key < best_key) {
        if (best >= 0) next_key = best_key;
        best = i;
        best_key = key;
      } else if (key < next_key) {
        next_key = key;
      }
    }
    if (best < 0) return;
    const TileEvents& tile = batch.tile_events[tiles[best]];
    std::size_t end = cursors_[tiles[best]].quad + 1;
    while (end < ends[best] && tile.quads[end].key < next_key) ++end;
    stretch(tiles[best], tile, cursors_[tiles[best]], end);
  }
}

void ParallelRasterizer::hand_over(Batch& batch) {
  for (const std::size_t t : batch.busy_tiles) cursors_[t] = TileCursor{};
  if (lending_)
    merge_in_place(batch);
  else
    replay(batch);
}

template <typename Triangle, typename Flush>
void ParallelRasterizer::walk_steps(Batch& batch, Triangle&& triangle, Flush&& flush) {
  for (const Step& step : batch.steps) {
    switch (step.kind) {
      case StepKind::BeginDraw:
        sink_->begin_draw(batch.draws[step.first]);
        break;
      case StepKind::Fetches:
        sink_->vertex_fetches(std::span<const VertexFetch>(batch.fetches.data() + step.first, step.last - step.first));
        break;
      case StepKind::Triangle:
        triangle(step.first);
        break;
      case StepKind::Flush:
        flush();
        break;
      case StepKind::EndDraw:
        sink_->end_draw();
        break;
    }
  }
}

void ParallelRasterizer::replay(Batch& batch) {
  const auto emit = [this](std::size_t, const TileEvents& tile, TileCursor& cursor, std::size_t end) {
    while (cursor.quad < end) emit_quad(tile, cursor, tile.quads[cursor.quad]);
  };
  walk_steps(
      batch, [&](std::uint32_t triangle) { merge_triangle(batch, triangle, emit); },
      [this] {
        texels_out_.flush();
        events_out_.flush();
      });
}

// The lending sink keeps each kind's sequence only (sink.h): draws and fetches go to it as the
// steps come, and the batch's texel and framebuffer events after them, all at once.
void ParallelRasterizer::merge_in_place(Batch& batch) {
  std::vector<Run>& runs = workspace_->runs;
  runs.clear();
  const auto plan = [this](std::size_t tile, const TileEvents& events, TileCursor& cursor, std::size_t end) {
    plan_run(tile, events, cursor, end);
  };
  walk_steps(
      batch, [&](std::uint32_t triangle) { merge_triangle(batch, triangle, plan); }, [] {});
  if (runs.empty()) return;
  const std::size_t texels = runs.back().texel_after(), events = runs.back().event_after();
  texels_to_ = texels ? sink_->texel_slots(texels) : std::span<TexelAccess>();
  events_to_ = events ? sink_->framebuffer_slots(events) : std::span<FramebufferAccess>();
  merging_ = &batch;
  next_run_ = 0;
  pool_.run(copy_runs_);
  if (texels) sink_->commit_texels(texels);
  if (events) sink_->commit_framebuffer(events);
}

void ParallelRasterizer::plan_run(std::size_t tile, const TileEvents& events, TileCursor& cursor, std::size_t end) {
  const QuadMark& last_quad = events.quads[end - 1];
  // Runs stay short enough for the workers to share a batch that is one big run.
  constexpr std::uint32_t kRunTexels = 1u << 15;
  std::vector<Run>& runs = workspace_->runs;
  Run* last = runs.empty() ? nullptr : &runs.back();
  if (last && last->tile == tile && last->texel_end == cursor.texel && last->event_end == cursor.event) {
    last->texel_end = last_quad.texel_end;
    last->event_end = last_quad.events_end;
  } else {
    const std::size_t texel_to = last ? last->texel_after() : 0, event_to = last ? last->event_after() : 0;
    runs.push_back({static_cast<std::uint32_t>(tile), static_cast<std::uint32_t>(cursor.texel), last_quad.texel_end,
                    static_cast<std::uint32_t>(cursor.event), last_quad.events_end, texel_to, event_to});
  }
  // A long run is cut into pieces of kRunTexels texels; the framebuffer events stay with the first.
  while (runs.back().texel_end - runs.back().texel_begin > kRunTexels) {
    Run& run = runs.back();
    const Run rest{run.tile,      run.texel_begin + kRunTexels, run.texel_end,    run.event_end,
                   run.event_end, run.texel_to + kRunTexels,    run.event_after()};
    run.texel_end = run.texel_begin + kRunTexels;
    runs.push_back(rest);
  }
  cursor.texel = last_quad.texel_end;
  cursor.event = last_quad.events_end;
  cursor.quad = end;
}

void ParallelRasterizer::copy_runs(const Batch& batch) {
  constexpr std::size_t kClaim = 32;  // runs a worker claims at a time
  // The sink's storage is written once here and read after the frame (streams_lent_storage), and
  // the plane's tens of megabytes of runs are long: streamed, they cost half what memcpy did.
  const auto copy = [this](const auto* first, const auto* last, auto* to) {
    if (streaming_copies_)
      copy_streaming(first, last, to);
    else
      std::copy(first, last, to);
  };
  const std::vector<Run>& runs = workspace_->runs;
  for (std::size_t first = next_run_.fetch_add(kClaim); first < runs.size(); first = next_run_.fetch_add(kClaim)) {
    const std::size_t last = std::min(first + kClaim, runs.size());
    for (std::size_t r = first; r < last; ++r) {
      const Run& run = runs[r];
      const TileEvents& tile = batch.tile_events[run.tile];
      copy(tile.texels.data() + run.texel_begin, tile.texels.data() + run.texel_end, texels_to_.data() + run.texel_to);
      copy(tile.framebuffer.data() + run.event_begin, tile.framebuffer.data() + run.event_end,
           events_to_.data() + run.event_to);
    }
  }
  if (streaming_copies_) streaming_fence();  // before the pool's join hands the events to the sink
}

}  // namespace rastrace
