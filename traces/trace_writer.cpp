#include "traces/trace_writer.h"

#include <cstring>
#include <stdexcept>

#include <zstd.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "traces/crc32c.h"

#ifndef RASTRACE_VERSION
#define RASTRACE_VERSION "unknown"
#endif

namespace rastrace {

namespace {
template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}
}  // namespace

struct TraceWriter::State {
  explicit State(const std::string& path) : file(path) {}
  ~State() { ZSTD_freeCCtx(cctx); }
  AtomicFile file;
  ZSTD_CCtx* cctx = ZSTD_createCCtx();
  std::string path;
};

TraceWriter::TraceWriter(const std::string& path, TraceMetadata metadata, TraceWriterOptions options)
    : options_(options) {
  if (options_.chunk_records == 0 || options_.chunk_records > kMaxChunkRecords)
    throw InputError("trace chunk size " + std::to_string(options_.chunk_records) + ": expected 1..16777216 records");
  state_ = std::make_unique<State>(path);
  state_->path = path;
  if (!state_->file.stream()) throw_in_file(path, "cannot open for writing");
  if (metadata.tool_version.empty()) metadata.tool_version = RASTRACE_VERSION;
  const std::string json = metadata_to_json(metadata);
  std::string header(kTraceMagic, 8);
  put<std::uint32_t>(header, kTraceVersion);
  put<std::uint32_t>(header, static_cast<std::uint32_t>(json.size()));
  header += json;
  put<std::uint32_t>(header, crc32c(json.data(), json.size()));
  write(header.data(), header.size());
  vertices_.reserve(options_.chunk_records);
}

TraceWriter::~TraceWriter() = default;

void TraceWriter::write(const void* data, std::size_t size) {
  // After a failed write the file is lost: later events (from destructors flushing while the
  // first error unwinds) are dropped instead of throwing again, and finish() reports it.
  if (failed_) return;
  state_->file.stream().write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!state_->file.stream()) {
    failed_ = true;
    throw_in_file(state_->path, "write failed (disk full?)");
  }
  offset_ += size;
}

void TraceWriter::write_chunk(RecordKind kind, std::uint8_t flags, std::uint32_t records) {
  const std::size_t bound = ZSTD_compressBound(raw_.size());
  compressed_.resize(bound);
  const std::size_t stored =
      ZSTD_compressCCtx(state_->cctx, compressed_.data(), bound, raw_.data(), raw_.size(), options_.zstd_level);
  if (ZSTD_isError(stored)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(stored));
  std::uint64_t& count = counts_[static_cast<int>(kind)];
  std::string header;
  put<std::uint32_t>(header, kChunkTag);
  put<std::uint8_t>(header, static_cast<std::uint8_t>(kind));
  put<std::uint8_t>(header, flags);
  put<std::uint16_t>(header, 0);
  put<std::uint32_t>(header, records);
  put<std::uint32_t>(header, static_cast<std::uint32_t>(stored));
  put<std::uint32_t>(header, static_cast<std::uint32_t>(raw_.size()));
  put<std::uint64_t>(header, count);
  const std::uint32_t crc = crc32c(compressed_.data(), stored, crc32c(header.data(), header.size()));
  put<std::uint32_t>(header, crc);
  index_.push_back({offset_, count, records, kind});
  count += records;
  write(header.data(), header.size());
  write(compressed_.data(), stored);
}

void TraceWriter::flush_vertices(bool ends_draw) {
  if (!draw_open_) return;
  if (vertices_.empty() && draw_started_ && !ends_draw) return;
  encode_vertex_records(draw_, vertices_, raw_);
  const std::uint8_t flags =
      static_cast<std::uint8_t>((draw_started_ ? 0 : kChunkStartsDraw) | (ends_draw ? kChunkEndsDraw : 0));
  write_chunk(RecordKind::Vertex, flags, static_cast<std::uint32_t>(vertices_.size()));
  vertices_.clear();
  draw_started_ = true;
  if (ends_draw) draw_open_ = false;
}

void TraceWriter::flush_texels() {
  if (texels_.empty()) return;
  encode_texel_records(texels_, raw_);
  write_chunk(RecordKind::Texel, 0, static_cast<std::uint32_t>(texels_.size()));
  texels_.clear();
}

