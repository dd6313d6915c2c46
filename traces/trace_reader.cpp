#include "traces/trace_reader.h"

#include <algorithm>
#include <array>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

#include <zstd.h>

#include "core/error.h"
#include "core/input_guard.h"
#include "core/progress.h"
#include "traces/crc32c.h"

namespace rastrace {

namespace {

template <typename T>
T load(const std::uint8_t* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  return value;
}

std::string hex(std::uint32_t v) {
  std::ostringstream s;
  s << "0x" << std::hex << v;
  return s.str();
}

std::string printable(const char* bytes, std::size_t n) {
  std::string s;
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char c = static_cast<unsigned char>(bytes[i]);
    if (c >= 32 && c < 127)
      s += static_cast<char>(c);
    else
      s += "\\x" + hex(c).substr(2);
  }
  return s;
}

// What one thread needs to read chunks: its own stream, zstd context and buffers.
struct ChunkSource {
  std::ifstream in;
  ZSTD_DCtx* dctx = nullptr;
  std::vector<std::uint8_t> stored;
  std::vector<std::uint8_t> raw;

  explicit ChunkSource(std::ifstream stream) : in(std::move(stream)), dctx(ZSTD_createDCtx()) {}
  ChunkSource(const ChunkSource&) = delete;
  ChunkSource& operator=(const ChunkSource&) = delete;
  ~ChunkSource() { ZSTD_freeDCtx(dctx); }
};

// The immutable part of an open trace that loading a chunk needs (shared by both threads).
struct TraceLayout {
  const std::string& path;
  const std::vector<ChunkInfo>& chunks;
  std::uint64_t index_offset;
  std::uint32_t version;
};

// What a chunk's header says, once read_checked_payload() has checked it.
struct ChunkHeader {
  std::uint8_t flags = 0;
  std::uint32_t records = 0;
  std::uint32_t stored = 0;
  std::uint32_t raw_bytes = 0;
  std::uint64_t first = 0;
};

// Reads chunk i's header and payload into src.stored and checks the checksum, the reserved bytes
// and the agreement with the index (no decoding); throws the chunk's InputError.
ChunkHeader read_checked_payload(const TraceLayout& file, ChunkSource& src, std::size_t i) {
  const std::string& path = file.path;
  const ChunkInfo& info = file.chunks[i];
  const std::string where = "chunk " + std::to_string(i) + ": ";
  std::uint8_t h[kChunkHeaderBytes] = {};
  src.in.clear();
  src.in.seekg(static_cast<std::streamoff>(info.offset));
  src.in.read(reinterpret_cast<char*>(h), kChunkHeaderBytes);
  if (!src.in) throw_at_byte(path, info.offset, where + "read failed (the file is shorter than its index says)");
  if (load<std::uint32_t>(h) != kChunkTag) throw_at_byte(path, info.offset, where + "bad chunk tag, expected 'CHNK'");
  const std::uint8_t kind = h[4];
  const std::uint8_t flags = h[5];
  const std::uint16_t frame = load<std::uint16_t>(h + 6);
  if (file.version < kFramesTraceVersion && frame != 0)
    throw_at_byte(path, info.offset + 6, where + "reserved header bytes are not zero");
  if (frame != info.frame)
    throw_at_byte(path, info.offset + 6,
                  where + "frame " + std::to_string(frame) + " disagrees with the chunk index's frame " +
                      std::to_string(info.frame));
  if ((flags & ~(kChunkStartsDraw | kChunkEndsDraw)) != 0)
    throw_at_byte(path, info.offset + 5, where + "unknown flags " + hex(flags));
  const std::uint32_t records = load<std::uint32_t>(h + 8);
  const std::uint32_t stored = load<std::uint32_t>(h + 12);
  const std::uint32_t raw_bytes = load<std::uint32_t>(h + 16);
  const std::uint64_t first = load<std::uint64_t>(h + 20);
  const std::uint32_t crc = load<std::uint32_t>(h + 28);
  const std::uint64_t next = i + 1 < file.chunks.size() ? file.chunks[i + 1].offset : file.index_offset;
  if (info.offset + kChunkHeaderBytes + stored > next)
    throw_at_byte(path, info.offset, where + "payload of " + std::to_string(stored) + " bytes overruns the next chunk");
  src.stored.resize(stored);
  src.in.read(reinterpret_cast<char*>(src.stored.data()), stored);
  if (!src.in) throw_at_byte(path, info.offset, where + "read failed");
  const std::uint32_t computed = crc32c(src.stored.data(), stored, crc32c(h, 28));
  if (computed != crc)
    throw_at_byte(path, info.offset,
                  where + "checksum mismatch (stored " + hex(crc) + ", computed " + hex(computed) + ")");
  if (kind != static_cast<std::uint8_t>(info.kind) || records != info.records || first != info.first_record)
    throw_at_byte(path, info.offset, where + "header disagrees with the chunk index");
  // Every encoding uses at most 8 bytes per field: a larger claim is corruption, not a big chunk.
  if (raw_bytes > std::uint64_t{records} * 64 + 4096)
    throw_at_byte(path, info.offset, where + "implausible decoded size");
  return {flags, records, stored, raw_bytes, first};
}

// Reads, checks and decodes chunk i into `out`; throws the chunk's InputError.
void load_chunk(const TraceLayout& file, ChunkSource& src, std::size_t i, DecodedChunk& out, bool texel_details) {
  const std::string& path = file.path;
  const ChunkInfo& info = file.chunks[i];
  const std::string where = "chunk " + std::to_string(i) + ": ";
  const auto [flags, records, stored, raw_bytes, first] = read_checked_payload(file, src, i);
  src.raw.resize(raw_bytes);
  const std::size_t got = ZSTD_decompressDCtx(src.dctx, src.raw.data(), src.raw.size(), src.stored.data(), stored);
  if (ZSTD_isError(got) || got != raw_bytes)
    throw_at_byte(path, info.offset, where + "zstd payload does not decode to " + std::to_string(raw_bytes) + " bytes");
  out.kind = info.kind;
  out.flags = flags;
  out.first_record = first;
  std::string error;
  const bool runs = file.version >= kRunsTraceVersion;
  // Only the decoded kind's vector is resized (no clearing: that would zero-fill it again).
  switch (info.kind) {
    case RecordKind::Vertex:
      error = decode_vertex_records(src.raw, records, out.draw, out.vertices, runs);
      break;
    case RecordKind::Texel:
      error = decode_texel_records(src.raw, records, out.texels, texel_details, runs);
      break;
    case RecordKind::Framebuffer:
      error = decode_framebuffer_records(src.raw, records, out.framebuffer, runs);
      break;
    default:
      error = decode_address_records(src.raw, records, out.addresses, runs);
      break;
  }
  if (!error.empty()) throw_at_byte(path, info.offset, where + error);
}

constexpr std::size_t kNone = ~std::size_t{0};

// On with 2 or more hardware threads, unless RASTRACE_READ_AHEAD=0: a second thread only pays
// when the process can get a second core (under Linux's autogroup scheduling, a session on a
// busy machine gets its fair share however many threads it runs).
bool read_ahead_by_default() {
  const char* env = std::getenv("RASTRACE_READ_AHEAD");
  if (env && std::string(env) == "0") return false;
  return std::thread::hardware_concurrency() >= 2;
}

// A decoded chunk and who owns it. Free: nobody. Busy: the thread decoding into it (the
// caller's or the read-ahead thread). Ready: decoded (or failed), waiting to be asked for.
// Held: returned by read_chunk() until the next call.
struct Slot {
  enum class State { Free, Busy, Ready, Held };
  State state = State::Free;
  std::size_t chunk = kNone;
  bool drop = false;  // busy on a chunk nobody expects any more: free it when done
  bool details = true;  // decoded with texel details (ReplayKinds::texel_details)
  DecodedChunk decoded;
  std::exception_ptr error;
};

}  // namespace

