// What every VIPM representation offers the measurements: a level of detail set at run time
// (LoD = collapses done), the draws a GPU would receive for it, and what it costs in memory and
// in work to get there. The representations (Forsyth, "Comparison of VIPM Methods", Game
// Programming Gems 2, 2001) live in vanilla.h, skip_strips.h, mixed_mode.h and sliding_window.h;
// each object holds the global data and the state of ONE instance.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "traces/events.h"

namespace rastrace {

// One DrawIndexedPrimitive call.
struct VipmDraw {
  PrimitiveType type = PrimitiveType::TriangleList;
  std::span<const std::uint32_t> indices;  // what is sent; strips restart at restart_index
  RestartIndex restart_index = kNoRestart;
  std::uint32_t vertex_count = 0;   // the vertex range handed to the draw: 0 .. vertex_count - 1
  std::uint64_t index_address = 0;  // byte address of indices[0] (global buffers first, then the instance's)
};

// Work done by one LoD change.
struct LodChangeCost {
  std::uint64_t collapses = 0;
  std::uint64_t splits = 0;
  std::uint64_t index_writes = 0;    // indices rewritten by collapse records
  std::uint64_t level_switches = 0;  // a new level's index list copied into the instance
  std::uint64_t bytes_copied = 0;    // by level switches
  std::uint64_t record_bytes_read = 0;

  LodChangeCost& operator+=(const LodChangeCost& o) {
    collapses += o.collapses;
    splits += o.splits;
    index_writes += o.index_writes;
    level_switches += o.level_switches;
    bytes_copied += o.bytes_copied;
    record_bytes_read += o.record_bytes_read;
    return *this;
  }
};

struct VipmMemory {
  // Global (shared by all instances).
  std::uint64_t vertex_bytes = 0;      // the vertex buffer
  std::uint64_t index_list_bytes = 0;  // every stored index list (levels, collapsed copies, static lists)
  std::uint64_t record_bytes = 0;      // collapse records
  std::uint64_t table_bytes = 0;       // level tables, sliding-window records
  // Per instance, at the current LoD (the index list copy and the state that walks the records).
  std::uint64_t instance_bytes = 0;

  std::uint64_t global_bytes() const { return vertex_bytes + index_list_bytes + record_bytes + table_bytes; }
};

class VipmRepresentation {
 public:
  virtual ~VipmRepresentation() = default;

  // "vanilla", "skip-strips-list", "skip-strips-strip", "mixed-list", "mixed-strip", "sliding-window"
  virtual std::string method() const = 0;
  // LoDs 0 .. lod_count() - 1.
  virtual std::uint32_t lod_count() const = 0;
  virtual std::uint32_t lod() const = 0;
  // Collapses, splits and level switches until the LoD is `lod` (clamped to the last).
  virtual LodChangeCost set_lod(std::uint32_t lod) = 0;
  virtual std::vector<VipmDraw> draws() const = 0;
  virtual VipmMemory memory() const = 0;
  // Bytes that must be resident to draw the current LoD: the vertices in range, the index bytes
  // the draws read, and the stored lists, records and table entries the instance was built from.
  virtual std::uint64_t streaming_bytes() const = 0;
  virtual std::uint32_t levels() const = 0;
  virtual std::uint32_t level() const = 0;        // the current one
  virtual std::uint32_t index_bytes() const = 0;  // 2 or 4
  // The record or table layout, for the output ("kept 16-bit, counts 8-bit, ...").
  virtual std::string layout() const = 0;
};

// Bytes per index: 16-bit while there are at most 65,535 vertices (65,535 = strip restart).
inline std::uint32_t vipm_index_bytes(std::uint64_t vertex_count) { return vertex_count <= 0xFFFF ? 2 : 4; }

// Where instance buffers start in the index address space (the global lists lie below).
inline constexpr std::uint64_t kInstanceIndexAddress = 1ull << 40;

}  // namespace rastrace
