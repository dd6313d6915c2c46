#include "lod/vanilla_numbering.h"

#include <algorithm>
#include <limits>
#include <string>

#include "core/error.h"

namespace rastrace {

namespace {

constexpr std::uint32_t kNever = std::numeric_limits<std::uint32_t>::max();

[[noreturn]] void bad_collapse(const Mesh& mesh, std::size_t n, const HalfEdgeCollapse& c, const std::string& what) {
  throw InputError(mesh.name + ": collapse " + std::to_string(n) + " (" + std::to_string(c.binned) + " -> " +
                   std::to_string(c.kept) + "): " + what);
}

}  // namespace

ProgressiveMesh progressive_mesh_from_collapses(const Mesh& mesh, std::span<const HalfEdgeCollapse> collapses) {
  const std::size_t vertex_count = mesh.vertex_count();
  const std::size_t face_count = mesh.face_count();
  if (mesh.indices.size() != 3 * face_count) throw InputError(mesh.name + ": index count is not a multiple of 3");
  std::vector<std::uint32_t> current = mesh.indices;
  std::vector<std::vector<std::uint32_t>> star(vertex_count);
  for (std::size_t f = 0; f < face_count; ++f) {
    const std::uint32_t* v = current.data() + 3 * f;
    for (int c = 0; c < 3; ++c)
      if (v[c] >= vertex_count)
        throw InputError(mesh.name + ": face " + std::to_string(f) + ": index " + std::to_string(v[c]) +
                         " >= vertex count " + std::to_string(vertex_count));
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
      throw InputError(mesh.name + ": face " + std::to_string(f) + " repeats a vertex");
    for (int c = 0; c < 3; ++c) star[v[c]].push_back(static_cast<std::uint32_t>(f));
  }

  // Replay the collapses in the mesh's own numbering.
  std::vector<std::uint32_t> binned_at(face_count, kNever);
  std::vector<std::uint8_t> vertex_binned(vertex_count, 0);
  struct Step {
    std::vector<std::uint32_t> binned_faces;
    std::vector<std::uint32_t> changed_faces;  // with the corner: 3 * face + corner
  };
  std::vector<Step> steps(collapses.size());
  for (std::size_t n = 0; n < collapses.size(); ++n) {
    const HalfEdgeCollapse& c = collapses[n];
    if (c.binned >= vertex_count || c.kept >= vertex_count) bad_collapse(mesh, n, c, "vertex out of range");
    if (c.binned == c.kept) bad_collapse(mesh, n, c, "a vertex cannot collapse onto itself");
    if (vertex_binned[c.binned] || vertex_binned[c.kept]) bad_collapse(mesh, n, c, "vertex already binned");
    Step& step = steps[n];
    for (std::uint32_t f : star[c.binned]) {
      if (binned_at[f] != kNever) continue;
      const std::uint32_t* v = current.data() + 3 * std::size_t(f);
      if (v[0] == c.kept || v[1] == c.kept || v[2] == c.kept) {
        step.binned_faces.push_back(f);
      } else {
        const std::uint32_t corner = v[0] == c.binned ? 0 : (v[1] == c.binned ? 1 : 2);
        step.changed_faces.push_back(3 * f + corner);
      }
    }
    if (step.binned_faces.empty()) bad_collapse(mesh, n, c, "the two vertices share no edge of the current mesh");
    for (std::uint32_t f : step.binned_faces) binned_at[f] = static_cast<std::uint32_t>(n);
    for (std::uint32_t corner : step.changed_faces) {
      current[corner] = c.kept;
      star[c.kept].push_back(corner / 3);
    }
    star[c.binned].clear();
    vertex_binned[c.binned] = 1;
  }

  // Vanilla numbering: survivors first in original order, then the binned ones, last binned first.
  ProgressiveMesh pm;
  pm.name = mesh.name;
  std::vector<std::uint8_t> used(vertex_count, 0);
  for (std::uint32_t v : mesh.indices) used[v] = 1;
  std::vector<std::uint32_t> new_vertex(vertex_count, kNever);
  for (std::size_t v = 0; v < vertex_count; ++v)
    if (used[v] && !vertex_binned[v]) {
      new_vertex[v] = static_cast<std::uint32_t>(pm.vertex_order.size());
      pm.vertex_order.push_back(static_cast<std::uint32_t>(v));
    }
  for (std::size_t n = collapses.size(); n-- > 0;) {
    new_vertex[collapses[n].binned] = static_cast<std::uint32_t>(pm.vertex_order.size());
    pm.vertex_order.push_back(collapses[n].binned);
  }
  std::vector<std::uint32_t> new_face(face_count, kNever);
  for (std::size_t f = 0; f < face_count; ++f)
    if (binned_at[f] == kNever) {
      new_face[f] = static_cast<std::uint32_t>(pm.triangle_origin.size());
      pm.triangle_origin.push_back(static_cast<std::uint32_t>(f));
    }
  const auto survivors = static_cast<std::uint32_t>(pm.triangle_origin.size());
  for (std::size_t n = collapses.size(); n-- > 0;) {
    std::vector<std::uint32_t>& faces = steps[n].binned_faces;
    std::sort(faces.begin(), faces.end());
    for (std::uint32_t f : faces) {
      new_face[f] = static_cast<std::uint32_t>(pm.triangle_origin.size());
      pm.triangle_origin.push_back(f);
    }
  }
  pm.triangles.resize(face_count);
  for (std::size_t t = 0; t < face_count; ++t) {
    const std::uint32_t f = pm.triangle_origin[t];
    for (int c = 0; c < 3; ++c) pm.triangles[t][c] = new_vertex[mesh.indices[3 * f + c]];
  }
  pm.collapses.resize(collapses.size());
  for (std::size_t n = 0; n < collapses.size(); ++n) {
    CollapseRecord& record = pm.collapses[n];
    record.kept = new_vertex[collapses[n].kept];
    record.binned = new_vertex[collapses[n].binned];
    record.error = collapses[n].error;
    for (std::uint32_t f : steps[n].binned_faces) record.binned_triangles.push_back(new_face[f]);
    std::sort(record.binned_triangles.begin(), record.binned_triangles.end());
    std::vector<std::uint32_t> corners;
    for (std::uint32_t corner : steps[n].changed_faces) corners.push_back(3 * new_face[corner / 3] + corner % 3);
    std::sort(corners.begin(), corners.end());
    for (std::uint32_t corner : corners) {
      record.changed_triangles.push_back(corner / 3);
      record.changed_corners.push_back(corner);
    }
  }
  pm.triangle_counts.assign(collapses.size() + 1, survivors);
  for (std::size_t n = collapses.size(); n-- > 0;)
    pm.triangle_counts[n] =
        pm.triangle_counts[n + 1] + static_cast<std::uint32_t>(pm.collapses[n].binned_triangles.size());
  return pm;
}

std::vector<HalfEdgeCollapse> collapses_of(const ProgressiveMesh& pm) {
  std::vector<HalfEdgeCollapse> out;
  out.reserve(pm.collapses.size());
  for (const CollapseRecord& c : pm.collapses) out.push_back({c.binned, c.kept, c.error});
  return out;
}

void TriangleReplay::advance_to(std::uint32_t n) {
  for (; lod_ < n; ++lod_) {
    const CollapseRecord& c = pm_->collapses[lod_];
    for (std::uint32_t corner : c.changed_corners) triangles_[corner / 3][corner % 3] = c.kept;
  }
}

Mesh triangles_as_mesh(const ProgressiveMesh& pm, const Mesh& vertices) {
  Mesh mesh;
  mesh.name = pm.name;
  mesh.positions = vertices.positions;
  mesh.positions.resize(pm.vertex_order.size());
  mesh.indices.reserve(3 * pm.triangles.size());
  for (const auto& t : pm.triangles) mesh.indices.insert(mesh.indices.end(), t.begin(), t.end());
  return mesh;
}

}  // namespace rastrace
