#include "traces/trace_writer.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include <zstd.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "traces/append_bytes.h"
#include "traces/crc32c.h"

#ifndef RASTRACE_VERSION
#define RASTRACE_VERSION "unknown"
#endif

namespace rastrace {

// A full chunk on its way to the file: its records of one kind (the other vectors are empty),
// then its bytes as they go into the file.
struct TraceWriter::Chunk {
  RecordKind kind = RecordKind::Vertex;
  std::uint8_t flags = 0;
  std::uint32_t records = 0;
  std::uint64_t first_record = 0;
  std::uint16_t frame = 0;
  std::uint64_t sequence = 0;  // submission order, which is the file's order
  DrawInfo draw;
  std::vector<VertexFetch> vertices;
  TexelColumns texels;
  std::vector<AddressAccess> addresses;
  std::vector<FramebufferAccess> framebuffer;
  std::string header, compressed;
  std::size_t stored = 0;  // bytes of compressed that are the chunk's payload
  // Empties the records, keeping their memory for the next chunk.
  void clear_records() {
    vertices.clear();
    texels.size = 0;
    addresses.clear();
    framebuffer.clear();
  }
};

namespace {
// A compression thread's own: zstd context and encoding buffer, kept from chunk to chunk.
struct Compressor {
  Compressor() : cctx(ZSTD_createCCtx()) {
    if (!cctx) throw std::bad_alloc();
  }
  ~Compressor() { ZSTD_freeCCtx(cctx); }
  Compressor(const Compressor&) = delete;
  Compressor& operator=(const Compressor&) = delete;
  ZSTD_CCtx* cctx;
  std::string raw;
  ColumnScratch scratch;
};
}  // namespace

// What a writer leaves to the next one in the process: compressors (zstd context, encoding
// buffers) and chunks with their record vectors, all allocated and their pages touched. A
// process writing trace after trace (a file per frame, per ordering, per configuration of a
// sweep) then allocates them once instead of faulting in some megabytes of fresh pages for every
// file. Bounded: at most one compressor per thread of the most automatic threads, and the chunks
// the last writer had in flight and open. Never destroyed, so that a writer outliving static
// destruction still finds it.
class TraceWriter::KeptResources {
 public:
  static KeptResources& get() {
    static KeptResources* kept = new KeptResources;
    return *kept;
  }
  std::unique_ptr<Compressor> compressor() {
    {
      const std::lock_guard lock(mutex_);
      if (!compressors_.empty()) {
        std::unique_ptr<Compressor> kept = std::move(compressors_.back());
        compressors_.pop_back();
        return kept;
      }
    }
    return std::make_unique<Compressor>();
  }
  void keep(std::unique_ptr<Compressor> compressor) {
    const std::lock_guard lock(mutex_);
    if (compressors_.size() < kMostThreads) compressors_.push_back(std::move(compressor));
  }
  std::optional<Chunk> chunk() {
    const std::lock_guard lock(mutex_);
    if (chunks_.empty()) return std::nullopt;
    std::optional<Chunk> kept(std::move(chunks_.back()));
    chunks_.pop_back();
    return kept;
  }
  // Keeps chunks while fewer than `most` are kept.
  void keep(std::vector<Chunk>& chunks, std::size_t most) {
    const std::lock_guard lock(mutex_);
    for (Chunk& chunk : chunks)
      if (chunks_.size() < most) chunks_.push_back(std::move(chunk));
    chunks.clear();
  }

