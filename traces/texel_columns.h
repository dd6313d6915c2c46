// Texel records held as the trace encoder reads them: one lane per field (texture, level, x, y,
// pixel x, pixel y, triangle), field k of record i at lanes[k * capacity + i]. A trace writer
// fills its open texel chunk this way as batches arrive, while each batch is still in the
// renderer's cache, so that its compression threads read the lanes directly instead of first
// transposing 16-byte records that have gone cold by the time they get them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "traces/events.h"
#include "traces/texel_lanes.h"

namespace rastrace {

struct TexelColumns {
  static constexpr std::size_t kFields = kTexelLaneFields;
  std::vector<std::uint32_t> lanes;
  std::size_t capacity = 0;  // records the lanes hold
  std::size_t size = 0;      // records held

  // Empties the columns and gives them room for `records` (keeping the memory they have).
  void reset(std::size_t records) {
    capacity = records;
    size = 0;
    lanes.resize(kFields * records);
  }
  // Appends records; at most capacity - size of them.
  void append(std::span<const TexelAccess> records) {
    split_texels(records.data(), records.size(), lanes.data() + size, capacity);
    size += records.size();
  }
  std::span<const std::uint32_t> field(std::size_t k) const { return {lanes.data() + k * capacity, size}; }
};

}  // namespace rastrace
