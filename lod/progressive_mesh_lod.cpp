// Reading a progressive mesh at a level of detail: the reference triangle set, the reordered
// full-detail buffers, and vanilla VIPM's in-place collapse and split of an index buffer
// (Forsyth, "Comparison of VIPM Methods", 2001).
#include <algorithm>

#include "lod/progressive_mesh.h"

namespace rastrace {

std::size_t ProgressiveMesh::lod_for_triangle_count(std::uint32_t triangles) const {
  // triangle_counts never increases, so the first LoD at or below the count is a binary search.
  const auto it = std::lower_bound(triangle_counts.begin(), triangle_counts.end(), triangles,
                                   [](std::uint32_t count, std::uint32_t wanted) { return count > wanted; });
  return it == triangle_counts.end() ? collapses.size() : std::size_t(it - triangle_counts.begin());
}

Mesh reordered_mesh(const Mesh& mesh, const ProgressiveMesh& pm) {
  Mesh out;
  out.name = mesh.name;
  out.materials = mesh.materials;
  out.positions.reserve(pm.vertex_order.size());
  for (const std::uint32_t v : pm.vertex_order) {
    out.positions.push_back(mesh.positions[v]);
    if (!mesh.normals.empty()) out.normals.push_back(mesh.normals[v]);
    if (!mesh.uvs.empty()) out.uvs.push_back(mesh.uvs[v]);
  }
  out.indices.reserve(3 * pm.triangles.size());
  for (std::size_t t = 0; t < pm.triangles.size(); ++t) {
    out.indices.insert(out.indices.end(), pm.triangles[t].begin(), pm.triangles[t].end());
    if (!mesh.face_material.empty()) out.face_material.push_back(mesh.face_material[pm.triangle_origin[t]]);
  }
  return out;
}

std::vector<std::array<std::uint32_t, 3>> triangles_at_lod(const ProgressiveMesh& pm, std::size_t n) {
  n = std::min(n, pm.collapses.size());
  // final[v]: where vertex v ends after the first n collapses. Going backwards, the kept vertex
  // of collapse i already knows its own destination (later collapses may bin it too).
  std::vector<std::uint32_t> final(pm.vertex_order.size());
  for (std::uint32_t v = 0; v < final.size(); ++v) final[v] = v;
  for (std::size_t i = n; i-- > 0;) final[pm.collapses[i].binned] = final[pm.collapses[i].kept];
  std::vector<std::array<std::uint32_t, 3>> out;
  for (const auto& t : pm.triangles) {
    const std::array<std::uint32_t, 3> m{final[t[0]], final[t[1]], final[t[2]]};
    if (m[0] != m[1] && m[1] != m[2] && m[0] != m[2]) out.push_back(m);
  }
  return out;
}

ProgressiveMeshCursor::ProgressiveMeshCursor(const ProgressiveMesh& pm) : pm_(&pm) {
  indices_.reserve(3 * pm.triangles.size());
  for (const auto& t : pm.triangles) indices_.insert(indices_.end(), t.begin(), t.end());
}

bool ProgressiveMeshCursor::collapse() {
  if (lod_ >= pm_->collapses.size()) return false;
  const CollapseRecord& c = pm_->collapses[lod_++];
  for (const std::uint32_t corner : c.changed_corners) indices_[corner] = c.kept;
  return true;
}

bool ProgressiveMeshCursor::split() {
  if (lod_ == 0) return false;
  const CollapseRecord& c = pm_->collapses[--lod_];
  for (const std::uint32_t corner : c.changed_corners) indices_[corner] = c.binned;
  return true;
}

void ProgressiveMeshCursor::set_lod(std::size_t n) {
  n = std::min(n, pm_->collapses.size());
  while (lod_ < n) collapse();
  while (lod_ > n) split();
}

}  // namespace rastrace