// Every field below `mutex` is guarded by it, except a Busy slot's `decoded`, which belongs to
// the thread decoding into it until it marks the slot Ready under the lock.
struct TraceReader::ReadState {
  ChunkSource caller;                  // the caller's thread
  std::unique_ptr<ChunkSource> ahead;  // the read-ahead thread
  // Opened with the caller's stream, so both read the same file even if the path is replaced
  // (written atomically by rename) before the first in-order read starts the thread.
  std::ifstream ahead_stream;
  // One held by the caller, one per decoding thread, and two more: the read-ahead thread keeps
  // decoding while the caller works on a chunk it decoded itself (it then finds two ready).
  std::array<Slot, 5> slots;
  std::size_t held = kNone;
  bool enabled = read_ahead_by_default();
  bool broken = false;  // the thread could not start: read in the caller only
  bool wanted[5] = {false, true, true, true, true};
  bool texel_details = true;
  std::size_t last = kNone;    // the chunk read last
  std::size_t cursor = kNone;  // the next chunk to read ahead, kNone: none
  bool stop = false;
  std::mutex mutex;
  std::condition_variable work;  // to the read-ahead thread: a slot or a chunk to read
  std::condition_variable done;  // to the caller: a slot became Ready
  std::thread thread;

  explicit ReadState(std::ifstream in) : caller(std::move(in)) {}
  ~ReadState() {
    if (!thread.joinable()) return;
    {
      std::lock_guard lock(mutex);
      stop = true;
    }
    work.notify_all();
    thread.join();
  }

