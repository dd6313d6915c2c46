#include "traces/trace_reader.h"

#include <cstring>
#include <sstream>

#include <zstd.h>

#include "core/error.h"
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
    if (c >= 32 && c < 127) s += static_cast<char>(c);
    else s += "\\x" + hex(c).substr(2);
  }
  return s;
}

}  // namespace

bool TraceReader::is_trace_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[8] = {};
  in.read(magic, 8);
  return in.gcount() == 8 && std::memcmp(magic, kTraceMagic, 8) == 0;
}

TraceReader::TraceReader(const std::string& path) : path_(path), in_(path, std::ios::binary) {
  if (!in_) throw_in_file(path, "cannot open for reading");
  in_.seekg(0, std::ios::end);
  file_bytes_ = static_cast<std::uint64_t>(in_.tellg());
  in_.seekg(0);

  std::uint8_t fixed[16];
  in_.read(reinterpret_cast<char*>(fixed), 16);
  if (in_.gcount() < 8 || std::memcmp(fixed, kTraceMagic, 8) != 0)
    throw_at_byte(path, 0, "not a rastrace trace: magic '" +
                               printable(reinterpret_cast<const char*>(fixed), static_cast<std::size_t>(std::min<std::streamsize>(in_.gcount(), 8))) +
                               "', expected 'RASTRACE'");
  if (in_.gcount() < 16) throw_at_byte(path, static_cast<std::uint64_t>(in_.gcount()), "truncated header: expected 16 bytes");
  const std::uint32_t version = load<std::uint32_t>(fixed + 8);
  if (version != kTraceVersion)
    throw_at_byte(path, 8, "unknown trace version " + std::to_string(version) + ": this rastrace reads version " +
                               std::to_string(kTraceVersion));
  const std::uint32_t json_bytes = load<std::uint32_t>(fixed + 12);
  const std::uint64_t header_end = 16 + std::uint64_t{json_bytes} + 4;
  if (header_end > file_bytes_)
    throw_at_byte(path, 12, "truncated metadata header: " + std::to_string(json_bytes) + " bytes announced, file has " +
                                std::to_string(file_bytes_));
  std::string json(json_bytes, '\0');
  in_.read(json.data(), json_bytes);
  std::uint8_t crc_bytes[4];
  in_.read(reinterpret_cast<char*>(crc_bytes), 4);
  const std::uint32_t stored_crc = load<std::uint32_t>(crc_bytes);
  const std::uint32_t computed = crc32c(json.data(), json.size());
  if (stored_crc != computed)
    throw_at_byte(path, 16, "metadata header checksum mismatch (stored " + hex(stored_crc) + ", computed " +
                                hex(computed) + ")");
  metadata_ = metadata_from_json(json, path);

  // Footer and index.
  if (file_bytes_ < header_end + kFooterBytes) fail_truncated(header_end);
  std::uint8_t footer[kFooterBytes];
  in_.seekg(static_cast<std::streamoff>(file_bytes_ - kFooterBytes));
  in_.read(reinterpret_cast<char*>(footer), kFooterBytes);
  if (std::memcmp(footer + 16, kTraceEndMagic, 8) != 0) fail_truncated(header_end);
  index_offset_ = load<std::uint64_t>(footer);
  const std::uint32_t index_crc = load<std::uint32_t>(footer + 8);
  if (index_offset_ < header_end || index_offset_ + 16 > file_bytes_ - kFooterBytes)
    throw_at_byte(path, file_bytes_ - kFooterBytes, "chunk index offset " + std::to_string(index_offset_) +
                                                        " outside the file");
  std::vector<std::uint8_t> index(file_bytes_ - kFooterBytes - index_offset_);
  in_.seekg(static_cast<std::streamoff>(index_offset_));
  in_.read(reinterpret_cast<char*>(index.data()), static_cast<std::streamsize>(index.size()));
  if (crc32c(index.data(), index.size()) != index_crc)
    throw_at_byte(path, index_offset_, "chunk index checksum mismatch");
  const std::uint64_t count = index.size() >= 16 ? load<std::uint64_t>(index.data() + 8) : 0;
  if (index.size() < 16 || load<std::uint32_t>(index.data()) != kIndexTag || count > index.size() / 24 ||
      index.size() != 16 + count * 24)
    throw_at_byte(path, index_offset_, "malformed chunk index");
  std::uint64_t previous_end = header_end;
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::uint8_t* e = index.data() + 16 + i * 24;
    ChunkInfo c;
    c.offset = load<std::uint64_t>(e);
    c.first_record = load<std::uint64_t>(e + 8);
    c.records = load<std::uint32_t>(e + 16);
    const std::uint8_t kind = e[20];
    if (kind < 1 || kind > 3 || c.records > kMaxChunkRecords || c.offset < previous_end ||
        c.offset + kChunkHeaderBytes > index_offset_)
      throw_at_byte(path, index_offset_ + 16 + i * 24, "chunk index entry " + std::to_string(i) + " is invalid");
    c.kind = static_cast<RecordKind>(kind);
    if (c.first_record != counts_[kind])
      throw_at_byte(path, index_offset_ + 16 + i * 24, "chunk index entry " + std::to_string(i) +
                                                           ": records out of sequence");
    counts_[kind] += c.records;
    previous_end = c.offset + kChunkHeaderBytes;
    chunks_.push_back(c);
  }
  dctx_ = ZSTD_createDCtx();
}

TraceReader::~TraceReader() { ZSTD_freeDCtx(static_cast<ZSTD_DCtx*>(dctx_)); }