 private:
  std::mutex mutex_;
  std::vector<std::unique_ptr<Compressor>> compressors_;
  std::vector<Chunk> chunks_;
};

// Chunks flow: submit() queues them; compression threads take them in order, encode and compress
// each independently (a chunk's bytes do not depend on the thread or on the chunks around it);
// the ordered stage writes them by sequence. The ordered stage is whichever compression thread
// finds the next chunk due and nobody writing: it writes every consecutive finished chunk, so
// the file is written by one thread at a time, in submission order.
struct TraceWriter::State {
  State(const std::string& file_path, int level, unsigned compression_threads)
      : file(file_path), path(file_path), zstd_level(level), threads(compression_threads),
        limit(TraceWriter::chunks_in_flight(compression_threads)), done(limit) {}
  ~State() {
    stop();
    KeptResources::get().keep(spare, limit);
  }
  void write(const void* data, std::size_t size) {
    file.stream().write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!file.stream()) throw_in_file(path, "write failed (disk full?)");
    offset += size;
  }
  void compress(Chunk& chunk, Compressor& compressor) const {
    std::string& raw = compressor.raw;
    switch (chunk.kind) {
      case RecordKind::Vertex:
        encode_vertex_records(chunk.draw, chunk.vertices, raw, compressor.scratch);
        break;
      case RecordKind::Texel:
        encode_texel_records(chunk.texels, raw, compressor.scratch);
        break;
      case RecordKind::Address:
        encode_address_records(chunk.addresses, raw, compressor.scratch);
        break;
      case RecordKind::Framebuffer:
        encode_framebuffer_records(chunk.framebuffer, raw, compressor.scratch);
        break;
    }
    const std::size_t bound = ZSTD_compressBound(raw.size());
    chunk.compressed.resize(bound);
    const std::size_t stored =
        ZSTD_compressCCtx(compressor.cctx, chunk.compressed.data(), bound, raw.data(), raw.size(), zstd_level);
    if (ZSTD_isError(stored)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(stored));
    chunk.stored = stored;
    std::string& header = chunk.header;
    header.clear();
    append_bytes<std::uint32_t>(header, kChunkTag);
    append_bytes<std::uint8_t>(header, static_cast<std::uint8_t>(chunk.kind));
    append_bytes<std::uint8_t>(header, chunk.flags);
    append_bytes<std::uint16_t>(header, chunk.frame);
    append_bytes<std::uint32_t>(header, chunk.records);
    append_bytes<std::uint32_t>(header, static_cast<std::uint32_t>(stored));
    append_bytes<std::uint32_t>(header, static_cast<std::uint32_t>(raw.size()));
    append_bytes<std::uint64_t>(header, chunk.first_record);
    const std::uint32_t crc = crc32c(chunk.compressed.data(), stored, crc32c(header.data(), header.size()));
    append_bytes<std::uint32_t>(header, crc);
  }
  // The ordered stage's work on one chunk.
  void write_chunk(const Chunk& chunk) {
    index.push_back({offset.load(), chunk.first_record, chunk.records, chunk.kind, chunk.frame});
    write(chunk.header.data(), chunk.header.size());
    write(chunk.compressed.data(), chunk.stored);
  }
  void run() {
    std::unique_ptr<Compressor> compressor;
    for (;;) {
      Chunk chunk;
      {
        std::unique_lock lock(mutex);
        ready.wait(lock, [this] { return stopping || !queue.empty(); });
        if (queue.empty()) {
          if (compressor) KeptResources::get().keep(std::move(compressor));
          return;
        }
        chunk = std::move(queue.front());
        queue.pop_front();
      }
      std::exception_ptr failure;
      try {
        if (!failed()) {
          if (!compressor) compressor = KeptResources::get().compressor();
          compress(chunk, *compressor);
        }
      } catch (...) {
        failure = std::current_exception();
      }
      {
        const std::lock_guard lock(mutex);
        if (failure && !error) error = failure;
        done[chunk.sequence % limit] = std::move(chunk);
      }
      write_due();
    }
  }
  // The ordered stage: writes the finished chunks that are due, unless another thread is at it
  // (it finds this thread's chunk before it stops: both look under the lock).
  void write_due() {
    std::unique_lock lock(mutex);
    if (writing) return;
    writing = true;
    for (;;) {
      std::optional<Chunk>& slot = done[next_write % limit];
      if (!slot || slot->sequence != next_write) break;
      Chunk chunk = std::move(*slot);
      slot.reset();
      const bool skip = error != nullptr;
      lock.unlock();
      std::exception_ptr failure;
      try {
        if (!skip) write_chunk(chunk);
      } catch (...) {
        failure = std::current_exception();
      }
      chunk.clear_records();
      lock.lock();
      if (failure && !error) error = failure;
      spare.push_back(std::move(chunk));
      ++next_write;
      --in_flight;
      space.notify_all();
    }
    writing = false;
  }
  bool failed() {
    const std::lock_guard lock(mutex);
    return error != nullptr;
  }
  // Compresses and writes what is queued, and ends the threads (the queue is emptied first).
  void stop() {
    {
      const std::lock_guard lock(mutex);
      stopping = true;
    }
    ready.notify_all();
    for (std::thread& thread : pool)
      if (thread.joinable()) thread.join();
  }