  Slot* find(std::size_t chunk) {
    for (Slot& s : slots)
      if (s.chunk == chunk && s.details == texel_details &&
          (s.state == Slot::State::Busy || s.state == Slot::State::Ready))
        return &s;
    return nullptr;
  }
  Slot* free_slot() {
    for (Slot& s : slots)
      if (s.state == Slot::State::Free) return &s;
    return nullptr;
  }
  // The first chunk after `from` (kNone: from the start) of a wanted kind.
  std::size_t next_wanted(const std::vector<ChunkInfo>& chunks, std::size_t from) const {
    for (std::size_t i = from == kNone ? 0 : from + 1; i < chunks.size(); ++i)
      if (wanted[static_cast<int>(chunks[i].kind)]) return i;
    return kNone;
  }
  // The first wanted chunk after `from` that is not already read or being read.
  std::size_t next_to_read_ahead(const std::vector<ChunkInfo>& chunks, std::size_t from) {
    std::size_t i = next_wanted(chunks, from);
    while (i != kNone && find(i)) i = next_wanted(chunks, i);
    return i;
  }
  // Frees what was read ahead (a read out of order: the caller went elsewhere).
  void drop_read_ahead() {
    cursor = kNone;
    for (Slot& s : slots) {
      if (s.state == Slot::State::Ready) s.state = Slot::State::Free;
      if (s.state == Slot::State::Busy) s.drop = true;
    }
  }
  // Decodes chunk `slot->chunk` into the Busy slot, without the lock; then marks it Ready.
  void decode(const TraceLayout& file, ChunkSource& src, Slot* slot, std::unique_lock<std::mutex>& lock) {
    const std::size_t chunk = slot->chunk;
    const bool details = slot->details = texel_details;
    lock.unlock();
    std::exception_ptr error;
    try {
      load_chunk(file, src, chunk, slot->decoded, details);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    slot->error = error;
    slot->state = slot->drop ? Slot::State::Free : Slot::State::Ready;
    slot->drop = false;
  }
  void run(const TraceLayout& file) {
    std::unique_lock lock(mutex);
    for (;;) {
      Slot* slot = nullptr;
      work.wait(lock, [&] { return stop || (cursor != kNone && (slot = free_slot()) != nullptr); });
      if (stop) return;
      slot->state = Slot::State::Busy;
      slot->chunk = cursor;
      cursor = next_to_read_ahead(file.chunks, cursor);
      decode(file, *ahead, slot, lock);
      done.notify_all();
    }
  }
};

bool TraceReader::is_trace_file(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;  // the reader that follows says why
  std::ifstream in(path, std::ios::binary);
  char magic[8] = {};
  in.read(magic, 8);
  return in.gcount() == 8 && std::memcmp(magic, kTraceMagic, 8) == 0;
}

TraceReader::TraceReader(const std::string& path) : path_(path) {
  require_regular_file(path);  // a FIFO would block, /dev/zero never end
  std::ifstream in_(path, std::ios::binary);
  if (!in_) throw_in_file(path, "cannot open for reading");
  in_.seekg(0, std::ios::end);
  file_bytes_ = static_cast<std::uint64_t>(in_.tellg());
  in_.seekg(0);

  std::uint8_t fixed[16];
  in_.read(reinterpret_cast<char*>(fixed), 16);
  if (in_.gcount() < 8 || std::memcmp(fixed, kTraceMagic, 8) != 0)
    throw_at_byte(path, 0,
                  "not a rastrace trace: magic '" +
                      printable(reinterpret_cast<const char*>(fixed),
                                static_cast<std::size_t>(std::min<std::streamsize>(in_.gcount(), 8))) +
                      "', expected 'RASTRACE'");
  if (in_.gcount() < 16)
    throw_at_byte(path, static_cast<std::uint64_t>(in_.gcount()), "truncated header: expected 16 bytes");
  const std::uint32_t version = load<std::uint32_t>(fixed + 8);
  if (version < kOldestTraceVersion || version > kTraceVersion)
    throw_at_byte(path, 8,
                  "unknown trace version " + std::to_string(version) + ": this rastrace reads versions " +
                      std::to_string(kOldestTraceVersion) + " to " + std::to_string(kTraceVersion));
  version_ = version;
  // Version 1 knew vertex, texel and address chunks; version 2 added framebuffer chunks.
  const std::uint8_t last_kind = version == 1 ? 3 : 4;
  const std::uint32_t json_bytes = load<std::uint32_t>(fixed + 12);
  const std::uint64_t header_end = 16 + std::uint64_t{json_bytes} + 4;
  if (header_end > file_bytes_)
    throw_at_byte(path, 12,
                  "truncated metadata header: " + std::to_string(json_bytes) + " bytes announced, file has " +
                      std::to_string(file_bytes_));
  std::string json(json_bytes, '\0');
  in_.read(json.data(), json_bytes);
  std::uint8_t crc_bytes[4];
  in_.read(reinterpret_cast<char*>(crc_bytes), 4);
  const std::uint32_t stored_crc = load<std::uint32_t>(crc_bytes);
  const std::uint32_t computed = crc32c(json.data(), json.size());
  if (stored_crc != computed)
    throw_at_byte(path, 16,
                  "metadata header checksum mismatch (stored " + hex(stored_crc) + ", computed " + hex(computed) + ")");
  metadata_ = metadata_from_json(json, path);

  // Footer and index.
  if (file_bytes_ < header_end + kFooterBytes) fail_truncated(in_, header_end);
  std::uint8_t footer[kFooterBytes];
  in_.seekg(static_cast<std::streamoff>(file_bytes_ - kFooterBytes));
  in_.read(reinterpret_cast<char*>(footer), kFooterBytes);
  if (std::memcmp(footer + 16, kTraceEndMagic, 8) != 0) fail_truncated(in_, header_end);
  index_offset_ = load<std::uint64_t>(footer);
  const std::uint32_t index_crc = load<std::uint32_t>(footer + 8);
  if (load<std::uint32_t>(footer + 12) != 0)
    throw_at_byte(path, file_bytes_ - kFooterBytes + 12, "reserved footer bytes are not zero");
  if (index_offset_ < header_end || index_offset_ + 16 > file_bytes_ - kFooterBytes)
    throw_at_byte(path, file_bytes_ - kFooterBytes,
                  "chunk index offset " + std::to_string(index_offset_) + " outside the file");
  std::vector<std::uint8_t> index(file_bytes_ - kFooterBytes - index_offset_);
  in_.seekg(static_cast<std::streamoff>(index_offset_));
  in_.read(reinterpret_cast<char*>(index.data()), static_cast<std::streamsize>(index.size()));
  if (crc32c(index.data(), index.size()) != index_crc)
    throw_at_byte(path, index_offset_, "chunk index checksum mismatch");
  const std::uint64_t count = index.size() >= 16 ? load<std::uint64_t>(index.data() + 8) : 0;
  if (index.size() < 16 || load<std::uint32_t>(index.data()) != kIndexTag ||
      load<std::uint32_t>(index.data() + 4) != 0 || count > index.size() / 24 || index.size() != 16 + count * 24)
    throw_at_byte(path, index_offset_, "malformed chunk index");
  std::uint64_t previous_end = header_end;
  std::uint16_t last_frame[5] = {0, 0, 0, 0, 0};  // per kind
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::uint8_t* e = index.data() + 16 + i * 24;
    ChunkInfo c;
    c.offset = load<std::uint64_t>(e);
    c.first_record = load<std::uint64_t>(e + 8);
    c.records = load<std::uint32_t>(e + 16);
    const std::uint8_t kind = e[20];
    // Bytes 21-22: the chunk's frame from version 3 on, reserved (zero) before.
    const bool frames = version_ >= kFramesTraceVersion;
    if ((!frames && (e[21] != 0 || e[22] != 0)) || e[23] != 0)
      throw_at_byte(path, index_offset_ + 16 + i * 24 + 21,
                    "chunk index entry " + std::to_string(i) + ": reserved bytes are not zero");
    c.frame = load<std::uint16_t>(e + 21);
    if (kind < 1 || kind > last_kind || c.records > kMaxChunkRecords || c.offset < previous_end ||
        c.offset + kChunkHeaderBytes > index_offset_)
      throw_at_byte(path, index_offset_ + 16 + i * 24, "chunk index entry " + std::to_string(i) + " is invalid");
    c.kind = static_cast<RecordKind>(kind);
    if (c.first_record != counts_[kind])
      throw_at_byte(path, index_offset_ + 16 + i * 24,
                    "chunk index entry " + std::to_string(i) + ": records out of sequence");
    if (c.frame < last_frame[kind])
      throw_at_byte(path, c.offset,
                    "chunk " + std::to_string(i) + ": frame " + std::to_string(c.frame) + " after frame " +
                        std::to_string(last_frame[kind]) + " in an earlier chunk of its kind (frames never decrease)");
    last_frame[kind] = c.frame;
    frames_ = std::max<std::uint32_t>(frames_, c.frame + 1u);
    counts_[kind] += c.records;
    previous_end = c.offset + kChunkHeaderBytes;
    chunks_.push_back(c);
  }
  if (version_ == kFramesTraceVersion && frames_ == 1)
    throw_at_byte(path, 8,
                  "version " + std::to_string(version_) +
                      " (several frames) but every chunk is of frame 0: a damaged "
                      "version field (a single-frame trace is version 2 or 4)");
  state_ = std::make_unique<ReadState>(std::move(in_));
  state_->ahead_stream.open(path, std::ios::binary);
}

