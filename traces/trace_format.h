// The rastrace trace container, version 4 (all integers little endian):
//
//   header   "RASTRACE" | u32 version | u32 metadata bytes | metadata JSON | u32 CRC32C(JSON)
//   chunks   32-byte chunk header | payload (zstd frame of the encoded records, chunk_codec.h)
//              u32 "CHNK" | u8 kind (1 vertex, 2 texel, 3 address, 4 framebuffer) | u8 flags (1 starts a draw,
//              2 ends it) | u16 frame | u32 records | u32 payload bytes | u32 raw bytes |
//              u64 first record (number of the first record among the file's records of this kind)
//              | u32 CRC32C over the 28 bytes before it and the payload
//   index    u32 "INDX" | u32 0 | u64 chunk count | per chunk: u64 offset, u64 first record,
//            u32 records, u8 kind, u16 frame, 1 zero byte
//   footer   u64 index offset | u32 CRC32C(index) | u32 0 | "RTRCEND1"
//
// A vertex chunk belongs to one draw; a draw's fetches span one or more chunks. Texel, address and
// framebuffer chunks hold up to 64 Ki records each. No chunk spans two frames: the writer ends
// every open chunk when a frame begins (EventSink::begin_frame), and the frame numbers of the
// chunks of one kind never decrease in file order (the writer's are non-decreasing over the whole
// file). The chunk header's frame and the index entry's agree, so a reader knows every chunk's
// frame (and the frame count) from the index alone.
//
// Versions: 1 had vertex, texel and address chunks; 2 adds framebuffer chunks (depth-test reads,
// depth writes and colour writes per 2x2 quad, chunk_codec.h) and changes nothing else, so a
// reader of version 2 reads version 1 files as they are. 3 adds the frame numbers (0..65535) in
// the chunk header's and the index entry's formerly reserved u16, which versions 1 and 2 keep
// zero (their frame is 0 throughout). Writers of version 3 wrote version 2 when every chunk was
// of frame 0 and version 3 when some chunk was of a later frame (render --frames N with N > 1); a
// reader refuses a version 3 file whose chunks are all of frame 0 (the version field is outside
// every checksum, and 2 and 3 differ by one bit). 4 lets record columns be stored as runs of equal values (chunk_codec.h, mode
// 0x82), which halves what zstd produces for a rendered texel chunk; the container is version 3's,
// frames included, and every file of the writer is version 4, of one frame or several (no
// single-bit flip of 4 gives 1, 2 or 3). Readers refuse run columns in files of versions 1 to 3.
// The index at the end lets a reader seek to any chunk and
// know every count before reading; a file without its footer was not finished (truncated).
#pragma once

#include <cstdint>

#include "traces/chunk_codec.h"

namespace rastrace {

inline constexpr char kTraceMagic[8] = {'R', 'A', 'S', 'T', 'R', 'A', 'C', 'E'};
inline constexpr char kTraceEndMagic[8] = {'R', 'T', 'R', 'C', 'E', 'N', 'D', '1'};
inline constexpr std::uint32_t kTraceVersion = 4;             // the newest the reader reads, what the writer writes
inline constexpr std::uint32_t kSingleFrameTraceVersion = 2;  // what writers before version 4 wrote for one frame
inline constexpr std::uint32_t kFramesTraceVersion = 3;       // the first version with frame numbers
inline constexpr std::uint32_t kRunsTraceVersion = 4;         // the first version with run columns
inline constexpr std::uint32_t kOldestTraceVersion = 1;  // the oldest the reader reads
inline constexpr std::uint32_t kChunkTag = 0x4B4E4843u;  // "CHNK"
inline constexpr std::uint32_t kIndexTag = 0x58444E49u;  // "INDX"
inline constexpr std::uint32_t kChunkHeaderBytes = 32;
inline constexpr std::uint32_t kFooterBytes = 24;
inline constexpr std::uint32_t kChunkRecords = 1 << 16;
// Readers refuse more records in one chunk (bounded memory and time: a chunk of identical records
// compresses to a few bytes, so the bound is on records, not on stored bytes; 2^20 texel records
// decode to 24 MiB). The writer's default is kChunkRecords.
inline constexpr std::uint32_t kMaxChunkRecords = 1 << 20;
inline constexpr std::uint8_t kChunkStartsDraw = 1;
inline constexpr std::uint8_t kChunkEndsDraw = 2;

struct ChunkInfo {
  std::uint64_t offset = 0;        // byte offset of the chunk header
  std::uint64_t first_record = 0;  // among the records of its kind
  std::uint32_t records = 0;
  RecordKind kind = RecordKind::Vertex;
  std::uint16_t frame = 0;  // the frame the chunk's records belong to (0 before version 3)
};

}  // namespace rastrace
