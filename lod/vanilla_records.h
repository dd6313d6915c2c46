// Forsyth's variable-length collapse record ("Comparison of VIPM Methods", 2001), as the bytes a
// game would stream: the kept vertex, the triangle count(s) that fall off the end of the list,
// the number of index offsets to rewrite, the previous record's number (so that splits can walk
// backwards), then the offsets themselves. Records follow each other in memory in collapse order.
//
// Forsyth's struct is the 16-bit case: a 6-byte header (unsigned short wKeptVert, three unsigned
// chars, one pad byte) and unsigned short offsets. The widths here follow the mesh: vertices are
// 16-bit while there are at most 65,535 of them (65,535 stays free for a strip restart), offsets
// 16-bit while the index list has at most 65,536 entries, counts 8-bit while they fit, and the
// header is padded to the wider of the two. Mixed-mode has two triangle counts (static, dynamic).
// A sentinel header ends each stream, so a split from the end can read its predecessor's size.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace rastrace {

struct CollapseRecordLayout {
  std::uint32_t vertex_bytes = 2;  // wKeptVert
  std::uint32_t count_bytes = 1;   // bNumTris (bNumStaticTris, bNumDynamicTris), bNumChanges, bPrevNumChanges
  std::uint32_t offset_bytes = 2;  // wIndexOffset[]
  bool two_triangle_counts = false;

  std::uint32_t alignment() const { return vertex_bytes > offset_bytes ? vertex_bytes : offset_bytes; }
  std::uint32_t header_bytes() const;
  std::uint32_t record_bytes(std::uint32_t changes) const;
  // "kept 16-bit, counts 8-bit, offsets 16-bit, 6-byte header"
  std::string describe() const;
};

// The narrowest layout for records over index lists of at most `max_list_length` entries,
// `vertex_count` vertices and counts up to `max_count`.
CollapseRecordLayout choose_record_layout(std::uint64_t vertex_count, std::uint64_t max_list_length,
                                          std::uint64_t max_count, bool two_triangle_counts);

struct CollapseRecordView {
  std::uint32_t kept = 0;
  std::uint32_t triangles = 0;          // binned off the end of the (single or static) list
  std::uint32_t dynamic_triangles = 0;  // mixed-mode: binned off the end of the dynamic list
  std::uint32_t changes = 0;
  std::uint32_t previous_changes = 0;
  std::size_t offsets_at = 0;  // byte position of the first offset
  std::size_t bytes = 0;       // the whole record, padding included
};

class CollapseRecordStream {
 public:
  explicit CollapseRecordStream(const CollapseRecordLayout& layout) : layout_(layout) {}

  void append(std::uint32_t kept, std::uint32_t triangles, std::uint32_t dynamic_triangles,
              std::span<const std::uint32_t> offsets);
  // Writes the sentinel and returns the bytes.
  std::vector<std::uint8_t> finish();

 private:
  void put(std::uint64_t value, std::uint32_t bytes);
  CollapseRecordLayout layout_;
  std::vector<std::uint8_t> bytes_;
  std::uint32_t previous_changes_ = 0;
};

// The record starting at byte `at`.
CollapseRecordView read_record(const CollapseRecordLayout& layout, std::span<const std::uint8_t> bytes, std::size_t at);
// The i-th offset of a record.
std::uint32_t record_offset(const CollapseRecordLayout& layout, std::span<const std::uint8_t> bytes,
                            const CollapseRecordView& record, std::uint32_t i);
// Byte position of the record before the one at `at` (whose view is `record`).
inline std::size_t previous_record_at(const CollapseRecordLayout& layout, const CollapseRecordView& record,
                                      std::size_t at) {
  return at - layout.record_bytes(record.previous_changes);
}

// Vanilla's run-time edit: every offset of the record gets `value` (the kept vertex on a
// collapse, the binned one on a split). Returns the number of indices written.
std::uint32_t rewrite_indices(const CollapseRecordLayout& layout, std::span<const std::uint8_t> bytes,
                              const CollapseRecordView& record, std::span<std::uint32_t> indices, std::uint32_t value);

}  // namespace rastrace
