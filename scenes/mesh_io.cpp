#include "scenes/mesh_io.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include <assimp/Importer.hpp>

#include "core/error.h"

namespace rastrace {

namespace {

std::string lower_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace

Mesh load_mesh(const std::string& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".off") return load_off(path);
  if (extension == ".ply") return load_ply(path);
  if (extension == ".obj") return load_obj(path);
  if (!extension.empty() && Assimp::Importer().IsExtensionSupported(extension)) return load_with_assimp(path);
  throw_in_file(path, "unknown mesh format " +
                          (extension.empty() ? std::string("(no extension)") : "'" + extension + "'") +
                          ": expected .off, .ply, .obj or a format assimp reads (.gltf, .glb, .dae, .fbx, .3ds, ...)");
}

void save_mesh(const Mesh& mesh, const std::string& path, const MeshWriteOptions& options) {
  for (const std::uint32_t index : mesh.indices)
    if (index >= mesh.vertex_count())
      throw_in_file(path, "cannot write: index " + std::to_string(index) + " >= vertex count " +
                              std::to_string(mesh.vertex_count()));
  const std::string extension = lower_extension(path);
  if (extension == ".off") return save_off(mesh, path);
  if (extension == ".ply") return save_ply(mesh, path, options.ascii);
  if (extension == ".obj") return save_obj(mesh, path);
  throw_in_file(path, "cannot write format " +
                          (extension.empty() ? std::string("(no extension)") : "'" + extension + "'") +
                          ": expected .off, .ply or .obj");
}

}  // namespace rastrace