void TraceReader::fail_truncated(std::uint64_t header_end) {
  // Walk the chunks from the start to say where the file stops.
  std::uint64_t offset = header_end;
  std::size_t chunk = 0;
  in_.clear();
  while (offset + kChunkHeaderBytes <= file_bytes_) {
    std::uint8_t h[kChunkHeaderBytes];
    in_.seekg(static_cast<std::streamoff>(offset));
    in_.read(reinterpret_cast<char*>(h), kChunkHeaderBytes);
    if (load<std::uint32_t>(h) != kChunkTag) break;
    const std::uint64_t end = offset + kChunkHeaderBytes + load<std::uint32_t>(h + 12);
    if (end > file_bytes_)
      throw_at_byte(path_, offset, "truncated trace: chunk " + std::to_string(chunk) + " needs " +
                                       std::to_string(end - offset) + " bytes, the file ends after " +
                                       std::to_string(file_bytes_ - offset));
    offset = end;
    ++chunk;
  }
  throw_at_byte(path_, offset, "truncated trace: no chunk index and footer after chunk " +
                                   std::to_string(chunk) + " (the writer did not finish)");
}

const DecodedChunk& TraceReader::read_chunk(std::size_t i) {
  const ChunkInfo& info = chunks_.at(i);
  const std::string where = "chunk " + std::to_string(i) + ": ";
  std::uint8_t h[kChunkHeaderBytes];
  in_.clear();
  in_.seekg(static_cast<std::streamoff>(info.offset));
  in_.read(reinterpret_cast<char*>(h), kChunkHeaderBytes);
  if (load<std::uint32_t>(h) != kChunkTag) throw_at_byte(path_, info.offset, where + "bad chunk tag, expected 'CHNK'");
  const std::uint8_t kind = h[4];
  const std::uint8_t flags = h[5];
  const std::uint32_t records = load<std::uint32_t>(h + 8);
  const std::uint32_t stored = load<std::uint32_t>(h + 12);
  const std::uint32_t raw_bytes = load<std::uint32_t>(h + 16);
  const std::uint64_t first = load<std::uint64_t>(h + 20);
  const std::uint32_t crc = load<std::uint32_t>(h + 28);
  const std::uint64_t next = i + 1 < chunks_.size() ? chunks_[i + 1].offset : index_offset_;
  if (info.offset + kChunkHeaderBytes + stored > next)
    throw_at_byte(path_, info.offset, where + "payload of " + std::to_string(stored) + " bytes overruns the next chunk");
  stored_.resize(stored);
  in_.read(reinterpret_cast<char*>(stored_.data()), stored);
  if (!in_) throw_at_byte(path_, info.offset, where + "read failed");
  const std::uint32_t computed = crc32c(stored_.data(), stored, crc32c(h, 28));
  if (computed != crc)
    throw_at_byte(path_, info.offset, where + "checksum mismatch (stored " + hex(crc) + ", computed " + hex(computed) + ")");
  if (kind != static_cast<std::uint8_t>(info.kind) || records != info.records || first != info.first_record)
    throw_at_byte(path_, info.offset, where + "header disagrees with the chunk index");
  // Every encoding uses at most 8 bytes per field: a larger claim is corruption, not a big chunk.
  if (raw_bytes > std::uint64_t{records} * 64 + 4096) throw_at_byte(path_, info.offset, where + "implausible decoded size");
  raw_.resize(raw_bytes);
  const std::size_t got = ZSTD_decompressDCtx(static_cast<ZSTD_DCtx*>(dctx_), raw_.data(), raw_.size(), stored_.data(), stored);
  if (ZSTD_isError(got) || got != raw_bytes)
    throw_at_byte(path_, info.offset, where + "zstd payload does not decode to " + std::to_string(raw_bytes) + " bytes");
  chunk_.kind = info.kind;
  chunk_.flags = flags;
  chunk_.first_record = first;
  std::string error;
  // Only the decoded kind's vector is resized (no clearing: that would zero-fill it again).
  switch (info.kind) {
    case RecordKind::Vertex: error = decode_vertex_records(raw_, records, chunk_.draw, chunk_.vertices); break;
    case RecordKind::Texel: error = decode_texel_records(raw_, records, chunk_.texels); break;
    default: error = decode_address_records(raw_, records, chunk_.addresses); break;
  }
  if (!error.empty()) throw_at_byte(path_, info.offset, where + error);
  return chunk_;
}

void replay_trace(TraceReader& reader, EventSink& sink, ReplayKinds kinds, Progress* progress) {
  for (std::size_t i = 0; i < reader.chunks().size(); ++i) {
    const ChunkInfo& info = reader.chunks()[i];
    const bool wanted = (info.kind == RecordKind::Vertex && kinds.vertices) ||
                        (info.kind == RecordKind::Texel && kinds.texels) ||
                        (info.kind == RecordKind::Address && kinds.addresses);
    if (!wanted) continue;
    const DecodedChunk& chunk = reader.read_chunk(i);
    switch (chunk.kind) {
      case RecordKind::Vertex:
        if (chunk.flags & kChunkStartsDraw) sink.begin_draw(chunk.draw);
        if (!chunk.vertices.empty()) sink.vertex_fetches(chunk.vertices);
        if (chunk.flags & kChunkEndsDraw) sink.end_draw();
        break;
      case RecordKind::Texel: sink.texel_accesses(chunk.texels); break;
      default: sink.address_accesses(chunk.addresses); break;
    }
    if (progress) progress->advance(info.records);
  }
  sink.finish();
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