void TraceWriter::flush_addresses() {
  if (addresses_.empty()) return;
  encode_address_records(addresses_, raw_);
  write_chunk(RecordKind::Address, 0, static_cast<std::uint32_t>(addresses_.size()));
  addresses_.clear();
}

void TraceWriter::flush_framebuffer() {
  if (framebuffer_.empty()) return;
  encode_framebuffer_records(framebuffer_, raw_);
  write_chunk(RecordKind::Framebuffer, 0, static_cast<std::uint32_t>(framebuffer_.size()));
  framebuffer_.clear();
}

void TraceWriter::begin_draw(const DrawInfo& draw) {
  if (finished_) throw std::logic_error("TraceWriter: begin_draw after finish");
  if (draw_open_) flush_vertices(true);  // a draw without end_draw ends where the next begins
  draw_ = draw;
  draw_open_ = true;
  draw_started_ = false;
}

void TraceWriter::vertex_fetches(std::span<const VertexFetch> fetches) {
  if (finished_) throw std::logic_error("TraceWriter: vertex_fetches after finish");
  if (!draw_open_) begin_draw(DrawInfo{});
  while (!fetches.empty()) {
    const std::size_t room = options_.chunk_records - vertices_.size();
    const std::size_t take = std::min(room, fetches.size());
    vertices_.insert(vertices_.end(), fetches.begin(), fetches.begin() + static_cast<std::ptrdiff_t>(take));
    fetches = fetches.subspan(take);
    if (vertices_.size() == options_.chunk_records) flush_vertices(false);
  }
}

namespace {
// Appends records to a kind's pending chunk, handing each full chunk to `flush`.
template <typename Record, typename Flush>
void append_in_chunks(std::vector<Record>& pending, std::span<const Record> records, std::size_t chunk_records,
                      Flush flush) {
  while (!records.empty()) {
    const std::size_t take = std::min(chunk_records - pending.size(), records.size());
    pending.insert(pending.end(), records.begin(), records.begin() + static_cast<std::ptrdiff_t>(take));
    records = records.subspan(take);
    if (pending.size() == chunk_records) flush();
  }
}
}  // namespace

void TraceWriter::texel_accesses(std::span<const TexelAccess> accesses) {
  if (finished_) throw std::logic_error("TraceWriter: texel_accesses after finish");
  append_in_chunks(texels_, accesses, options_.chunk_records, [this] { flush_texels(); });
}

void TraceWriter::address_accesses(std::span<const AddressAccess> accesses) {
  if (finished_) throw std::logic_error("TraceWriter: address_accesses after finish");
  append_in_chunks(addresses_, accesses, options_.chunk_records, [this] { flush_addresses(); });
}

void TraceWriter::framebuffer_accesses(std::span<const FramebufferAccess> accesses) {
  if (finished_) throw std::logic_error("TraceWriter: framebuffer_accesses after finish");
  append_in_chunks(framebuffer_, accesses, options_.chunk_records, [this] { flush_framebuffer(); });
}

void TraceWriter::end_draw() {
  if (draw_open_) flush_vertices(true);
}

void TraceWriter::finish() {
  if (finished_) return;
  if (failed_) throw_in_file(state_->path, "write failed (disk full?)");
  if (draw_open_) flush_vertices(true);
  flush_texels();
  flush_framebuffer();
  flush_addresses();
  std::string index;
  put<std::uint32_t>(index, kIndexTag);
  put<std::uint32_t>(index, 0);
  put<std::uint64_t>(index, index_.size());
  for (const ChunkInfo& c : index_) {
    put<std::uint64_t>(index, c.offset);
    put<std::uint64_t>(index, c.first_record);
    put<std::uint32_t>(index, c.records);
    put<std::uint8_t>(index, static_cast<std::uint8_t>(c.kind));
    index.append(3, '\0');
  }
  const std::uint64_t index_offset = offset_;
  std::string footer;
  put<std::uint64_t>(footer, index_offset);
  put<std::uint32_t>(footer, crc32c(index.data(), index.size()));
  put<std::uint32_t>(footer, 0);
  footer.append(kTraceEndMagic, 8);
  write(index.data(), index.size());
  write(footer.data(), footer.size());
  state_->file.commit();  // flushes: throws "write failed" when the last bytes do not fit
  finished_ = true;
}

}  // namespace rastrace
