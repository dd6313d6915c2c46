// Sliding-window VIPM (Forsyth, "Comparison of VIPM Methods", 2001): fully static, global index
// lists and no index editing at run time. A collapse's binned AND changed triangles drop off the
// end of the drawn window, and the changed triangles' new versions join at its start. Per level
// the index list has three sections:
//   [added: the new versions, last collapse first] [middle: untouched, vertex-cache order]
//   [binned or changed: the old versions, last collapse first, so the first collapse at the end]
// and LoD first_lod + j draws the window that starts j blocks before the middle and ends j blocks
// before the list's end. A triangle changed by a collapse cannot take part in another in the same
// level (its new version is already in the added section), so such a collapse starts a new level:
// the collapsed mesh, re-ordered. The levels' lists are concatenated; a SlidingWindowRecord per LoD
// (first index, triangles, vertices) is all a draw needs. Per instance: the LoD.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "lod/progressive_mesh.h"
#include "lod/vanilla.h"
#include "lod/vipm_representation.h"
#include "reorder/ordering.h"
#include "scenes/mesh.h"

namespace rastrace {

struct SlidingWindowParams {
  std::string algorithm = "tipsy";  // the list ordering of each level's middle section
  ReorderParams reorder;
};

// Forsyth's table entry; wider counts (12 bytes) when a LoD has more than 65,535 triangles or vertices.
struct SlidingWindowRecord {
  std::uint32_t first_index = 0;
  std::uint32_t triangles = 0;
  std::uint32_t vertices = 0;
};

class SlidingWindow : public VipmRepresentation {
 public:
  SlidingWindow(std::vector<std::uint32_t> indices, std::vector<SlidingWindowRecord> records,
                std::vector<std::uint32_t> level_first_lod, std::uint32_t vertex_bytes);

  std::string method() const override { return "sliding-window"; }
  std::uint32_t lod_count() const override { return static_cast<std::uint32_t>(records_.size()); }
  std::uint32_t lod() const override { return lod_; }
  LodChangeCost set_lod(std::uint32_t lod) override;
  std::vector<VipmDraw> draws() const override;
  VipmMemory memory() const override;
  std::uint64_t streaming_bytes() const override;
  std::uint32_t levels() const override { return static_cast<std::uint32_t>(level_first_lod_.size()); }
  std::uint32_t level() const override;
  std::uint32_t index_bytes() const override { return index_bytes_; }
  std::string layout() const override;

  const std::vector<std::uint32_t>& indices() const { return indices_; }
  const std::vector<SlidingWindowRecord>& records() const { return records_; }
  std::uint32_t record_bytes() const { return record_bytes_; }
  // The instance holds its LoD and nothing else.
  static constexpr std::uint64_t kInstanceBytes = 4;

 private:
  std::vector<std::uint32_t> indices_;
  std::vector<SlidingWindowRecord> records_;
  std::vector<std::uint32_t> level_first_lod_;
  std::uint32_t vertex_bytes_;
  std::uint32_t index_bytes_;
  std::uint32_t record_bytes_;
  std::uint32_t lod_ = 0;
};

// `vertices`: the vertex buffer in pm's numbering (positions only are read).
std::unique_ptr<SlidingWindow> build_sliding_window(const ProgressiveMesh& pm, const Mesh& vertices,
                                                    const SlidingWindowParams& window = {},
                                                    const VipmBuildParams& params = {});

// Where sliding window's levels start for this collapse order: a level ends before the first
// collapse that bins or changes a triangle changed earlier in the level.
std::vector<std::uint32_t> sliding_window_level_starts(const ProgressiveMesh& pm);

}  // namespace rastrace
