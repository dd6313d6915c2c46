// TraceWriter: an EventSink that writes the trace container (trace_format.h). Give it to the
// renderer instead of (or beside) a live cache bank; `rastrace replay` reads the file back.
// Chunks are encoded and compressed by a few threads of the writer's own, each chunk on its own
// (its bytes depend on its records only), and written by one ordered stage in the order they were
// filled: compression overlaps rendering and spreads over the cores, and the file's bytes are
// those a writer with one thread, or none, would write. Memory is bounded: one open chunk per
// record kind, at most chunks_in_flight(threads) = 2 x threads + 2 full chunks between filled and
// written (submitting waits for room), plus 24 bytes of index per chunk, so frames of any length
// stream to disk. When a writer ends, its compressors (one per thread, at most kMostThreads) and
// chunks (at most chunks_in_flight + 1) are kept for the next writer in the process, so that a
// program writing a trace per frame does not allocate them afresh for each. The file appears
// only when finish() succeeds (core/atomic_file.h); a writer destroyed without finish() leaves
// nothing behind. The first error (a failed write, disk full) is thrown from the next submission
// of a chunk or from finish().
//
//   TraceMetadata meta{.scene = "builtin:bunny", .ordering = "tipsy", .width = 512, .height = 512,
//                      .filter = "trilinear", .textures = {mip_chain_sizes(256, 256)}};
//   TraceWriter writer("frame.rtrace", meta);
//   render(scene, writer);   // calls begin_draw / vertex_fetches / texel_accesses / end_draw
//   writer.finish();
//
// Several frames: begin_frame(f) ends every open chunk (no chunk spans two frames) and stamps the
// chunks after it with f. Every file is version 4, of one frame or several (trace_format.h).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "traces/events.h"
#include "traces/sink.h"
#include "traces/texel_columns.h"
#include "traces/trace_format.h"
#include "traces/trace_metadata.h"

namespace rastrace {

struct TraceWriterOptions {
  int zstd_level = 3;
  std::uint32_t chunk_records = kChunkRecords;  // records per chunk (tests use small chunks)
  unsigned compression_threads = 0;             // 0: one per core, up to 8
};

class TraceWriter : public EventSink {
 public:
  // Opens "<path>.tmp.<pid>" for writing; throws InputError if it cannot.
  TraceWriter(const std::string& path, TraceMetadata metadata, TraceWriterOptions options = {});
  ~TraceWriter() override;

  // Frames never decrease and fit the format's u16; throws std::invalid_argument otherwise.
  void begin_frame(std::uint32_t frame) override;
  void begin_draw(const DrawInfo& draw) override;
  void vertex_fetches(std::span<const VertexFetch> fetches) override;
  void texel_accesses(std::span<const TexelAccess> accesses) override;
  void address_accesses(std::span<const AddressAccess> accesses) override;
  void framebuffer_accesses(std::span<const FramebufferAccess> accesses) override;
  bool wants_framebuffer_events() const override { return true; }
  void end_draw() override;
  // Flushes the last chunks, writes the index and footer, renames the file into place.
  void finish() override;

  // The frame of the chunks being filled; frames written: frame() + 1.
  std::uint32_t frame() const { return frame_; }
  std::uint64_t records(RecordKind kind) const { return counts_[static_cast<int>(kind)]; }
  // Bytes written so far (the file size once finished).
  std::uint64_t bytes_written() const;
  // Compression threads when there is one per core: beyond a few, the renderer, filling chunks on
  // one thread, is the bound.
  static constexpr unsigned kMostThreads = 8;
  // Full chunks that may be between filled and written before submitting one waits.
  static constexpr std::size_t chunks_in_flight(unsigned compression_threads) {
    return 2 * std::size_t{compression_threads} + 2;
  }

 private:
  struct Chunk;
  void flush_vertices(bool ends_draw);
  void flush_texels();
  void flush_addresses();
  void flush_framebuffer();
  // Hands a chunk to the compression threads (waiting while the most chunks allowed are in flight).
  void submit(Chunk& chunk, RecordKind kind, std::uint8_t flags, std::uint32_t records);
  Chunk take_spare();
  // Swaps the records being filled (every kind's) with `chunk`'s.
  void exchange_open_records(Chunk& chunk);

  struct State;
  class KeptResources;
  std::unique_ptr<State> state_;
  TraceWriterOptions options_;
  std::uint64_t counts_[5] = {0, 0, 0, 0, 0};
  bool finished_ = false;
  std::uint16_t frame_ = 0;
  // Open draw: its info, whether its first chunk has been written.
  bool draw_open_ = false;
  bool draw_started_ = false;
  DrawInfo draw_{};
  std::vector<VertexFetch> vertices_;
  TexelColumns texels_;
  std::vector<AddressAccess> addresses_;
  std::vector<FramebufferAccess> framebuffer_;
};

}  // namespace rastrace
