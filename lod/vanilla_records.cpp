#include "lod/vanilla_records.h"

#include <cstring>

#include "core/error.h"

namespace rastrace {

namespace {

std::uint32_t round_up(std::uint32_t value, std::uint32_t to) { return (value + to - 1) / to * to; }

std::uint64_t get(std::span<const std::uint8_t> bytes, std::size_t at, std::uint32_t width) {
  std::uint64_t value = 0;
  for (std::uint32_t i = 0; i < width; ++i) value |= std::uint64_t(bytes[at + i]) << (8 * i);
  return value;
}

std::uint32_t bits(std::uint32_t bytes) { return 8 * bytes; }

}  // namespace

std::uint32_t CollapseRecordLayout::header_bytes() const {
  return round_up(vertex_bytes + count_bytes * (two_triangle_counts ? 4 : 3), alignment());
}

std::uint32_t CollapseRecordLayout::record_bytes(std::uint32_t changes) const {
  return round_up(header_bytes() + changes * offset_bytes, alignment());
}

std::string CollapseRecordLayout::describe() const {
  return "kept " + std::to_string(bits(vertex_bytes)) + "-bit, counts " + std::to_string(bits(count_bytes)) +
         "-bit, offsets " + std::to_string(bits(offset_bytes)) + "-bit, " + std::to_string(header_bytes()) +
         "-byte header";
}

CollapseRecordLayout choose_record_layout(std::uint64_t vertex_count, std::uint64_t max_list_length,
                                          std::uint64_t max_count, bool two_triangle_counts) {
  CollapseRecordLayout layout;
  layout.vertex_bytes = vertex_count <= 0xFFFF ? 2 : 4;
  layout.offset_bytes = max_list_length <= 0x10000 ? 2 : 4;
  layout.count_bytes = max_count <= 0xFF ? 1 : (max_count <= 0xFFFF ? 2 : 4);
  layout.two_triangle_counts = two_triangle_counts;
  return layout;
}

void CollapseRecordStream::put(std::uint64_t value, std::uint32_t bytes) {
  for (std::uint32_t i = 0; i < bytes; ++i) bytes_.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

void CollapseRecordStream::append(std::uint32_t kept, std::uint32_t triangles, std::uint32_t dynamic_triangles,
                                  std::span<const std::uint32_t> offsets) {
  const std::uint64_t count_limit = layout_.count_bytes == 4 ? 0xFFFFFFFFull : (1ull << bits(layout_.count_bytes)) - 1;
  if (triangles > count_limit || dynamic_triangles > count_limit || offsets.size() > count_limit)
    throw InputError("collapse record: a count does not fit the record layout (" + layout_.describe() + ")");
  const std::size_t start = bytes_.size();
  put(kept, layout_.vertex_bytes);
  put(triangles, layout_.count_bytes);
  if (layout_.two_triangle_counts) put(dynamic_triangles, layout_.count_bytes);
  put(offsets.size(), layout_.count_bytes);
  put(previous_changes_, layout_.count_bytes);
  bytes_.resize(start + layout_.header_bytes(), 0);
  for (std::uint32_t offset : offsets) put(offset, layout_.offset_bytes);
  bytes_.resize(start + layout_.record_bytes(static_cast<std::uint32_t>(offsets.size())), 0);
  previous_changes_ = static_cast<std::uint32_t>(offsets.size());
}

std::vector<std::uint8_t> CollapseRecordStream::finish() {
  append(0, 0, 0, {});
  return std::move(bytes_);
}

CollapseRecordView read_record(const CollapseRecordLayout& layout, std::span<const std::uint8_t> bytes,
                               std::size_t at) {
  CollapseRecordView view;
  std::size_t p = at;
  view.kept = static_cast<std::uint32_t>(get(bytes, p, layout.vertex_bytes));
  p += layout.vertex_bytes;
  view.triangles = static_cast<std::uint32_t>(get(bytes, p, layout.count_bytes));
  p += layout.count_bytes;
  if (layout.two_triangle_counts) {
    view.dynamic_triangles = static_cast<std::uint32_t>(get(bytes, p, layout.count_bytes));
    p += layout.count_bytes;
  }
  view.changes = static_cast<std::uint32_t>(get(bytes, p, layout.count_bytes));
  p += layout.count_bytes;
  view.previous_changes = static_cast<std::uint32_t>(get(bytes, p, layout.count_bytes));
  view.offsets_at = at + layout.header_bytes();
  view.bytes = layout.record_bytes(view.changes);
  return view;
}

std::uint32_t record_offset(const CollapseRecordLayout& layout, std::span<const std::uint8_t> bytes,
                            const CollapseRecordView& record, std::uint32_t i) {
  return static_cast<std::uint32_t>(
      get(bytes, record.offsets_at + std::size_t(i) * layout.offset_bytes, layout.offset_bytes));
}

std::uint32_t rewrite_indices(const CollapseRecordLayout& layout, std::span<const std::uint8_t> bytes,
                              const CollapseRecordView& record, std::span<std::uint32_t> indices, std::uint32_t value) {
  for (std::uint32_t i = 0; i < record.changes; ++i) indices[record_offset(layout, bytes, record, i)] = value;
  return record.changes;
}

}  // namespace rastrace