  AtomicFile file;
  std::string path;
  int zstd_level;
  unsigned threads;
  std::size_t limit;  // chunks submitted and not yet written, at most
  std::atomic<std::uint64_t> offset{0};
  std::vector<ChunkInfo> index;  // the ordered stage's until the threads have stopped
  std::mutex mutex;
  std::condition_variable ready, space;
  std::deque<Chunk> queue;                // waiting for a compression thread
  std::vector<std::optional<Chunk>> done;  // compressed, waiting for their turn: by sequence % limit
  std::uint64_t next_sequence = 0, next_write = 0;
  std::size_t in_flight = 0;
  bool writing = false;
  std::vector<Chunk> spare;  // written chunks, their vectors' capacity kept for reuse
  bool stopping = false;
  std::exception_ptr error;
  std::vector<std::thread> pool;
};

TraceWriter::TraceWriter(const std::string& path, TraceMetadata metadata, TraceWriterOptions options)
    : options_(options) {
  if (options_.chunk_records == 0 || options_.chunk_records > kMaxChunkRecords)
    throw InputError("trace chunk size " + std::to_string(options_.chunk_records) + ": expected 1..1048576 records");
  const unsigned threads = options_.compression_threads
                               ? options_.compression_threads
                               : std::clamp(std::thread::hardware_concurrency(), 1u, kMostThreads);
  state_ = std::make_unique<State>(path, options_.zstd_level, threads);
  if (!state_->file.stream()) throw_in_file(path, "cannot open for writing");
  if (metadata.tool_version.empty()) metadata.tool_version = RASTRACE_VERSION;
  const std::string json = metadata_to_json(metadata);
  std::string header(kTraceMagic, 8);
  append_bytes<std::uint32_t>(header, kTraceVersion);
  append_bytes<std::uint32_t>(header, static_cast<std::uint32_t>(json.size()));
  header += json;
  append_bytes<std::uint32_t>(header, crc32c(json.data(), json.size()));
  state_->write(header.data(), header.size());
  // The open chunks start in memory an earlier writer kept, where there is some (kept chunks are
  // empty).
  Chunk kept = take_spare();
  exchange_open_records(kept);
  vertices_.reserve(options_.chunk_records);
  texels_.reset(options_.chunk_records);
  for (unsigned t = 0; t < threads; ++t) state_->pool.emplace_back([state = state_.get()] { state->run(); });
}

TraceWriter::~TraceWriter() {
  const std::size_t most_kept = state_->limit + 1;  // the chunks in flight, and one of open vectors
  state_.reset();                                   // the threads end, the spare chunks are kept
  // The vectors being filled are kept too, in a chunk of their own.
  std::vector<Chunk> open(1);
  exchange_open_records(open[0]);
  open[0].clear_records();
  KeptResources::get().keep(open, most_kept);
}

void TraceWriter::exchange_open_records(Chunk& chunk) {
  std::swap(chunk.vertices, vertices_);
  std::swap(chunk.texels, texels_);
  std::swap(chunk.addresses, addresses_);
  std::swap(chunk.framebuffer, framebuffer_);
}

std::uint64_t TraceWriter::bytes_written() const { return state_->offset.load(); }

TraceWriter::Chunk TraceWriter::take_spare() {
  {
    const std::lock_guard lock(state_->mutex);
    if (!state_->spare.empty()) {
      Chunk chunk = std::move(state_->spare.back());
      state_->spare.pop_back();
      return chunk;
    }
  }
  if (std::optional<Chunk> kept = KeptResources::get().chunk()) return std::move(*kept);
  return Chunk{};
}

void TraceWriter::submit(Chunk& chunk, RecordKind kind, std::uint8_t flags, std::uint32_t records) {
  std::uint64_t& count = counts_[static_cast<int>(kind)];
  chunk.kind = kind;
  chunk.flags = flags;
  chunk.records = records;
  chunk.first_record = count;
  chunk.frame = frame_;
  count += records;
  State& state = *state_;
  {
    std::unique_lock lock(state.mutex);
    state.space.wait(lock, [&] { return state.error || state.in_flight < state.limit; });
    if (state.error) std::rethrow_exception(state.error);
    chunk.sequence = state.next_sequence++;
    ++state.in_flight;
    state.queue.push_back(std::move(chunk));
  }
  state.ready.notify_one();
}

