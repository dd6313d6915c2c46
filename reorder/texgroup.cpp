#include "reorder/texgroup.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "core/error.h"
#include "reorder/mesh_topology.h"

namespace rastrace {

namespace {

std::string texture_key(const Material& material) {
  const TextureSource& source = material.texture_source;
  switch (source.kind) {
    case TextureSource::Kind::None:
      return "untextured";
    case TextureSource::Kind::File:
      return source.path;
    case TextureSource::Kind::Checker:
      return "checker " + std::to_string(source.size) + "/" + std::to_string(source.checks);
    case TextureSource::Kind::FourColour:
      return "four-colour " + std::to_string(source.size);
    case TextureSource::Kind::Gradient:
      return "gradient " + std::to_string(source.size);
  }
  return "untextured";
}

const Material* material_of_face(const Mesh& mesh, std::size_t face) {
  const std::uint32_t id = mesh.material_of(face);
  return id < mesh.materials.size() ? &mesh.materials[id] : nullptr;
}

std::uint32_t uv_quadrant(const Mesh& mesh, std::size_t face) {
  if (mesh.uvs.empty()) return 0;
  glm::vec2 centroid(0.0f);
  for (int i = 0; i < 3; ++i) centroid += mesh.uvs[mesh.indices[3 * face + i]];
  centroid /= 3.0f;
  // REPEAT wrapping: the quadrant of the texture actually sampled.
  const float u = centroid.x - std::floor(centroid.x), v = centroid.y - std::floor(centroid.y);
  return (v >= 0.5f ? 2u : 0u) + (u >= 0.5f ? 1u : 0u);
}

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Faces edge-connected within the same texture; labels are the smallest face id of each chart.
std::vector<std::uint32_t> uv_charts(const Mesh& mesh, const std::vector<std::uint32_t>& texture_of_face) {
  const MeshTopology topology = build_mesh_topology(mesh);
  UnionFind charts(mesh.face_count());
  for (std::uint32_t e = 0; e < topology.edge_count(); ++e) {
    const auto faces = topology.faces_of_edge(e);
    for (std::size_t i = 1; i < faces.size(); ++i)
      if (texture_of_face[faces[i]] == texture_of_face[faces[0]]) charts.unite(faces[0], faces[i]);
  }
  std::vector<std::uint32_t> chart(mesh.face_count());
  for (std::uint32_t f = 0; f < chart.size(); ++f) chart[f] = charts.find(f);
  return chart;
}

// Appends one group's strip to the stream after a restart. 0xFFFFFFFF is GL's fixed restart
// index for 32-bit indices and never a vertex id, so every strip stream can use it.
void append_strip(Ordering& out, const Ordering& group) {
  if (group.indices.empty()) return;
  if (!out.indices.empty()) out.indices.push_back(group.restart_index.value_or(kStripRestart));
  out.indices.insert(out.indices.end(), group.indices.begin(), group.indices.end());
}

}  // namespace

TextureGroups find_texture_groups(const Mesh& mesh, const std::string& mode) {
  if (mode != "auto" && mode != "quadrant" && mode != "chart" && mode != "texture")
    throw InputError("unknown texture region mode '" + mode + "': expected auto, quadrant, chart or texture");
  const std::size_t faces = mesh.face_count();

  // Textures numbered by first appearance.
  std::map<std::string, std::uint32_t> texture_ids;
  std::vector<std::string> texture_names;
  std::vector<bool> texture_is_four_colour;
  std::vector<std::uint32_t> texture_of_face(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    const Material* material = material_of_face(mesh, f);
    const std::string key = material ? texture_key(*material) : "untextured";
    const auto [it, added] = texture_ids.emplace(key, static_cast<std::uint32_t>(texture_names.size()));
    if (added) {
      texture_names.push_back(key);
      texture_is_four_colour.push_back(material && material->texture_source.kind == TextureSource::Kind::FourColour);
    }
    texture_of_face[f] = it->second;
  }

  // Region within the texture.
  std::vector<std::uint32_t> region(faces, 0);
  std::vector<std::uint32_t> chart;
  for (std::size_t f = 0; f < faces; ++f) {
    const bool quadrant = mode == "quadrant" || (mode == "auto" && texture_is_four_colour[texture_of_face[f]]);
    if (quadrant) {
      region[f] = uv_quadrant(mesh, f);
    } else if (mode != "texture") {
      if (chart.empty()) chart = uv_charts(mesh, texture_of_face);
      region[f] = chart[f];
    }
  }

  // Groups numbered by first appearance of (texture, region).
  TextureGroups groups;
  groups.group_of_face.resize(faces);
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> group_ids;
  std::vector<std::uint32_t> texture_of_group;
  for (std::size_t f = 0; f < faces; ++f) {
    const auto [it, added] = group_ids.emplace(std::make_pair(texture_of_face[f], region[f]),
                                               static_cast<std::uint32_t>(groups.labels.size()));
    if (added) {
      const bool quadrant = mode == "quadrant" || (mode == "auto" && texture_is_four_colour[texture_of_face[f]]);
      std::string label = texture_names[texture_of_face[f]];
      if (mode != "texture")
        label += (quadrant ? " quadrant " : " chart ") + std::to_string(quadrant ? region[f] : it->second);
      groups.labels.push_back(label);
      texture_of_group.push_back(texture_of_face[f]);
    }
    groups.group_of_face[f] = it->second;
  }
  const std::size_t group_count = groups.labels.size();

  // Vertices shared between groups, to chain neighbouring groups.
  std::vector<std::vector<std::uint32_t>> groups_of_vertex(mesh.vertex_count());
  for (std::size_t f = 0; f < faces; ++f)
    for (int i = 0; i < 3; ++i) {
      auto& list = groups_of_vertex[mesh.indices[3 * f + i]];
      const std::uint32_t g = groups.group_of_face[f];
      if (std::find(list.begin(), list.end(), g) == list.end()) list.push_back(g);
    }
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> shared;
  for (const auto& list : groups_of_vertex)
    for (std::size_t i = 0; i < list.size(); ++i)
      for (std::size_t j = 0; j < list.size(); ++j)
        if (i != j) ++shared[{list[i], list[j]}];

  // Groups are numbered by first appearance, so within a texture the lowest unvisited id is the
  // region of the earliest remaining face.
  std::vector<bool> drawn(group_count, false);
  for (std::uint32_t texture = 0; texture < texture_names.size(); ++texture) {
    std::uint32_t current = kNoFace;
    for (;;) {
      std::uint32_t next = kNoFace, best_shared = 0;
      for (std::uint32_t g = 0; g < group_count; ++g) {
        if (drawn[g] || texture_of_group[g] != texture) continue;
        const auto it = current == kNoFace ? shared.end() : shared.find({current, g});
        const std::uint32_t count = it == shared.end() ? 0 : it->second;
        if (next == kNoFace || count > best_shared) {
          next = g;
          best_shared = count;
        }
      }
      if (next == kNoFace) break;
      drawn[next] = true;
      groups.order.push_back(next);
      current = next;
    }
  }
  return groups;
}

Ordering reorder_texgroup(const Mesh& mesh, const ReorderParams& params) {
  if (params.texgroup_base == "texgroup") throw InputError("texgroup cannot be its own base algorithm");
  const ReorderAlgorithm& base = find_reorder_algorithm(params.texgroup_base);
  const TextureGroups groups = find_texture_groups(mesh, params.texgroup_regions);

  std::vector<std::vector<std::uint32_t>> faces_of_group(groups.labels.size());
  for (std::uint32_t f = 0; f < groups.group_of_face.size(); ++f) faces_of_group[groups.group_of_face[f]].push_back(f);

  Ordering result;
  bool first = true;
  std::vector<std::uint32_t> local_of_vertex(mesh.vertex_count(), kNoFace);
  for (const std::uint32_t g : groups.order) {
    // The group as a compact mesh (local vertex ids by first use), ordered by the base algorithm.
    Mesh part;
    part.name = mesh.name;
    std::vector<std::uint32_t> global_of_local;
    for (const std::uint32_t f : faces_of_group[g]) {
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t v = mesh.indices[3 * f + i];
        if (local_of_vertex[v] == kNoFace) {
          local_of_vertex[v] = static_cast<std::uint32_t>(global_of_local.size());
          global_of_local.push_back(v);
          part.positions.push_back(mesh.positions[v]);
          if (!mesh.uvs.empty()) part.uvs.push_back(mesh.uvs[v]);
          if (!mesh.normals.empty()) part.normals.push_back(mesh.normals[v]);
        }
        part.indices.push_back(local_of_vertex[v]);
      }
    }
    Ordering ordered = base.run(part, params);
    for (std::uint32_t& index : ordered.indices)
      if (!is_restart(ordered.type, ordered.restart_index, index)) index = global_of_local[index];
    for (const std::uint32_t v : global_of_local) local_of_vertex[v] = kNoFace;

    if (first) {
      result.type = ordered.type;
      // The groups' strips are joined with restarts, so the result restarts even if a group's does not.
      if (ordered.type == PrimitiveType::TriangleStrip)
        result.restart_index = ordered.restart_index.value_or(kStripRestart);
      first = false;
    }
    for (const std::uint32_t local_face : ordered.face_order)
      result.face_order.push_back(faces_of_group[g][local_face]);
    if (ordered.type == PrimitiveType::TriangleStrip)
      append_strip(result, ordered);
    else
      result.indices.insert(result.indices.end(), ordered.indices.begin(), ordered.indices.end());
  }
  return result;
}

}  // namespace rastrace
