#include "reorder/adjacency/build.h"

namespace rastrace {

AdjacencyBuild build_adjacency_primitives(const Mesh& mesh, const CoverParams& params) {
  AdjacencyBuild build;
  build.dual = build_adjacency_dual(mesh);
  build.cover = find_adjacency_cover(build.dual, params);
  build.assignment = assign_uncovered_faces(build.dual, build.cover.in_cover);
  build.primitives = encode_adjacency_primitives(mesh, build.dual, build.cover.in_cover, build.assignment);
  return build;
}

}  // namespace rastrace