void TraceWriter::flush_vertices(bool ends_draw) {
  if (!draw_open_) return;
  if (vertices_.empty() && draw_started_ && !ends_draw) return;
  const auto records = static_cast<std::uint32_t>(vertices_.size());
  Chunk chunk = take_spare();
  chunk.draw = draw_;
  std::swap(chunk.vertices, vertices_);
  vertices_.reserve(options_.chunk_records);
  const std::uint8_t flags =
      static_cast<std::uint8_t>((draw_started_ ? 0 : kChunkStartsDraw) | (ends_draw ? kChunkEndsDraw : 0));
  submit(chunk, RecordKind::Vertex, flags, records);
  draw_started_ = true;
  if (ends_draw) draw_open_ = false;
}

void TraceWriter::flush_texels() {
  if (texels_.size == 0) return;
  const auto records = static_cast<std::uint32_t>(texels_.size);
  Chunk chunk = take_spare();
  std::swap(chunk.texels, texels_);
  texels_.reset(options_.chunk_records);
  submit(chunk, RecordKind::Texel, 0, records);
}

void TraceWriter::flush_addresses() {
  if (addresses_.empty()) return;
  const auto records = static_cast<std::uint32_t>(addresses_.size());
  Chunk chunk = take_spare();
  std::swap(chunk.addresses, addresses_);
  submit(chunk, RecordKind::Address, 0, records);
}

void TraceWriter::flush_framebuffer() {
  if (framebuffer_.empty()) return;
  const auto records = static_cast<std::uint32_t>(framebuffer_.size());
  Chunk chunk = take_spare();
  std::swap(chunk.framebuffer, framebuffer_);
  framebuffer_.reserve(options_.chunk_records);
  submit(chunk, RecordKind::Framebuffer, 0, records);
}

void TraceWriter::begin_frame(std::uint32_t frame) {
  if (finished_) throw std::logic_error("TraceWriter: begin_frame after finish");
  if (frame < frame_ || frame > 0xFFFFu)
    throw std::invalid_argument("TraceWriter: frame " + std::to_string(frame) + " after frame " +
                                std::to_string(frame_) + " (frames increase, at most 65535)");
  if (frame == frame_) return;
  if (draw_open_) flush_vertices(true);  // a draw never spans two frames
  flush_texels();
  flush_framebuffer();
  flush_addresses();
  frame_ = static_cast<std::uint16_t>(frame);
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
  while (!accesses.empty()) {
    const std::size_t take = std::min(texels_.capacity - texels_.size, accesses.size());
    texels_.append(accesses.first(take));
    accesses = accesses.subspan(take);
    if (texels_.size == texels_.capacity) flush_texels();
  }
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
  if (draw_open_) flush_vertices(true);
  flush_texels();
  flush_framebuffer();
  flush_addresses();
  State& state = *state_;
  state.stop();
  if (state.error) std::rethrow_exception(state.error);
  std::string index;
  append_bytes<std::uint32_t>(index, kIndexTag);
  append_bytes<std::uint32_t>(index, 0);
  append_bytes<std::uint64_t>(index, state.index.size());
  for (const ChunkInfo& c : state.index) {
    append_bytes<std::uint64_t>(index, c.offset);
    append_bytes<std::uint64_t>(index, c.first_record);
    append_bytes<std::uint32_t>(index, c.records);
    append_bytes<std::uint8_t>(index, static_cast<std::uint8_t>(c.kind));
    append_bytes<std::uint16_t>(index, c.frame);
    index.append(1, '\0');
  }
  const std::uint64_t index_offset = state.offset.load();
  std::string footer;
  append_bytes<std::uint64_t>(footer, index_offset);
  append_bytes<std::uint32_t>(footer, crc32c(index.data(), index.size()));
  append_bytes<std::uint32_t>(footer, 0);
  footer.append(kTraceEndMagic, 8);
  state.write(index.data(), index.size());
  state.write(footer.data(), footer.size());
  state.file.commit();
  finished_ = true;
}

}  // namespace rastrace