TraceReader::~TraceReader() = default;

void TraceReader::fail_if_trailing_data(std::ifstream& in_, std::uint64_t index_offset, std::size_t chunk,
                                        const std::uint8_t* index_header) {
  // The walk reached a chunk index: if a whole footer follows it, the file was finished and
  // something was appended after it (not a truncation).
  const std::uint64_t count = load<std::uint64_t>(index_header + 8);
  if (count > file_bytes_ / 24) return;
  const std::uint64_t footer_at = index_offset + 16 + count * 24;
  if (footer_at + kFooterBytes == file_bytes_)  // the file ends where its footer should
    throw_at_byte(path_, footer_at + 16, "damaged footer: the end magic is not 'RTRCEND1'");
  if (footer_at + kFooterBytes > file_bytes_) return;
  std::uint8_t footer[kFooterBytes];
  in_.clear();
  in_.seekg(static_cast<std::streamoff>(footer_at));
  in_.read(reinterpret_cast<char*>(footer), kFooterBytes);
  if (!in_ || std::memcmp(footer + 16, kTraceEndMagic, 8) != 0 || load<std::uint64_t>(footer) != index_offset) return;
  const std::uint64_t end = footer_at + kFooterBytes;
  throw_at_byte(path_, end,
                "trailing data: " + std::to_string(file_bytes_ - end) + " bytes after the trace's footer (the trace of " +
                    std::to_string(chunk) + " chunks ends at byte " + std::to_string(end) + ")");
}

