// TraceWriter: an EventSink that writes the trace container (trace_format.h). Give it to the
// renderer instead of (or beside) a live cache bank; `rastrace replay` reads the file back.
// Memory is bounded (one chunk per record kind plus 24 bytes of index per chunk), so frames of
// any length stream to disk. The file appears only when finish() succeeds (core/atomic_file.h);
// a writer destroyed without finish() leaves nothing behind.
//
//   TraceMetadata meta{.scene = "builtin:bunny", .ordering = "tipsy", .width = 512, .height = 512,
//                      .filter = "trilinear", .textures = {mip_chain_sizes(256, 256)}};
//   TraceWriter writer("frame.rtrace", meta);
//   render(scene, writer);   // calls begin_draw / vertex_fetches / texel_accesses / end_draw
//   writer.finish();
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "traces/events.h"
#include "traces/sink.h"
#include "traces/trace_format.h"
#include "traces/trace_metadata.h"

namespace rastrace {

struct TraceWriterOptions {
  int zstd_level = 3;
  std::uint32_t chunk_records = kChunkRecords;  // records per chunk (tests use small chunks)
};

class TraceWriter : public EventSink {
 public:
  // Opens "<path>.tmp.<pid>" for writing; throws InputError if it cannot.
  TraceWriter(const std::string& path, TraceMetadata metadata, TraceWriterOptions options = {});
  ~TraceWriter() override;

  void begin_draw(const DrawInfo& draw) override;
  void vertex_fetches(std::span<const VertexFetch> fetches) override;
  void texel_accesses(std::span<const TexelAccess> accesses) override;
  void address_accesses(std::span<const AddressAccess> accesses) override;
  void framebuffer_accesses(std::span<const FramebufferAccess> accesses) override;
  bool wants_framebuffer_events() const override { return true; }
  void end_draw() override;
  // Flushes the last chunks, writes the index and footer, renames the file into place.
  void finish() override;

  std::uint64_t records(RecordKind kind) const { return counts_[static_cast<int>(kind)]; }
  // Bytes written so far (the file size once finished).
  std::uint64_t bytes_written() const { return offset_; }

 private:
  void flush_vertices(bool ends_draw);
  void flush_texels();
  void flush_addresses();
  void flush_framebuffer();
  void write_chunk(RecordKind kind, std::uint8_t flags, std::uint32_t records);
  void write(const void* data, std::size_t size);

  struct State;
  std::unique_ptr<State> state_;
  TraceWriterOptions options_;
  std::uint64_t offset_ = 0;
  std::uint64_t counts_[5] = {0, 0, 0, 0, 0};
  bool finished_ = false;
  bool failed_ = false;  // a write failed: the file is lost
  // Open draw: its info, whether its first chunk has been written.
  bool draw_open_ = false;
  bool draw_started_ = false;
  DrawInfo draw_{};
  std::vector<VertexFetch> vertices_;
  std::vector<TexelAccess> texels_;
  std::vector<AddressAccess> addresses_;
  std::vector<FramebufferAccess> framebuffer_;
  std::vector<ChunkInfo> index_;
  std::string raw_;
  std::string compressed_;
};

}  // namespace rastrace
