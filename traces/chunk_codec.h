// The record encoding inside a trace chunk (before zstd): struct of arrays, one column per field.
// A column is: its mode (1 byte), the first value (8 bytes), then the zig-zag deltas of the
// following records: mode 0, 1, 2, 4, 8 = fixed width w bytes each, little endian; mode 0x81 = a
// u32 count of escapes, one byte per delta (0xFF = escaped), then the escaped deltas, 8 bytes
// each; mode 0x82 (trace version 4 on) = runs of equal values: u32 runs, u32 escapes, one length
// byte per run (1..255), the runs - 1 deltas between consecutive runs' values coded like mode
// 0x81's bytes, then the escaped deltas. Rendered traces move in small steps (neighbouring
// texels, consecutive vertex ids) and hold fields still over several records (a footprint's mip
// level, a fragment's pixel and triangle over its texels), so most deltas fit one byte or none,
// and decoding is a flat prefix sum or a fill per column. The writer picks the smallest mode per
// column. Vertex chunks start with their draw (u32 draw number, u8 primitive type, u32 restart
// index) and keep primitive starts as a bitmap. The type byte of a strip without primitive restart has
// kStripWithoutRestart set (its restart field is then meaningless); a strip without the flag restarts at the stored
// index, which is how files written before the flag existed read. List draws carry no restart index.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "traces/column_encoder.h"
#include "traces/events.h"
#include "traces/texel_columns.h"

namespace rastrace {

enum class RecordKind : std::uint8_t { Vertex = 1, Texel = 2, Address = 3, Framebuffer = 4 };
inline constexpr std::uint8_t kStripWithoutRestart = 0x80;
const char* to_string(RecordKind kind);

// Encoders replace `raw` with the chunk's record bytes. `scratch` is working memory a caller
// encoding chunk after chunk keeps (column_encoder.h); the calls without it use the thread's own.
void encode_vertex_records(const DrawInfo& draw, std::span<const VertexFetch> fetches, std::string& raw,
                           ColumnScratch& scratch);
void encode_texel_records(std::span<const TexelAccess> texels, std::string& raw, ColumnScratch& scratch);
void encode_texel_records(const TexelColumns& texels, std::string& raw, ColumnScratch& scratch);
void encode_address_records(std::span<const AddressAccess> addresses, std::string& raw, ColumnScratch& scratch);
// Columns x, y, operation, mask, triangle.
void encode_framebuffer_records(std::span<const FramebufferAccess> accesses, std::string& raw,
                                ColumnScratch& scratch);
void encode_vertex_records(const DrawInfo& draw, std::span<const VertexFetch> fetches, std::string& raw);
void encode_texel_records(std::span<const TexelAccess> texels, std::string& raw);
void encode_address_records(std::span<const AddressAccess> addresses, std::string& raw);
void encode_framebuffer_records(std::span<const FramebufferAccess> accesses, std::string& raw);

// Decoders append nothing: they resize `out` to `records`. They return an empty string on
// success, or what was wrong (the caller names the file and chunk). runs = false refuses mode
// 0x82 as a bad column width (files before version 4 cannot hold it).
std::string decode_vertex_records(std::span<const std::uint8_t> raw, std::uint32_t records, DrawInfo& draw,
                                  std::vector<VertexFetch>& out, bool runs = true);
// details = false decodes texture, level, x and y only (what a cache simulation reads): pixel_x,
// pixel_y and triangle are set to 0, and their columns, whose bytes must still all be there, are
// neither decoded nor range-checked (the chunk's checksum covers them).
std::string decode_texel_records(std::span<const std::uint8_t> raw, std::uint32_t records,
                                 std::vector<TexelAccess>& out, bool details = true, bool runs = true);
std::string decode_address_records(std::span<const std::uint8_t> raw, std::uint32_t records,
                                   std::vector<AddressAccess>& out, bool runs = true);
std::string decode_framebuffer_records(std::span<const std::uint8_t> raw, std::uint32_t records,
                                       std::vector<FramebufferAccess>& out, bool runs = true);

}  // namespace rastrace