void TraceReader::fail_truncated(std::ifstream& in_, std::uint64_t header_end) {
  // Walk the chunks from the start to say where the file stops.
  std::uint64_t offset = header_end;
  std::size_t chunk = 0;
  in_.clear();
  while (offset + kChunkHeaderBytes <= file_bytes_) {
    std::uint8_t h[kChunkHeaderBytes];
    in_.seekg(static_cast<std::streamoff>(offset));
    in_.read(reinterpret_cast<char*>(h), kChunkHeaderBytes);
    if (load<std::uint32_t>(h) == kIndexTag) fail_if_trailing_data(in_, offset, chunk, h);
    if (load<std::uint32_t>(h) != kChunkTag) break;
    const std::uint64_t end = offset + kChunkHeaderBytes + load<std::uint32_t>(h + 12);
    if (end > file_bytes_)
      throw_at_byte(path_, offset,
                    "truncated trace: chunk " + std::to_string(chunk) + " needs " + std::to_string(end - offset) +
                        " bytes, the file ends after " + std::to_string(file_bytes_ - offset));
    offset = end;
    ++chunk;
  }
  throw_at_byte(path_, offset,
                "truncated trace: no chunk index and footer after chunk " + std::to_string(chunk) +
                    " (the writer did not finish)");
}

