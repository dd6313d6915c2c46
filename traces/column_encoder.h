// The writer's side of a chunk's record columns (the format is described in chunk_codec.h): one
// field of every record, gathered into a contiguous lane, encoded in the smallest of the column
// modes. The encoder works on lanes rather than on the records themselves so that each of its
// passes (counting deltas, finding changes, writing deltas) reads 4 or 8 bytes a record in
// order, in vector lanes where the compiler can, instead of striding across 16-byte records once
// per pass: a trace file's writer encodes every event of a frame, and this is half its work.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace rastrace {

// Column modes besides the fixed widths 0, 1, 2, 4 and 8 bytes a delta.
inline constexpr std::uint8_t kEscapedBytes = 0x81;  // 1-byte deltas, 0xFF escapes to 8 bytes
inline constexpr std::uint8_t kRuns = 0x82;          // runs of equal values, each with its length
inline constexpr std::uint64_t kLongestRun = 0xFF;   // a longer run is stored as several, with zero deltas

// The encoder's working memory: the lanes of a chunk's fields and the runs of one column. A
// caller that encodes chunk after chunk keeps one, so that it is allocated (and its pages
// touched) once rather than per chunk.
struct ColumnScratch {
  std::vector<std::uint32_t> lanes;
  std::vector<std::uint64_t> wide_lane;  // a 64-bit field (addresses)
  std::vector<std::uint32_t> changes;    // the records where a column's value changes
  std::vector<char> runs;                // a column's run lengths at [0, n), deltas at [n, 2n), escapes after
};

// Records a column may hold (a chunk holds at most kMaxChunkRecords).
inline constexpr std::size_t kMostColumnRecords = 0xFFFFFFFFu - 8;

// Appends the column of `values` (record i's field is values[i]) to `out`; throws
// std::length_error past kMostColumnRecords.
void put_column(std::string& out, std::span<const std::uint32_t> values, ColumnScratch& scratch);
void put_column(std::string& out, std::span<const std::uint64_t> values, ColumnScratch& scratch);

// False: the encoder takes its portable paths from now on, as on a machine without AVX2 (for
// tests of those paths on any machine; the bytes are the same either way).
void use_column_encoder_simd(bool enabled);

}  // namespace rastrace
