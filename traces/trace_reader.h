// Reading trace files (trace_format.h) in bounded memory: one decoded chunk at a time.
//   TraceReader         the container: metadata, chunk index, random access to any chunk
//   VertexTraceReader   streams the vertex fetches, draw by draw
//   TexelTraceReader    streams the texel accesses
//   replay_trace()      feeds a whole file into any EventSink in file order; `rastrace replay`
//                       does exactly this into a LiveBankSink, so a replay and a live render
//                       through the same bank run the same code.
// Errors are InputErrors naming the file, the chunk and its byte offset: wrong magic, unknown
// version, missing footer (truncated file; the truncated chunk is located), checksum mismatch,
// a chunk whose header disagrees with the index, frames decreasing among a kind's chunks,
// undecodable records.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "traces/events.h"
#include "traces/sink.h"
#include "traces/trace_format.h"
#include "traces/trace_metadata.h"

namespace rastrace {

class Progress;

// Which record kinds replay_trace() delivers (and a TraceReader reads ahead).
struct ReplayKinds {
  bool vertices = true;
  bool texels = true;
  bool addresses = true;
  bool framebuffer = true;
  // Texel records' pixel position and triangle. False: a trace file's reader leaves them 0, their
  // columns checked by the chunk checksum but not decoded (for consumers of texel addresses alone;
  // text formats still carry them).
  bool texel_details = true;
};

// Only the vector of the chunk's kind holds this chunk's records; the others are stale.
struct DecodedChunk {
  RecordKind kind = RecordKind::Vertex;
  std::uint8_t flags = 0;  // kChunkStartsDraw, kChunkEndsDraw (vertex chunks)
  std::uint64_t first_record = 0;
  DrawInfo draw;  // vertex chunks: the draw they belong to
  std::vector<VertexFetch> vertices;
  std::vector<TexelAccess> texels;
  std::vector<AddressAccess> addresses;
  std::vector<FramebufferAccess> framebuffer;
};

class TraceReader {
 public:
  // Reads the header, the metadata and the chunk index; throws InputError on a bad file.
  explicit TraceReader(const std::string& path);
  ~TraceReader();

  const std::string& path() const { return path_; }
  const TraceMetadata& metadata() const { return metadata_; }
  const std::vector<ChunkInfo>& chunks() const { return chunks_; }
  std::uint64_t records(RecordKind kind) const { return counts_[static_cast<int>(kind)]; }
  std::uint64_t file_bytes() const { return file_bytes_; }
  // The container version the file was written in (trace_format.h).
  std::uint32_t version() const { return version_; }
  // Frames the file holds (the largest chunk frame + 1; 1 before version 3 and for no chunks).
  std::uint32_t frames() const { return frames_; }

  // Reads, checks and decodes chunk i. The result stays valid until the next call. Any order
  // works and gives the same records; a chunk's error is thrown by the call for that chunk.
  const DecodedChunk& read_chunk(std::size_t i);
  // Reads chunk i and checks its checksum, reserved bytes and agreement with the index without
  // decoding it (for chunks a caller skips); throws the chunk's InputError.
  void check_chunk(std::size_t i);

  // Read-ahead. Once chunks are read in file order (chunk i, then the next chunk of the kinds
  // below), a second thread with its own stream and zstd context reads, checks and decodes the
  // following chunks while the caller works on chunk i, and a caller that would wait for it
  // decodes the chunk after instead. At most 5 decoded chunks are in memory. A read out of order
  // drops what was read ahead. On by default when the machine has 2 or more hardware threads
  // and the environment does not set RASTRACE_READ_AHEAD=0.
  void set_read_ahead(bool enabled);
  // The kinds the caller will read (default: all); chunks of other kinds are not read ahead and
  // skipping them still counts as reading in order. Also whether texel details are decoded.
  void set_read_ahead_kinds(ReplayKinds kinds);

  // True when `path` starts with the trace magic (to tell traces from CSV or din files).
  static bool is_trace_file(const std::string& path);

 private:
  struct ReadState;  // decoding buffers, read-ahead slots and thread (trace_reader.cpp)
  [[noreturn]] void fail_truncated(std::ifstream& in, std::uint64_t header_end);
  void fail_if_trailing_data(std::ifstream& in, std::uint64_t index_offset, std::size_t chunk,
                             const std::uint8_t* index_header);

  std::string path_;
  std::uint64_t file_bytes_ = 0;
  std::uint64_t index_offset_ = 0;
  TraceMetadata metadata_;
  std::vector<ChunkInfo> chunks_;
  std::uint64_t counts_[5] = {0, 0, 0, 0, 0};
  std::uint32_t version_ = kTraceVersion;
  std::uint32_t frames_ = 1;
  std::unique_ptr<ReadState> state_;
};

// Feeds every chunk of the file into the sink, in file order, then calls sink.finish(). A file of
// several frames (version 3 or 4) calls sink.begin_frame(f) before the first chunk of each frame f. Chunks
// of kinds not asked for are still checked (check_chunk), so a damaged file never passes.
// Progress (when given) advances by records.
void replay_trace(TraceReader& reader, EventSink& sink, ReplayKinds kinds = {}, Progress* progress = nullptr);

// Reads, checks and decodes every chunk (checksums, reserved bytes, index agreement, records);
// returns the records read. Throws the first damaged chunk's InputError (chunk and byte offset).
std::uint64_t verify_trace(TraceReader& reader);

struct VertexBatch {
  DrawInfo draw;
  bool starts_draw = false;  // first batch of `draw`
  bool ends_draw = false;    // last batch of `draw`
  std::span<const VertexFetch> fetches;
};

class VertexTraceReader {
 public:
  explicit VertexTraceReader(const std::string& path) : reader_(path) {
    reader_.set_read_ahead_kinds({true, false, false, false});
  }
  const TraceMetadata& metadata() const { return reader_.metadata(); }
  std::uint64_t records() const { return reader_.records(RecordKind::Vertex); }
  // The next batch (one chunk); false at the end of the file.
  bool next(VertexBatch& batch);
  void set_read_ahead(bool enabled) { reader_.set_read_ahead(enabled); }

 private:
  TraceReader reader_;
  std::size_t next_chunk_ = 0;
};

class TexelTraceReader {
 public:
  explicit TexelTraceReader(const std::string& path) : reader_(path) {
    reader_.set_read_ahead_kinds({false, true, false, false});
  }
  // Decode texture, level, x and y only (pixel_x, pixel_y and triangle read as 0; ReplayKinds).
  void set_addresses_only(bool addresses_only) {
    reader_.set_read_ahead_kinds({false, true, false, false, !addresses_only});
  }
  const TraceMetadata& metadata() const { return reader_.metadata(); }
  std::uint64_t records() const { return reader_.records(RecordKind::Texel); }
  bool next(std::span<const TexelAccess>& batch);
  void set_read_ahead(bool enabled) { reader_.set_read_ahead(enabled); }

 private:
  TraceReader reader_;
  std::size_t next_chunk_ = 0;
};

}  // namespace rastrace
