// Mixed-mode VIPM (Forsyth, "Comparison of VIPM Methods", 2001), as lists and as strips. Per
// level (the levels of skip_strips.h) the triangles fall into four lists: (1) not affected by
// the level's collapses, (2) binned without being modified first, (3) modified and not binned,
// (4) modified, then binned.
//   lists:  a static buffer shared by all instances, list 1 in vertex-cache order then list 2 in
//           reverse bin order (binned triangles fall off its end), and a per-instance dynamic
//           buffer, list 3 in vertex-cache order then list 4 in reverse bin order, edited by
//           vanilla's records with two triangle counts (static, dynamic);
//   strips: list 1 stripified as the static buffer, lists 2, 3 and 4 stripified together as a
//           per-instance skip strip (binning makes triangles degenerate).
// Two draws per frame: the dynamic buffer, then the static one.
#pragma once

#include <memory>

#include "lod/skip_strips.h"

namespace rastrace {

std::unique_ptr<EditedIndexLists> build_mixed_mode(const ProgressiveMesh& pm, const Mesh& vertices,
                                                   const LevelParams& level, const VipmBuildParams& params = {});

}  // namespace rastrace
