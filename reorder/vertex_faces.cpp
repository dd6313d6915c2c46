#include "reorder/vertex_faces.h"

#include <string>

#include "core/error.h"

namespace rastrace {

MeshTopology build_vertex_faces(const Mesh& mesh) {
  // Only an error needs the name (a copy would allocate on every call).
  const auto name = [&] { return mesh.name.empty() ? std::string("mesh") : mesh.name; };
  if (mesh.indices.size() % 3 != 0)
    throw_in_file(name(), "index count " + std::to_string(mesh.indices.size()) + " is not a multiple of 3");
  if (mesh.vertex_count() >= kNoFace || mesh.face_count() >= kNoFace / 3)
    throw_in_file(name(), "mesh too large for 32-bit topology");
  MeshTopology t;
  t.vertex_count = static_cast<std::uint32_t>(mesh.vertex_count());
  t.face_count = static_cast<std::uint32_t>(mesh.face_count());
  const std::uint32_t V = t.vertex_count, F = t.face_count;
  const std::uint32_t* idx = mesh.indices.data();
  t.vertex_face_offsets.assign(std::size_t(V) + 1, 0);
  for (std::uint32_t f = 0; f < F; ++f) {
    const std::uint32_t a = idx[3 * f], b = idx[3 * f + 1], c = idx[3 * f + 2];
    if (a >= V || b >= V || c >= V) {
      const std::uint32_t bad = a >= V ? a : b >= V ? b : c;
      throw_in_file(name(), "face " + std::to_string(f) + ": vertex index " + std::to_string(bad) +
                              " >= vertex count " + std::to_string(V));
    }
    ++t.vertex_face_offsets[a + 1];
    if (b != a) ++t.vertex_face_offsets[b + 1];
    if (c != a && c != b) ++t.vertex_face_offsets[c + 1];
  }
  for (std::uint32_t v = 0; v < V; ++v) t.vertex_face_offsets[v + 1] += t.vertex_face_offsets[v];
  t.vertex_faces.resize(t.vertex_face_offsets[V]);
  // Fill through offsets[v + 1] used as vertex v's cursor (it starts at v's first slot, i.e.
  // offsets[v] before the shift), so no cursor array is needed; afterwards offsets[v + 1] is v's
  // end, which is what it must be.
  std::uint32_t* cursor = t.vertex_face_offsets.data();
  for (std::uint32_t v = V; v > 0; --v) cursor[v] = cursor[v - 1];
  for (std::uint32_t f = 0; f < F; ++f) {
    const std::uint32_t a = idx[3 * f], b = idx[3 * f + 1], c = idx[3 * f + 2];
    t.vertex_faces[cursor[a + 1]++] = f;
    if (b != a) t.vertex_faces[cursor[b + 1]++] = f;
    if (c != a && c != b) t.vertex_faces[cursor[c + 1]++] = f;
  }
  return t;
}

}  // namespace rastrace
