#include "reorder/meshlets/meshlet.h"

#include <string>

#include "core/error.h"

namespace rastrace {

void validate(const MeshletLimits& limits) {
  if (limits.max_vertices < 3 || limits.max_vertices > kMeshletMaxVertices)
    throw InputError("--max-vertices " + std::to_string(limits.max_vertices) + ": expected 3 to " +
                     std::to_string(kMeshletMaxVertices) + " (a meshlet's vertices are 8-bit local indices)");
  if (limits.max_triangles < 1 || limits.max_triangles > kMeshletMaxTriangles)
    throw InputError("--max-triangles " + std::to_string(limits.max_triangles) + ": expected 1 to " +
                     std::to_string(kMeshletMaxTriangles));
}

void validate_triangle_list(std::span<const std::uint32_t> triangles, std::size_t vertex_count) {
  if (triangles.size() % 3 != 0)
    throw InputError("meshlets: " + std::to_string(triangles.size()) + " indices is not a whole number of triangles");
  for (std::size_t i = 0; i < triangles.size(); ++i)
    if (triangles[i] >= vertex_count)
      throw InputError("meshlets: index " + std::to_string(i) + " is vertex " + std::to_string(triangles[i]) +
                       ", >= vertex count " + std::to_string(vertex_count));
}

MeshletAccumulator::MeshletAccumulator(std::size_t vertex_count, const MeshletLimits& limits)
    : limits_(limits), local_(vertex_count, kAbsent) {
  validate(limits);
}

std::uint32_t MeshletAccumulator::new_vertices(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
  return (local_[a] == kAbsent) + (local_[b] == kAbsent && b != a) + (local_[c] == kAbsent && c != a && c != b);
}

std::uint8_t MeshletAccumulator::local(std::uint32_t vertex) {
  if (local_[vertex] == kAbsent) {
    local_[vertex] = static_cast<std::uint16_t>(open_.vertex_count++);
    set_.vertices.push_back(vertex);
  }
  return static_cast<std::uint8_t>(local_[vertex]);
}

void MeshletAccumulator::append(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const std::uint8_t la = local(a), lb = local(b), lc = local(c);
  set_.triangles.insert(set_.triangles.end(), {la, lb, lc});
  ++open_.triangle_count;
}

void MeshletAccumulator::close() {
  if (open_.triangle_count == 0) return;
  for (const std::uint32_t vertex : open_vertices()) local_[vertex] = kAbsent;
  set_.meshlets.push_back(open_);
  open_.vertex_offset += open_.vertex_count;
  open_.triangle_offset += open_.triangle_count;
  open_.vertex_count = 0;
  open_.triangle_count = 0;
}

MeshletSet MeshletAccumulator::finish() {
  close();
  return std::move(set_);
}

}  // namespace rastrace