void TraceReader::set_read_ahead(bool enabled) {
  std::lock_guard lock(state_->mutex);
  state_->enabled = enabled;
  if (!enabled) state_->drop_read_ahead();
}

void TraceReader::set_read_ahead_kinds(ReplayKinds kinds) {
  std::lock_guard lock(state_->mutex);
  ReadState& s = *state_;
  s.wanted[static_cast<int>(RecordKind::Vertex)] = kinds.vertices;
  s.wanted[static_cast<int>(RecordKind::Texel)] = kinds.texels;
  s.wanted[static_cast<int>(RecordKind::Address)] = kinds.addresses;
  s.wanted[static_cast<int>(RecordKind::Framebuffer)] = kinds.framebuffer;
  s.texel_details = kinds.texel_details;
  s.drop_read_ahead();
}

const DecodedChunk& TraceReader::read_chunk(std::size_t i) {
  if (i >= chunks_.size())
    throw std::out_of_range("TraceReader::read_chunk: chunk " + std::to_string(i) + " of " +
                            std::to_string(chunks_.size()));
  const TraceLayout file{path_, chunks_, index_offset_, version_};
  ReadState& s = *state_;
  std::unique_lock lock(s.mutex);
  if (s.held != kNone) {
    s.slots[s.held].state = Slot::State::Free;
    s.held = kNone;
    s.work.notify_one();
  }
  Slot* slot = nullptr;
  for (;;) {
    slot = s.find(i);
    if (slot && slot->state == Slot::State::Ready) break;
    if (slot) {
      // Being read ahead. Rather than wait, decode the chunk after it (two threads, two chunks).
      slot->drop = false;
      Slot* spare = s.cursor != kNone ? s.free_slot() : nullptr;
      if (!spare) {
        s.done.wait(lock);
        continue;
      }
      spare->state = Slot::State::Busy;
      spare->chunk = s.cursor;
      s.cursor = s.next_to_read_ahead(chunks_, s.cursor);
      s.decode(file, s.caller, spare, lock);
      continue;
    }
    // Not read ahead: read it here, in a free slot (one exists: the read-ahead thread holds at
    // most one Busy slot, the caller's previous chunk was freed above) or over a Ready one.
    if (s.cursor == i) s.cursor = s.next_to_read_ahead(chunks_, i);
    slot = s.free_slot();
    for (Slot& r : s.slots)
      if (!slot && r.state == Slot::State::Ready) slot = &r;
    slot->state = Slot::State::Busy;
    slot->chunk = i;
    s.decode(file, s.caller, slot, lock);
  }

  // Read ahead when the caller reads in order; drop the read-ahead when it jumps.
  const bool in_order = i == s.next_wanted(chunks_, s.last);
  s.last = i;
  if (in_order && s.enabled && !s.broken) {
    s.cursor = s.next_to_read_ahead(chunks_, i);
    if (s.cursor != kNone && !s.thread.joinable()) {
      try {
        if (!s.ahead_stream.is_open() || !s.ahead_stream) throw std::runtime_error("no second stream");
        s.ahead = std::make_unique<ChunkSource>(std::move(s.ahead_stream));
        s.thread = std::thread([&s, file] { s.run(file); });
      } catch (const std::exception&) {
        s.broken = true;  // no second stream or thread: everything is read by the caller
        s.cursor = kNone;
      }
    }
    s.work.notify_one();
  } else {
    s.drop_read_ahead();
  }

  slot->state = Slot::State::Held;
  s.held = static_cast<std::size_t>(slot - s.slots.data());
  if (slot->error) {
    const std::exception_ptr error = slot->error;
    slot->error = nullptr;
    slot->state = Slot::State::Free;
    s.held = kNone;
    s.work.notify_one();  // the slot is free for the read-ahead thread again
    std::rethrow_exception(error);
  }
  return slot->decoded;
}

