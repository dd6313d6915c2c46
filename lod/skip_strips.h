// Multilevel skip strips (Forsyth, "Comparison of VIPM Methods", 2001, after El-Sana et al.
// 1999), as strips and as lists: a collapse bins triangles by making them degenerate (every index
// holding the binned vertex gets the kept one, the degenerate triangles included), so triangles
// need not be in collapse order and each level is ordered for the vertex cache. A new level
// starts, with the degenerates thrown away and the triangles re-ordered, once the triangles binned
// inside the current level reach `new_level_fraction` of the level's triangles. Each level keeps
// its list as taken and fully collapsed (Forsyth's suggestion).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "lod/progressive_mesh.h"
#include "lod/vanilla.h"
#include "lod/vanilla_instance.h"
#include "lod/vanilla_numbering.h"
#include "reorder/ordering.h"
#include "scenes/mesh.h"

namespace rastrace {

struct LevelParams {
  PrimitiveType primitive = PrimitiveType::TriangleStrip;
  // The ordering of each level (reorder/ordering.h): a strip algorithm ("strip", "greedy") for
  // strips, a list one ("tipsy", "forsyth", ...) for lists.
  std::string algorithm = "greedy";
  ReorderParams reorder;
  // A new level starts when the triangles binned in the level reach this fraction of its triangles.
  double new_level_fraction = 0.5;
};

// `vertices`: the vertex buffer in the progressive mesh's numbering (reordered_mesh's result;
// only positions are read). Throws InputError for an unknown algorithm or a fraction outside (0, 1].
std::unique_ptr<EditedIndexLists> build_skip_strips(const ProgressiveMesh& pm, const Mesh& vertices,
                                                    const LevelParams& level, const VipmBuildParams& params = {});

// Shared by the multilevel methods.
namespace lod_detail {

void check_level_params(const LevelParams& level);
// The LoD at which the level that starts at `first_lod` with `triangles` triangles ends: after
// the first collapse at which the triangles binned since first_lod reach fraction * triangles
// (at least one collapse; the last LoD at most).
std::uint32_t level_end(const ProgressiveMesh& pm, std::uint32_t first_lod, std::uint32_t triangles, double fraction);
// Calls make_level(replay, first, end) for each level, in LoD order: replay holds the triangles
// at LoD `first`; the level's collapses are first .. end - 1 (level_end's rule).
void for_each_level(const ProgressiveMesh& pm, double fraction,
                    const std::function<void(const TriangleReplay&, std::uint32_t, std::uint32_t)>& make_level);
// The triangles ordered by `algorithm`, as its index stream (a list rebuilt from the face order,
// so that each triangle keeps its corner order) and its face order.
Ordering order_triangles(const Mesh& vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
                         const std::string& algorithm, const ReorderParams& params, PrimitiveType primitive);

// The skip-strip edit of collapses first .. end - 1 on `list`: per collapse, every position that
// holds its binned vertex by then (degenerate triangles included).
std::vector<std::vector<std::uint32_t>> skip_strip_offsets(const ProgressiveMesh& pm,
                                                           std::span<const std::uint32_t> list, std::uint32_t first,
                                                           std::uint32_t end);

// A level's collapse records before encoding: per collapse the triangles falling off the end of
// the (static or only) list and of the dynamic list, and the offsets to rewrite.
struct LevelEdits {
  std::vector<std::uint32_t> triangles, dynamic_triangles;
  std::vector<std::vector<std::uint32_t>> offsets;
};

// Encodes every level's records in the narrowest layout they fit, fills each level's collapsed
// copy when `keep_collapsed` and makes the representation.
std::unique_ptr<EditedIndexLists> assemble_levels(const std::string& method, const ProgressiveMesh& pm,
                                                  PrimitiveType primitive, bool two_triangle_counts,
                                                  bool keep_collapsed, std::vector<EditedLevel> levels,
                                                  const std::vector<LevelEdits>& edits, const VipmBuildParams& params);

}  // namespace lod_detail

}  // namespace rastrace
