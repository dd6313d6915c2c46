#include "lod/skip_strips.h"

#include <algorithm>

#include "core/error.h"
#include "lod/vanilla_numbering.h"

namespace rastrace {

namespace lod_detail {

void check_level_params(const LevelParams& level) {
  if (!(level.new_level_fraction > 0.0 && level.new_level_fraction <= 1.0))
    throw InputError("new-level fraction " + std::to_string(level.new_level_fraction) + ": expected a value in (0, 1]");
  find_reorder_algorithm(level.algorithm);
}

std::uint32_t level_end(const ProgressiveMesh& pm, std::uint32_t first_lod, std::uint32_t triangles, double fraction) {
  const auto last = static_cast<std::uint32_t>(pm.collapses.size());
  std::uint64_t binned = 0;
  std::uint32_t n = first_lod;
  while (n < last) {
    binned += pm.collapses[n].binned_triangles.size();
    ++n;
    if (double(binned) >= fraction * double(triangles)) break;
  }
  return n;
}

void for_each_level(const ProgressiveMesh& pm, double fraction,
                    const std::function<void(const TriangleReplay&, std::uint32_t, std::uint32_t)>& make_level) {
  const auto last = static_cast<std::uint32_t>(pm.collapses.size());
  TriangleReplay replay(pm);
  std::uint32_t first = 0;
  do {
    replay.advance_to(first);
    const std::uint32_t end = first == last ? last : level_end(pm, first, replay.alive(), fraction);
    make_level(replay, first, end);
    first = end;
  } while (first < last);
}

Ordering order_triangles(const Mesh& vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
                         const std::string& algorithm, const ReorderParams& params, PrimitiveType primitive) {
  Mesh mesh;
  mesh.name = vertices.name;
  mesh.positions = vertices.positions;
  mesh.indices.reserve(3 * triangles.size());
  for (const auto& t : triangles) mesh.indices.insert(mesh.indices.end(), t.begin(), t.end());
  Ordering ordering = find_reorder_algorithm(algorithm).run(mesh, params);
  if (primitive == PrimitiveType::TriangleList) {
    ordering.indices = indices_in_face_order(mesh, ordering.face_order);
    ordering.type = PrimitiveType::TriangleList;
    ordering.restart_index = kNoRestart;
  } else if (ordering.type != PrimitiveType::TriangleStrip) {
    throw InputError("ordering algorithm '" + algorithm +
                     "' makes no strips: expected a strip algorithm (strip, greedy)");
  }
  return ordering;
}

std::vector<std::vector<std::uint32_t>> skip_strip_offsets(const ProgressiveMesh& pm,
                                                           std::span<const std::uint32_t> list, std::uint32_t first,
                                                           std::uint32_t end) {
  const std::size_t vertex_count = pm.vertex_order.size();
  std::vector<std::vector<std::uint32_t>> positions(vertex_count);
  for (std::size_t i = 0; i < list.size(); ++i)
    if (list[i] < vertex_count) positions[list[i]].push_back(static_cast<std::uint32_t>(i));
  std::vector<std::vector<std::uint32_t>> offsets;
  for (std::uint32_t n = first; n < end; ++n) {
    const CollapseRecord& c = pm.collapses[n];
    offsets.push_back(std::move(positions[c.binned]));
    positions[c.binned] = {};
    positions[c.kept].insert(positions[c.kept].end(), offsets.back().begin(), offsets.back().end());
  }
  return offsets;
}

std::unique_ptr<EditedIndexLists> assemble_levels(const std::string& method, const ProgressiveMesh& pm,
                                                  PrimitiveType primitive, bool two_triangle_counts,
                                                  bool keep_collapsed, std::vector<EditedLevel> levels,
                                                  const std::vector<LevelEdits>& edits, const VipmBuildParams& params) {
  const auto vertex_count = static_cast<std::uint32_t>(pm.vertex_order.size());
  std::size_t max_list = 0, max_count = 0;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    EditedLevel& level = levels[l];
    max_list = std::max(max_list, level.dynamic_start.size());
    if (keep_collapsed) level.dynamic_collapsed = level.dynamic_start;
    for (std::uint32_t i = 0; i < level.collapses; ++i) {
      const std::vector<std::uint32_t>& offsets = edits[l].offsets[i];
      max_count =
          std::max<std::size_t>({max_count, offsets.size(), edits[l].triangles[i], edits[l].dynamic_triangles[i]});
      if (keep_collapsed)
        for (std::uint32_t p : offsets) level.dynamic_collapsed[p] = pm.collapses[level.first_lod + i].kept;
    }
  }
  EditedListsSpec spec;
  spec.method = method;
  spec.static_type = spec.dynamic_type = primitive;
  spec.layout = choose_record_layout(vertex_count, max_list, max_count, two_triangle_counts);
  spec.vertex_count = vertex_count;
  spec.vertex_bytes = params.vertex_bytes;
  spec.index_bytes = vipm_index_bytes(vertex_count);
  for (std::size_t l = 0; l < levels.size(); ++l) {
    CollapseRecordStream stream(spec.layout);
    for (std::uint32_t i = 0; i < levels[l].collapses; ++i)
      stream.append(pm.collapses[levels[l].first_lod + i].kept, edits[l].triangles[i], edits[l].dynamic_triangles[i],
                    edits[l].offsets[i]);
    levels[l].records = stream.finish();
  }
  return std::make_unique<EditedIndexLists>(std::move(spec), std::move(levels));
}

}  // namespace lod_detail

std::unique_ptr<EditedIndexLists> build_skip_strips(const ProgressiveMesh& pm, const Mesh& vertices,
                                                    const LevelParams& level_params, const VipmBuildParams& params) {
  lod_detail::check_level_params(level_params);
  std::vector<EditedLevel> levels;
  std::vector<lod_detail::LevelEdits> edits;
  lod_detail::for_each_level(
      pm, level_params.new_level_fraction, [&](const TriangleReplay& replay, std::uint32_t first, std::uint32_t end) {
        std::vector<std::array<std::uint32_t, 3>> triangles;
        for (std::uint32_t t = 0; t < replay.alive(); ++t) triangles.push_back(replay.triangle(t));
        EditedLevel& level = levels.emplace_back();
        level.first_lod = first;
        level.collapses = end - first;
        level.dynamic_start = lod_detail::order_triangles(vertices, triangles, level_params.algorithm,
                                                          level_params.reorder, level_params.primitive)
                                  .indices;
        level.dynamic_triangles = static_cast<std::uint32_t>(triangles.size());
        lod_detail::LevelEdits& edit = edits.emplace_back();
        edit.offsets = lod_detail::skip_strip_offsets(pm, level.dynamic_start, first, end);
        edit.triangles.assign(level.collapses, 0);  // nothing falls off: binned triangles turn degenerate
        edit.dynamic_triangles.assign(level.collapses, 0);
      });
  const char* method =
      level_params.primitive == PrimitiveType::TriangleStrip ? "skip-strips-strip" : "skip-strips-list";
  return lod_detail::assemble_levels(method, pm, level_params.primitive, false, true, std::move(levels), edits, params);
}

}  // namespace rastrace
