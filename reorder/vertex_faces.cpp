#include "reorder/vertex_faces.h"

#include <memory>
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
  // The count pass records each corner's rank among its vertex's faces (the count before it),
  // so the fill is offsets[v] + rank with no read-modify-write of a per-vertex cursor: on a mesh
  // stored in a good order consecutive faces share vertices, and such updates of one counter
  // wait for each other. A degenerate face's repeated corner gets no rank (kNoFace).
  t.vertex_face_offsets.assign(std::size_t(V) + 1, 0);
  std::uint32_t* const counts = t.vertex_face_offsets.data() + 1;
  const std::unique_ptr<std::uint32_t[]> rank = std::make_unique_for_overwrite<std::uint32_t[]>(3 * std::size_t(F));
  for (std::uint32_t f = 0; f < F; ++f) {
    const std::uint32_t a = idx[3 * std::size_t(f)], b = idx[3 * std::size_t(f) + 1], c = idx[3 * std::size_t(f) + 2];
    if (a >= V || b >= V || c >= V) {
      const std::uint32_t bad = a >= V ? a : b >= V ? b : c;
      throw_in_file(name(), "face " + std::to_string(f) + ": vertex index " + std::to_string(bad) +
                                " >= vertex count " + std::to_string(V));
    }
    std::uint32_t* r = rank.get() + 3 * std::size_t(f);
    r[0] = counts[a]++;
    r[1] = b != a ? counts[b]++ : kNoFace;
    r[2] = c != a && c != b ? counts[c]++ : kNoFace;
  }
  std::uint32_t* const offsets = t.vertex_face_offsets.data();
  for (std::uint32_t v = 0; v < V; ++v) offsets[v + 1] += offsets[v];
  t.vertex_faces.resize(offsets[V]);
  std::uint32_t* const faces = t.vertex_faces.data();
  for (std::uint32_t f = 0; f < F; ++f) {
    const std::uint32_t* r = rank.get() + 3 * std::size_t(f);
    const std::uint32_t* v = idx + 3 * std::size_t(f);
    faces[offsets[v[0]] + r[0]] = f;
    if (r[1] != kNoFace) faces[offsets[v[1]] + r[1]] = f;
    if (r[2] != kNoFace) faces[offsets[v[2]] + r[2]] = f;
  }
  return t;
}

}  // namespace rastrace
