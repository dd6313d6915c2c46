#include "experiments/meshlet_file.h"

#include <nlohmann/json.hpp>

#include <ostream>

#include "core/atomic_file.h"

namespace rastrace {

namespace {

void put_u32(std::ostream& out, std::uint32_t value) {
  const char bytes[4] = {static_cast<char>(value & 0xFF), static_cast<char>((value >> 8) & 0xFF),
                         static_cast<char>((value >> 16) & 0xFF), static_cast<char>((value >> 24) & 0xFF)};
  out.write(bytes, 4);
}

void write_binary(std::ostream& out, const MeshletSet& set, const MeshletLimits& limits) {
  out.write("RTMSHLT", 8);  // the terminating zero is the eighth byte
  for (const std::size_t value : {std::size_t{1}, std::size_t{limits.max_vertices}, std::size_t{limits.max_triangles},
                                  set.meshlets.size(), set.vertices.size(), set.triangle_count()})
    put_u32(out, static_cast<std::uint32_t>(value));
  for (const Meshlet& m : set.meshlets)
    for (const std::uint32_t value : {m.vertex_offset, m.triangle_offset, m.vertex_count, m.triangle_count})
      put_u32(out, value);
  for (const std::uint32_t vertex : set.vertices) put_u32(out, vertex);
  out.write(reinterpret_cast<const char*>(set.triangles.data()), static_cast<std::streamsize>(set.triangles.size()));
}

nlohmann::json to_json(const MeshletSet& set, const MeshletFileInfo& info) {
  nlohmann::json meshlets = nlohmann::json::array();
  for (const Meshlet& m : set.meshlets) {
    const auto vertices = set.vertices.begin() + m.vertex_offset;
    const auto corners = set.triangles.begin() + 3 * std::ptrdiff_t{m.triangle_offset};
    meshlets.push_back({{"vertices", std::vector<std::uint32_t>(vertices, vertices + m.vertex_count)},
                        {"triangles", std::vector<std::uint32_t>(corners, corners + 3 * std::ptrdiff_t{m.triangle_count})}});
  }
  return {{"format", "rastrace-meshlets"},
          {"version", 1},
          {"mesh", info.mesh},
          {"order", info.order},
          {"builder", info.builder},
          {"max_vertices", info.limits.max_vertices},
          {"max_triangles", info.limits.max_triangles},
          {"meshlets", std::move(meshlets)}};
}

}  // namespace

void write_meshlets(const std::string& path, const MeshletSet& set, const MeshletFileInfo& info) {
  const bool json = path.size() >= 5 && path.compare(path.size() - 5, 5, ".json") == 0;
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        if (json)
          out << to_json(set, info).dump() << "\n";
        else
          write_binary(out, set, info.limits);
      },
      !json);
}

}  // namespace rastrace