void TraceReader::check_chunk(std::size_t i) {
  if (i >= chunks_.size())
    throw std::out_of_range("TraceReader::check_chunk: chunk " + std::to_string(i) + " of " +
                            std::to_string(chunks_.size()));
  // The caller's stream belongs to the caller's thread; the read-ahead thread has its own.
  read_checked_payload(TraceLayout{path_, chunks_, index_offset_, version_}, state_->caller, i);
}

void replay_trace(TraceReader& reader, EventSink& sink, ReplayKinds kinds, Progress* progress) {
  reader.set_read_ahead_kinds(kinds);
  // A file of several frames (version 3 or 4): the sink learns of each before its first chunk
  // (frame 0 included). Frames rise in file order per kind; a kind lagging behind never steps
  // back. A single-frame file announces none, whatever its version.
  const bool frames = reader.frames() > 1;
  std::int64_t frame = -1;
  for (std::size_t i = 0; i < reader.chunks().size(); ++i) {
    const ChunkInfo& info = reader.chunks()[i];
    if (frames && info.frame > frame) {
      frame = info.frame;
      sink.begin_frame(info.frame);
    }
    const bool wanted = (info.kind == RecordKind::Vertex && kinds.vertices) ||
                        (info.kind == RecordKind::Texel && kinds.texels) ||
                        (info.kind == RecordKind::Address && kinds.addresses) ||
                        (info.kind == RecordKind::Framebuffer && kinds.framebuffer);
    if (!wanted) {
      reader.check_chunk(i);  // not needed, but a damaged file must not pass as sound
      continue;
    }
    const DecodedChunk& chunk = reader.read_chunk(i);
    switch (chunk.kind) {
      case RecordKind::Vertex:
        if (chunk.flags & kChunkStartsDraw) sink.begin_draw(chunk.draw);
        if (!chunk.vertices.empty()) sink.vertex_fetches(chunk.vertices);
        if (chunk.flags & kChunkEndsDraw) sink.end_draw();
        break;
      case RecordKind::Texel:
        sink.texel_accesses(chunk.texels);
        break;
      case RecordKind::Framebuffer:
        sink.framebuffer_accesses(chunk.framebuffer);
        break;
      default:
        sink.address_accesses(chunk.addresses);
        break;
    }
    if (progress) progress->advance(info.records);
  }
  sink.finish();
}

std::uint64_t verify_trace(TraceReader& reader) {
  reader.set_read_ahead_kinds({});
  std::uint64_t records = 0;
  for (std::size_t i = 0; i < reader.chunks().size(); ++i) {
    reader.read_chunk(i);
    records += reader.chunks()[i].records;
  }
  return records;
}

bool VertexTraceReader::next(VertexBatch& batch) {
  const auto& chunks = reader_.chunks();
  while (next_chunk_ < chunks.size() && chunks[next_chunk_].kind != RecordKind::Vertex) ++next_chunk_;
  if (next_chunk_ == chunks.size()) return false;
  const DecodedChunk& chunk = reader_.read_chunk(next_chunk_++);
  batch.draw = chunk.draw;
  batch.starts_draw = chunk.flags & kChunkStartsDraw;
  batch.ends_draw = chunk.flags & kChunkEndsDraw;
  batch.fetches = chunk.vertices;
  return true;
}

bool TexelTraceReader::next(std::span<const TexelAccess>& batch) {
  const auto& chunks = reader_.chunks();
  while (next_chunk_ < chunks.size() && chunks[next_chunk_].kind != RecordKind::Texel) ++next_chunk_;
  if (next_chunk_ == chunks.size()) return false;
  batch = reader_.read_chunk(next_chunk_++).texels;
  return true;
}

}  // namespace rastrace
