#include "lod/progressive_mesh_input.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.h"

namespace rastrace::lod_detail {
namespace {

std::uint64_t edge_key(std::uint32_t from, std::uint32_t to) { return (std::uint64_t(from) << 32) | to; }

[[noreturn]] void fail(const Mesh& mesh, const std::string& what) {
  throw InputError("mesh '" + mesh.name + "': " + what + " (a progressive mesh needs a consistently oriented " +
                   "two-manifold triangle mesh)");
}

}  // namespace

void check_manifold_input(const Mesh& mesh) {
  if (mesh.indices.size() % 3 != 0)
    fail(mesh, "index count " + std::to_string(mesh.indices.size()) + " is not a multiple of 3");
  const std::size_t faces = mesh.face_count();
  if (faces == 0) fail(mesh, "no triangles");
  const std::size_t vertices = mesh.vertex_count();
  if (faces >= 0xFFFFFFFFu / 3 || vertices >= 0xFFFFFFFFu)
    fail(mesh, "too large for 32-bit vertex and index numbering");

  // Directed edges (from -> to) with their face, sorted: each may occur once (a second face with
  // the same direction is a winding flip or a third face on the edge).
  std::vector<std::pair<std::uint64_t, std::uint32_t>> directed;
  directed.reserve(3 * faces);
  std::vector<std::uint32_t> valence(vertices, 0);
  for (std::size_t f = 0; f < faces; ++f) {
    const std::uint32_t* v = mesh.indices.data() + 3 * f;
    for (int i = 0; i < 3; ++i)
      if (v[i] >= vertices)
        fail(mesh, "face " + std::to_string(f) + ": vertex index " + std::to_string(v[i]) + " >= vertex count " +
                       std::to_string(vertices));
    for (int i = 0; i < 3; ++i) {
      const glm::vec3& p = mesh.positions[v[i]];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        fail(mesh, "face " + std::to_string(f) + ": vertex " + std::to_string(v[i]) + " has a non-finite position");
    }
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
      fail(mesh, "face " + std::to_string(f) + " repeats a vertex (" + std::to_string(v[0]) + " " +
                     std::to_string(v[1]) + " " + std::to_string(v[2]) + ")");
    for (int i = 0; i < 3; ++i) {
      directed.emplace_back(edge_key(v[i], v[(i + 1) % 3]), static_cast<std::uint32_t>(f));
      ++valence[v[i]];
    }
  }
  std::sort(directed.begin(), directed.end());
  for (std::size_t i = 1; i < directed.size(); ++i)
    if (directed[i].first == directed[i - 1].first) {
      const auto from = std::uint32_t(directed[i].first >> 32), to = std::uint32_t(directed[i].first);
      fail(mesh, "faces " + std::to_string(directed[i - 1].second) + " and " + std::to_string(directed[i].second) +
                     " both run edge " + std::to_string(from) + " -> " + std::to_string(to) +
                     " (a non-manifold edge or inconsistent winding)");
    }
  auto face_with = [&](std::uint32_t from, std::uint32_t to) -> std::int64_t {
    const auto it = std::lower_bound(directed.begin(), directed.end(), std::make_pair(edge_key(from, to), 0u));
    return it != directed.end() && it->first == edge_key(from, to) ? std::int64_t(it->second) : -1;
  };
  // The vertex after and before `v` in face f.
  auto next_of = [&](std::uint32_t f, std::uint32_t v) {
    const std::uint32_t* t = mesh.indices.data() + 3 * std::size_t(f);
    return t[0] == v ? t[1] : t[1] == v ? t[2] : t[0];
  };
  auto prev_of = [&](std::uint32_t f, std::uint32_t v) {
    const std::uint32_t* t = mesh.indices.data() + 3 * std::size_t(f);
    return t[0] == v ? t[2] : t[1] == v ? t[0] : t[1];
  };

  // Every vertex's faces must form one fan: walk around it from one face in both directions and
  // count the faces reached.
  std::vector<std::uint8_t> checked(vertices, 0);
  for (std::size_t f = 0; f < faces; ++f) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = mesh.indices[3 * f + i];
      if (checked[v]) continue;
      checked[v] = 1;
      std::uint32_t reached = 1;
      bool closed = false;
      // Counter-clockwise: the face across edge (v, next) runs next -> v.
      for (std::int64_t g = face_with(next_of(std::uint32_t(f), v), v); g >= 0;
           g = face_with(next_of(std::uint32_t(g), v), v)) {
        if (g == std::int64_t(f)) {
          closed = true;
          break;
        }
        if (++reached > valence[v]) break;
      }
      if (!closed)
        for (std::int64_t g = face_with(v, prev_of(std::uint32_t(f), v)); g >= 0 && reached <= valence[v];
             g = face_with(v, prev_of(std::uint32_t(g), v)))
          ++reached;
      if (reached != valence[v])
        fail(mesh, "vertex " + std::to_string(v) + ": its " + std::to_string(valence[v]) +
                       " faces do not form a single fan (a non-manifold vertex)");
    }
  }
}

}  // namespace rastrace::lod_detail
