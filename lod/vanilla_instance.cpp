#include "lod/vanilla_instance.h"

#include <algorithm>
#include <stdexcept>

#include "reorder/strip.h"

namespace rastrace {

EditedIndexLists::EditedIndexLists(EditedListsSpec spec, std::vector<EditedLevel> levels)
    : spec_(std::move(spec)), levels_(std::move(levels)) {
  if (levels_.empty() || levels_.front().first_lod != 0) throw std::logic_error("EditedIndexLists: no level at LoD 0");
  std::uint64_t address = 0;
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    const EditedLevel& level = levels_[l];
    if (l > 0 && level.first_lod != levels_[l - 1].first_lod + levels_[l - 1].collapses)
      throw std::logic_error("EditedIndexLists: levels do not follow each other");
    // Walk the records once: where the sentinel is and the triangle counts at the level's end.
    std::size_t at = 0;
    std::uint32_t static_tris = level.static_triangles, dynamic_tris = level.dynamic_triangles;
    for (std::uint32_t i = 0; i < level.collapses; ++i) {
      const CollapseRecordView r = read_record(spec_.layout, level.records, at);
      if (spec_.layout.two_triangle_counts) {
        static_tris -= r.triangles;
        dynamic_tris -= r.dynamic_triangles;
      } else {
        dynamic_tris -= r.triangles;
      }
      at += r.bytes;
    }
    sentinel_at_.push_back(at);
    static_end_.push_back(static_tris);
    dynamic_end_.push_back(dynamic_tris);
    for (const std::vector<std::uint32_t>* list :
         {&level.static_indices, &level.dynamic_start, &level.dynamic_collapsed}) {
      global_address_.push_back(address);
      address += list->size() * spec_.index_bytes;
    }
  }
  lod_count_ = levels_.back().first_lod + levels_.back().collapses + 1;
  const EditedLevel& first = levels_.front();
  dynamic_ = first.dynamic_start;
  static_triangles_ = first.static_triangles;
  dynamic_triangles_ = first.dynamic_triangles;
}

std::uint32_t EditedIndexLists::level_of(std::uint32_t lod) const {
  std::uint32_t l = 0;
  while (l + 1 < levels_.size() && levels_[l + 1].first_lod <= lod) ++l;
  return l;
}

bool EditedIndexLists::enter_from_collapsed(std::uint32_t level, std::uint32_t lod) const {
  const EditedLevel& l = levels_[level];
  return !l.dynamic_collapsed.empty() && l.first_lod + l.collapses - lod < lod - l.first_lod;
}

void EditedIndexLists::collapse(LodChangeCost& cost) {
  const EditedLevel& level = levels_[level_];
  const CollapseRecordView r = read_record(spec_.layout, level.records, record_at_);
  cost.index_writes += rewrite_indices(spec_.layout, level.records, r, dynamic_, r.kept);
  if (spec_.layout.two_triangle_counts) {
    static_triangles_ -= r.triangles;
    dynamic_triangles_ -= r.dynamic_triangles;
  } else {
    dynamic_triangles_ -= r.triangles;
  }
  cost.record_bytes_read += r.bytes;
  ++cost.collapses;
  record_at_ += r.bytes;
  ++lod_;
}

void EditedIndexLists::split(LodChangeCost& cost) {
  const EditedLevel& level = levels_[level_];
  const CollapseRecordView here = read_record(spec_.layout, level.records, record_at_);
  record_at_ = previous_record_at(spec_.layout, here, record_at_);
  const CollapseRecordView r = read_record(spec_.layout, level.records, record_at_);
  --lod_;
  // Collapse n binned the last vertex in use before it: vertex_count - 1 - n.
  cost.index_writes += rewrite_indices(spec_.layout, level.records, r, dynamic_, spec_.vertex_count - 1 - lod_);
  if (spec_.layout.two_triangle_counts) {
    static_triangles_ += r.triangles;
    dynamic_triangles_ += r.dynamic_triangles;
  } else {
    dynamic_triangles_ += r.triangles;
  }
  cost.record_bytes_read += spec_.layout.header_bytes() + r.bytes;
  ++cost.splits;
}

