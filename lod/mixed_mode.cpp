#include "lod/mixed_mode.h"

#include <algorithm>
#include <limits>

#include "lod/vanilla_numbering.h"

namespace rastrace {

namespace {

using Triangle = std::array<std::uint32_t, 3>;
constexpr std::uint32_t kNotBinned = std::numeric_limits<std::uint32_t>::max();

// The triangles in vertex-cache order (empty stays empty: orderings need a face).
std::vector<std::uint32_t> ordered(const Mesh& vertices, const std::vector<Triangle>& triangles,
                                   const LevelParams& params, std::vector<std::uint32_t>* face_order = nullptr) {
  if (triangles.empty()) return {};
  Ordering o = lod_detail::order_triangles(vertices, triangles, params.algorithm, params.reorder, params.primitive);
  if (face_order) *face_order = std::move(o.face_order);
  return std::move(o.indices);
}

void append(std::vector<std::uint32_t>& list, const std::vector<Triangle>& triangles) {
  for (const Triangle& t : triangles) list.insert(list.end(), t.begin(), t.end());
}

}  // namespace

std::unique_ptr<EditedIndexLists> build_mixed_mode(const ProgressiveMesh& pm, const Mesh& vertices,
                                                   const LevelParams& level_params, const VipmBuildParams& params) {
  lod_detail::check_level_params(level_params);
  const bool strips = level_params.primitive == PrimitiveType::TriangleStrip;
  std::vector<EditedLevel> levels;
  std::vector<lod_detail::LevelEdits> edits;
  lod_detail::for_each_level(
      pm, level_params.new_level_fraction, [&](const TriangleReplay& replay, std::uint32_t first, std::uint32_t end) {
        const std::uint32_t alive = replay.alive();
        std::vector<std::uint8_t> modified(alive, 0);
        std::vector<std::uint32_t> binned_at(alive, kNotBinned);
        for (std::uint32_t n = first; n < end; ++n) {
          for (std::uint32_t t : pm.collapses[n].changed_triangles) modified[t] = 1;
          for (std::uint32_t t : pm.collapses[n].binned_triangles) binned_at[t] = n;
        }
        // Forsyth's lists 1 to 4 (index 0 to 3); a triangle binned after being modified was modified first.
        std::vector<std::uint32_t> lists[4];
        for (std::uint32_t t = 0; t < alive; ++t)
          lists[(binned_at[t] != kNotBinned ? 1 : 0) + (modified[t] ? 2 : 0)].push_back(t);
        // Lists 2 and 4 in reverse bin order: the first collapse's triangles at the end.
        for (int l : {1, 3})
          std::stable_sort(lists[l].begin(), lists[l].end(),
                           [&](std::uint32_t a, std::uint32_t b) { return binned_at[a] > binned_at[b]; });
        auto triangles_of = [&](std::initializer_list<int> which) {
          std::vector<Triangle> out;
          for (int l : which)
            for (std::uint32_t t : lists[l]) out.push_back(replay.triangle(t));
          return out;
        };

        EditedLevel& level = levels.emplace_back();
        level.first_lod = first;
        level.collapses = end - first;
        lod_detail::LevelEdits& edit = edits.emplace_back();
        if (strips) {
          // The static strip never changes; lists 2, 3, 4 form a skip strip.
          level.static_indices = ordered(vertices, triangles_of({0}), level_params);
          level.dynamic_start = ordered(vertices, triangles_of({1, 2, 3}), level_params);
          edit.offsets = lod_detail::skip_strip_offsets(pm, level.dynamic_start, first, end);
          edit.triangles.assign(level.collapses, 0);
          edit.dynamic_triangles.assign(level.collapses, 0);
        } else {
          // Static: list 1 ordered, then list 2. Dynamic: list 3 ordered, then list 4.
          std::vector<std::uint32_t> order3;
          level.static_indices = ordered(vertices, triangles_of({0}), level_params);
          append(level.static_indices, triangles_of({1}));
          level.dynamic_start = ordered(vertices, triangles_of({2}), level_params, &order3);
          append(level.dynamic_start, triangles_of({3}));
          level.static_triangles = static_cast<std::uint32_t>(lists[0].size() + lists[1].size());
          level.dynamic_triangles = static_cast<std::uint32_t>(lists[2].size() + lists[3].size());
          std::vector<std::uint32_t> dynamic_slot(alive, 0);
          for (std::size_t i = 0; i < order3.size(); ++i)
            dynamic_slot[lists[2][order3[i]]] = static_cast<std::uint32_t>(i);
          for (std::size_t i = 0; i < lists[3].size(); ++i)
            dynamic_slot[lists[3][i]] = static_cast<std::uint32_t>(lists[2].size() + i);
          for (std::uint32_t n = first; n < end; ++n) {
            const CollapseRecord& c = pm.collapses[n];
            std::uint32_t in_static = 0, in_dynamic = 0;
            for (std::uint32_t t : c.binned_triangles) (modified[t] ? in_dynamic : in_static) += 1;
            edit.triangles.push_back(in_static);
            edit.dynamic_triangles.push_back(in_dynamic);
            std::vector<std::uint32_t>& offsets = edit.offsets.emplace_back();
            for (std::uint32_t corner : c.changed_corners) offsets.push_back(3 * dynamic_slot[corner / 3] + corner % 3);
          }
        }
      });
  return lod_detail::assemble_levels(strips ? "mixed-strip" : "mixed-list", pm, level_params.primitive, !strips, true,
                                     std::move(levels), edits, params);
}

}  // namespace rastrace
