#include "lod/vanilla.h"

#include "lod/skip_strips.h"

namespace rastrace {

std::unique_ptr<EditedIndexLists> build_vanilla(const ProgressiveMesh& pm, const VipmBuildParams& params) {
  // One level, the full-detail list in vanilla order; no collapsed copy.
  std::vector<EditedLevel> levels(1);
  EditedLevel& level = levels.front();
  level.collapses = static_cast<std::uint32_t>(pm.collapses.size());
  for (const auto& t : pm.triangles) level.dynamic_start.insert(level.dynamic_start.end(), t.begin(), t.end());
  level.dynamic_triangles = static_cast<std::uint32_t>(pm.triangles.size());
  std::vector<lod_detail::LevelEdits> edits(1);
  for (const CollapseRecord& c : pm.collapses) {
    edits[0].triangles.push_back(static_cast<std::uint32_t>(c.binned_triangles.size()));
    edits[0].dynamic_triangles.push_back(0);
    edits[0].offsets.push_back(c.changed_corners);
  }
  return lod_detail::assemble_levels("vanilla", pm, PrimitiveType::TriangleList, false, false, std::move(levels), edits,
                                     params);
}

}  // namespace rastrace
