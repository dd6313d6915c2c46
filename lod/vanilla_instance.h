// The run-time half of vanilla VIPM (Forsyth, "Comparison of VIPM Methods", 2001): a per-instance
// index list copied from global memory and edited in place by collapse records, generalised to
// the levels of multilevel skip strips and mixed-mode, which use the same records and the same
// edit. Each level keeps its list as taken at the level's first LoD and, when asked, its fully
// collapsed copy (Forsyth's suggestion), so that entering a level from below costs splits, not
// collapses. Mixed-mode adds a static list per level, drawn in place, never edited.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lod/vanilla_records.h"
#include "lod/vipm_representation.h"

namespace rastrace {

struct EditedLevel {
  std::uint32_t first_lod = 0;  // the level holds LoDs first_lod .. first_lod + collapses
  std::uint32_t collapses = 0;
  // Shared, drawn in place (mixed-mode's lists 1 + 2, or its static strip; empty otherwise). A
  // list draws its first static_triangles, fewer as records bin them; a strip draws it whole.
  std::vector<std::uint32_t> static_indices;
  std::uint32_t static_triangles = 0;
  // The instance's list at first_lod and fully collapsed (empty when not kept).
  std::vector<std::uint32_t> dynamic_start;
  std::vector<std::uint32_t> dynamic_collapsed;
  std::uint32_t dynamic_triangles = 0;  // lists: triangles of dynamic_start
  std::vector<std::uint8_t> records;    // `collapses` records and a sentinel
};

struct EditedListsSpec {
  std::string method;
  PrimitiveType static_type = PrimitiveType::TriangleList;
  PrimitiveType dynamic_type = PrimitiveType::TriangleList;
  CollapseRecordLayout layout;
  std::uint32_t vertex_count = 0;  // at full detail; collapse n bins vertex vertex_count - 1 - n
  std::uint32_t vertex_bytes = 32;
  std::uint32_t index_bytes = 2;
};

class EditedIndexLists : public VipmRepresentation {
 public:
  // Levels in LoD order, the first at LoD 0, each starting where the previous one ends.
  EditedIndexLists(EditedListsSpec spec, std::vector<EditedLevel> levels);

  std::string method() const override { return spec_.method; }
  std::uint32_t lod_count() const override { return lod_count_; }
  std::uint32_t lod() const override { return lod_; }
  LodChangeCost set_lod(std::uint32_t lod) override;
  std::vector<VipmDraw> draws() const override;
  VipmMemory memory() const override;
  std::uint64_t streaming_bytes() const override;
  std::uint32_t levels() const override { return static_cast<std::uint32_t>(levels_.size()); }
  std::uint32_t level() const override { return level_; }
  std::uint32_t index_bytes() const override { return spec_.index_bytes; }
  std::string layout() const override { return spec_.layout.describe(); }

  const std::vector<EditedLevel>& level_data() const { return levels_; }
  // The instance's current (edited) list.
  const std::vector<std::uint32_t>& instance_indices() const { return dynamic_; }

  // Per-instance state besides the list: LoD, level, record position, two triangle counts.
  static constexpr std::uint64_t kInstanceStateBytes = 20;
  // Per level: first LoD, record offset, and offset and length of its three lists.
  static constexpr std::uint64_t kLevelTableEntryBytes = 32;

 private:
  std::uint32_t level_of(std::uint32_t lod) const;
  // Whether entering level L at `lod` starts from its collapsed copy (fewer record walks).
  bool enter_from_collapsed(std::uint32_t level, std::uint32_t lod) const;
  void collapse(LodChangeCost& cost);
  void split(LodChangeCost& cost);
  std::uint64_t list_address(std::uint32_t level, int which) const;  // 0 static, 1 start, 2 collapsed

  EditedListsSpec spec_;
  std::vector<EditedLevel> levels_;
  std::vector<std::size_t> sentinel_at_;   // per level: byte position of its sentinel record
  std::vector<std::uint32_t> static_end_;  // per level: static triangles when fully collapsed
  std::vector<std::uint32_t> dynamic_end_;
  std::vector<std::uint64_t> global_address_;  // per level x 3 lists
  std::uint32_t lod_count_ = 1;

  // The instance.
  std::uint32_t lod_ = 0;
  std::uint32_t level_ = 0;
  std::size_t record_at_ = 0;
  std::uint32_t static_triangles_ = 0;
  std::uint32_t dynamic_triangles_ = 0;
  std::vector<std::uint32_t> dynamic_;
};

}  // namespace rastrace
