// The SIMD kernels between texel records and lanes (one contiguous uint32 array per record
// column). A texel chunk is decoded block by block into lanes, and the lanes are then interleaved
// into TexelAccess records (chunk_codec.cpp); a trace writer splits the records it is given into
// its open chunk's lanes (texel_columns.h):
//   add_byte_deltas()    a column of 1-byte zig-zag deltas (modes 1 and 0x81, chunk_codec.h) as
//                        prefix sums, eight records at a time;
//   interleave_texels()  the lanes into records, each record written once (16 bytes) instead of
//                        a store per field;
//   split_texels()       records into lanes, eight records as four loads and seven stores instead
//                        of fourteen of each.
// All use AVX2 where the machine has it; elsewhere add_byte_deltas() does nothing (the caller's
// scalar decoder does the work) and the others move a field at a time.
#pragma once

#include <cstddef>
#include <cstdint>

#include "traces/events.h"

namespace rastrace {

// The running state of a column of byte deltas: the low 32 bits of its last value (the lanes
// hold low 32 bits), and what the column's range check needs. A value's full 64 bits (the
// decoder's) leave [0, 2^32) only by a step of at most 128 across 0 or 2^32, which
// `left_32_bits` records; `ored` is the OR of the low 32 bits of every value written (against
// limits below 2^32: a value's first step above the limit, or below 0, sets bits above the
// limit's in its low 32 bits).
struct ByteDeltaSums {
  std::uint32_t value = 0;
  std::uint32_t ored = 0;
  bool left_32_bits = false;
};

// Adds deltas[0..) (zig-zag bytes) to `sums.value` eight at a time, writing each sum to
// lane[0..), while at least eight records are left of `count` and, when `escapes`, the eight
// bytes hold no escape (0xFF, mode 0x81). Returns the records done (a multiple of 8, 0 without
// AVX2); the caller decodes the rest.
std::size_t add_byte_deltas(const std::uint8_t* deltas, std::size_t count, bool escapes, ByteDeltaSums& sums,
                            std::uint32_t* lane);

// One block of decoded columns, `count` records each. Values are truncated to their field's width
// (level to 8 bits, the others but the triangle to 16: a column out of range is reported by its decoder,
// which then drops the records). pixel_x, pixel_y and triangle may be null: the fields are then 0.
struct TexelLanes {
  const std::uint32_t* texture = nullptr;
  const std::uint32_t* level = nullptr;
  const std::uint32_t* x = nullptr;
  const std::uint32_t* y = nullptr;
  const std::uint32_t* pixel_x = nullptr;
  const std::uint32_t* pixel_y = nullptr;
  const std::uint32_t* triangle = nullptr;
};

// Writes records out[0..count) from the lanes (the padding byte after `level` is written 0).
void interleave_texels(const TexelLanes& lanes, std::size_t count, TexelAccess* out);
// The same without SIMD, whatever the machine (for tests comparing the two).
void interleave_texels_portable(const TexelLanes& lanes, std::size_t count, TexelAccess* out);

// Lanes a record splits into: texture, level, x, y, pixel_x, pixel_y, triangle.
inline constexpr std::size_t kTexelLaneFields = 7;

// The inverse, for the trace writer's open chunk (texel_columns.h): field k of records[i] (texture,
// level, x, y, pixel_x, pixel_y, triangle, each widened to 32 bits) to lanes[k * stride + i].
void split_texels(const TexelAccess* records, std::size_t count, std::uint32_t* lanes, std::size_t stride);
void split_texels_portable(const TexelAccess* records, std::size_t count, std::uint32_t* lanes, std::size_t stride);

// False: the kernels take their portable paths from now on, as on a machine without AVX2 (for
// tests of those paths on any machine; true, the default, uses AVX2 where there is one).
void use_texel_lane_simd(bool enabled);

}  // namespace rastrace
