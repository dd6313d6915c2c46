// LiveBankSink: an EventSink holding a bank of cache simulators, fed while the renderer runs
// (render and simulate in one pass, no file) or by replay_trace() from a file. Both paths run
// this class, so a live render and a replay of its trace give the same numbers to the miss.
//
// What it simulates:
//   vertex         post-transform vertex reuse models over the vertex fetches: FIFO/LRU caches of
//                  k entries (all sizes of a policy in one pass, vertex_cache_sizes.h) and the
//                  warp and batch models of current GPUs (meshoptimizer's warp FIFO, Kerbl et
//                  al.'s batches: cache_sim/vertex_reuse.h), with the statistics of
//                  simulate_vertex_reuse(): lookups, misses, drawn triangles, degenerate
//                  triangles (looked up, not drawn), distinct vertices, warps and lane slots
//   texture        byte caches over the texel accesses, mapped to bytes by a texture layout
//                  (texture_layout.h) built from the textures' level sizes
//   vertex_buffer  byte caches over the vertex fetches: draw d's vertex v at (d << 40) + v*stride
//   address        byte caches over raw addresses (din / address records)
//   framebuffer    depth and colour caches over the framebuffer events: each covered pixel of a
//                  quad's event is one access, mapped to bytes by a pixel layout over the frame
//                  (texture_layout.h, pixel bytes as the element), into a write-back cache
//                  (write_back_cache.h) that reports bytes read and written; flushed at finish()
// Byte caches report accesses, hits, misses, bytes fetched and (three_c) Dinero's compulsory /
// capacity / conflict split from one LRU stack profile per address stream and line size.
// OPT caches buffer their line stream (16 bytes per access, at most kOptMaxAccesses) and are
// simulated at finish(). Statistics are valid after finish().
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "cache_sim/byte_cache.h"
#include "cache_sim/cache_config.h"
#include "cache_sim/lru_profile.h"
#include "cache_sim/opt_cache.h"
#include "cache_sim/texture_layout.h"
#include "cache_sim/vertex_cache.h"
#include "cache_sim/vertex_cache_sizes.h"
#include "cache_sim/vertex_reuse.h"
#include "cache_sim/write_back_cache.h"
#include "traces/sink.h"

namespace rastrace {

struct TextureCacheSpec {
  CacheConfig cache;
  LayoutSpec layout;
};

struct VertexBufferCacheSpec {
  CacheConfig cache;
  std::uint32_t stride = 32;  // bytes per vertex
};

// The framebuffer's two buffers, each with its own cache.
enum class FramebufferBuffer : std::uint8_t { Depth, Colour };
const char* to_string(FramebufferBuffer buffer);  // "depth", "colour"

struct FramebufferCacheSpec {
  FramebufferBuffer buffer = FramebufferBuffer::Depth;
  CacheConfig cache;  // fifo, lru or random
  LayoutSpec layout;  // over the frame's pixels: texel_bytes is the bytes per pixel
};

// The frame a trace draws, for the framebuffer caches' layouts.
struct FrameSize {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
};

struct CacheBankConfig {
  std::vector<VertexCacheSpec> vertex;
  std::vector<TextureCacheSpec> texture;
  std::vector<VertexBufferCacheSpec> vertex_buffer;
  std::vector<CacheConfig> address;
  std::vector<FramebufferCacheSpec> framebuffer;
  bool three_c = true;
  // Vertex ids of different draws index different buffers: start each draw with an empty
  // post-transform cache (as hardware does between draws).
  bool flush_vertex_cache_per_draw = true;
  // The most accesses an OPT cache buffers (opt_cache.h); more is an InputError stating the limit.
  std::uint64_t opt_max_accesses = kOptMaxAccesses;
};

class LiveBankSink final : public EventSink {
 public:
  // Throws InputError on an invalid cache or layout. `textures` gives every texture's level sizes
  // (the trace metadata's textures); texel accesses outside them are InputErrors.
  // `frame` is needed by framebuffer caches only (InputError without it).
  LiveBankSink(CacheBankConfig config, TextureLevels textures, FrameSize frame = {});
  ~LiveBankSink() override;

  void begin_draw(const DrawInfo& draw) override;
  void vertex_fetches(std::span<const VertexFetch> fetches) override;
  void texel_accesses(std::span<const TexelAccess> accesses) override;
  void address_accesses(std::span<const AddressAccess> accesses) override;
  void framebuffer_accesses(std::span<const FramebufferAccess> accesses) override;
  bool wants_framebuffer_events() const override { return !config_.framebuffer.empty(); }
  void end_draw() override;
  void finish() override;

  const CacheBankConfig& config() const { return config_; }
  // One entry per configured cache, in the order of the config (valid after finish()).
  const std::vector<VertexStreamStats>& vertex_stats() const;
  const std::vector<CacheStats>& texture_stats() const;
  const std::vector<CacheStats>& vertex_buffer_stats() const;
  const std::vector<CacheStats>& address_stats() const;
  const std::vector<WriteBackStats>& framebuffer_stats() const;

 private:
  struct LineGroup;
  struct AddressStream;
  struct BankCache;
  struct FramebufferCache;

  void feed_stream(AddressStream& stream);
  void on_vertex(std::uint32_t vertex, bool primitive_start);
  void check_finished() const;

  CacheBankConfig config_;
  TextureLevels textures_;
  bool finished_ = false;

  // Post-transform caches and primitive assembly.
  // Plain caches: one bank per policy, every size of that policy in one pass
  // (vertex_cache_sizes.h). Warp and batch models: one model each.
  struct VertexCacheSlot {
    bool batched = false;
    std::size_t bank = 0;  // plain: the bank; batched: the model
    std::size_t size = 0;  // plain: the size's index in the bank
    // Plain caches count a warp per flushed draw with a miss, as VertexReuseModel does.
    std::uint64_t closed_warps = 0;
    std::uint64_t misses_at_flush = 0;
  };
  std::vector<VertexCacheSizes> vertex_caches_;
  std::vector<VertexReuseModel> vertex_models_;
  std::vector<VertexCacheSlot> vertex_cache_of_;  // per config entry
  std::vector<std::uint32_t> fetched_;            // this batch's vertex ids
  std::array<std::uint32_t, 6> primitive_{};      // the open list primitive's fetched indices
  unsigned primitive_size_ = 0;
  std::vector<VertexStreamStats> vertex_results_;
  VertexStreamStats shared_;  // triangles, degenerates, vertices, indices sent, lookups
  DrawInfo draw_{};
  std::uint32_t draw_serial_ = 0;    // counts begin_draw calls (distinct-vertex stamps)
  std::vector<std::uint32_t> seen_;  // per vertex: draw_serial_ + 1 when referenced in this draw
  PrimitiveAssembler assembler_{PrimitiveType::TriangleList};
  std::uint64_t strips_in_draw_ = 0;

  // Byte caches.
  std::vector<std::unique_ptr<AddressStream>> streams_;
  std::vector<BankCache> caches_;                   // texture, then vertex_buffer, then address
  std::vector<std::size_t> vertex_buffer_streams_;  // stream indices fed by vertex fetches
  std::vector<std::size_t> texture_streams_;
  std::vector<std::size_t> address_streams_;
  std::vector<CacheStats> texture_results_, vertex_buffer_results_, address_results_;

  // Depth and colour caches.
  FrameSize frame_;
  std::vector<FramebufferCache> framebuffer_caches_;
  std::vector<WriteBackStats> framebuffer_results_;
};

}  // namespace rastrace
