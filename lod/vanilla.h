// Vanilla VIPM (Forsyth, "Comparison of VIPM Methods", 2001; the Direct3DX8 method): one index
// list per instance, triangles from last binned to first binned, so binned triangles fall off its
// end; collapse records rewrite the indices of the changed triangles (VanillaCollapseRecord,
// vanilla_records.h). The global data are the vertex buffer, the full-detail list instances are
// copied from, and the records. One draw.
#pragma once

#include <cstdint>
#include <memory>

#include "lod/progressive_mesh.h"
#include "lod/vanilla_instance.h"

namespace rastrace {

struct VipmBuildParams {
  std::uint32_t vertex_bytes = 32;  // vertex buffer stride (DESIGN's default vertex size)
};

std::unique_ptr<EditedIndexLists> build_vanilla(const ProgressiveMesh& pm, const VipmBuildParams& params = {});

}  // namespace rastrace