LodChangeCost EditedIndexLists::set_lod(std::uint32_t lod) {
  lod = std::min(lod, lod_count_ - 1);
  LodChangeCost cost;
  const std::uint32_t target = level_of(lod);
  if (target != level_) {
    const EditedLevel& level = levels_[target];
    level_ = target;
    if (enter_from_collapsed(target, lod)) {
      dynamic_ = level.dynamic_collapsed;
      lod_ = level.first_lod + level.collapses;
      record_at_ = sentinel_at_[target];
      static_triangles_ = static_end_[target];
      dynamic_triangles_ = dynamic_end_[target];
    } else {
      dynamic_ = level.dynamic_start;
      lod_ = level.first_lod;
      record_at_ = 0;
      static_triangles_ = level.static_triangles;
      dynamic_triangles_ = level.dynamic_triangles;
    }
    ++cost.level_switches;
    cost.bytes_copied += dynamic_.size() * spec_.index_bytes;
  }
  while (lod_ < lod) collapse(cost);
  while (lod_ > lod) split(cost);
  return cost;
}

std::uint64_t EditedIndexLists::list_address(std::uint32_t level, int which) const {
  return global_address_[3 * std::size_t(level) + which];
}

std::vector<VipmDraw> EditedIndexLists::draws() const {
  std::vector<VipmDraw> out;
  const std::uint32_t vertices = spec_.vertex_count - lod_;
  auto add = [&](PrimitiveType type, const std::vector<std::uint32_t>& list, std::uint32_t triangles,
                 std::uint64_t address) {
    const std::size_t count = type == PrimitiveType::TriangleList ? 3 * std::size_t(triangles) : list.size();
    if (count == 0) return;
    out.push_back({type, std::span<const std::uint32_t>(list.data(), count),
                   type == PrimitiveType::TriangleStrip ? kStripRestart : kNoRestart, vertices, address});
  };
  add(spec_.dynamic_type, dynamic_, dynamic_triangles_, kInstanceIndexAddress);
  const EditedLevel& level = levels_[level_];
  add(spec_.static_type, level.static_indices, static_triangles_, list_address(level_, 0));
  return out;
}

VipmMemory EditedIndexLists::memory() const {
  VipmMemory m;
  m.vertex_bytes = std::uint64_t(spec_.vertex_count) * spec_.vertex_bytes;
  for (const EditedLevel& level : levels_) {
    m.index_list_bytes +=
        (level.static_indices.size() + level.dynamic_start.size() + level.dynamic_collapsed.size()) * spec_.index_bytes;
    m.record_bytes += level.records.size();
  }
  m.table_bytes = levels_.size() > 1 ? levels_.size() * kLevelTableEntryBytes : 0;
  m.instance_bytes = dynamic_.size() * spec_.index_bytes + kInstanceStateBytes;
  return m;
}

std::uint64_t EditedIndexLists::streaming_bytes() const {
  const EditedLevel& level = levels_[level_];
  const std::uint64_t ib = spec_.index_bytes;
  std::uint64_t bytes = std::uint64_t(spec_.vertex_count - lod_) * spec_.vertex_bytes;
  // The static list's drawn part.
  if (!level.static_indices.empty())
    bytes += (spec_.static_type == PrimitiveType::TriangleList ? 3 * std::uint64_t(static_triangles_)
                                                               : level.static_indices.size()) *
             ib;
  // The stored list the instance is built from (only its live part, for a list) and the records
  // walked from it.
  const bool from_collapsed = enter_from_collapsed(level_, lod_);
  if (spec_.dynamic_type == PrimitiveType::TriangleList)
    bytes += 3 * std::uint64_t(dynamic_triangles_) * ib;
  else
    bytes += dynamic_.size() * ib;
  bytes += from_collapsed ? sentinel_at_[level_] - record_at_ + spec_.layout.header_bytes() : record_at_;
  if (levels_.size() > 1) bytes += kLevelTableEntryBytes;
  return bytes;
}

}  // namespace rastrace
