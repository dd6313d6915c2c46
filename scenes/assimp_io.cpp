// Every format assimp reads (glTF, COLLADA, FBX, 3DS, ...), as one mesh: the scene graph's
// transforms baked in (aiProcess_PreTransformVertices), identical vertices joined
// (aiProcess_JoinIdenticalVertices), polygons triangulated, points and lines dropped. Meshes are
// appended in assimp's order; each keeps its material as the per-face material.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <new>
#include <string>

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include "core/error.h"
#include "core/input_guard.h"
#include "core/sanitizers.h"
#include "scenes/mesh_io.h"

namespace rastrace {

namespace {

namespace fs = std::filesystem;

// The diffuse (or glTF base colour) texture of a material: a file resolved beside the model, or
// an image embedded in the model ("*0", or a name the scene's embedded textures carry).
void read_texture(const std::string& path, const aiScene& scene, const aiMaterial& source, Material& material) {
  aiString texture;
  if (source.GetTexture(aiTextureType_DIFFUSE, 0, &texture) != AI_SUCCESS &&
      source.GetTexture(aiTextureType_BASE_COLOR, 0, &texture) != AI_SUCCESS)
    return;
  std::string name = texture.C_Str();
  if (name.empty()) return;
  if (const aiTexture* embedded = scene.GetEmbeddedTexture(name.c_str())) {
    if (embedded->mHeight != 0 || embedded->mWidth == 0)
      throw_in_file(path, "material '" + material.name + "': embedded texture " + name +
                              " holds raw texels; expected an encoded image (PNG, JPEG...)");
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(embedded->pcData);
    material.texture_source.kind = TextureSource::Kind::File;
    material.texture_source.embedded =
        std::make_shared<const std::vector<std::uint8_t>>(bytes, bytes + embedded->mWidth);
    // The format hint ("png", "jpg") gives the decoder; the name says where the image came from.
    std::string hint = embedded->achFormatHint;
    if (hint.empty() || hint.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789") != std::string::npos)
      hint = "png";
    material.texture_source.path = path + "#" + name + "." + hint;
    return;
  }
  if (name[0] == '*')
    throw_in_file(path, "material '" + material.name + "': embedded texture " + name + " not found in the file");
  for (char& c : name)
    if (c == '\\') c = '/';
  if (name.starts_with("file://")) name = name.substr(7);
  fs::path resolved = fs::path(name).is_absolute() ? fs::path(name) : fs::path(path).parent_path() / name;
  resolved = resolved.lexically_normal();
  std::error_code error;
  if (!fs::is_regular_file(resolved, error))
    throw_in_file(path, "material '" + material.name + "': texture file " + resolved.string() + " not found");
  material.texture_source.kind = TextureSource::Kind::File;
  material.texture_source.path = resolved.string();
}

constexpr unsigned kAssimpFlags = aiProcess_JoinIdenticalVertices | aiProcess_Triangulate | aiProcess_SortByPType |
                                  aiProcess_PreTransformVertices | aiProcess_ValidateDataStructure;
constexpr rlim_t kAssimpCpuSeconds = 120;
constexpr rlim_t kAssimpMemoryBytes = rlim_t{4} << 30;

// The child's CPU limit: 120 s, or RASTRACE_ASSIMP_CPU_SECONDS (whole seconds, 1 to 3600) when
// set. The fuzz harness sets 1: under AddressSanitizer assimp's allocations all go through ASan's
// allocator, and a mutated 3DS file that assimp refuses in 0.8 s took over 6 s there.
rlim_t assimp_cpu_seconds() {
  const char* text = std::getenv("RASTRACE_ASSIMP_CPU_SECONDS");
  if (!text || !*text) return kAssimpCpuSeconds;
  char* end = nullptr;
  errno = 0;
  const unsigned long long value = std::strtoull(text, &end, 10);
  if (errno != 0 || *end != '\0' || *text == '-' || value < 1 || value > 3600)
    throw InputError("RASTRACE_ASSIMP_CPU_SECONDS=" + std::string(text).substr(0, 40) +
                     ": expected whole seconds from 1 to 3600");
  return static_cast<rlim_t>(value);
}

const aiScene* read_with_assimp(Assimp::Importer& importer, const std::string& path) {
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  return importer.ReadFile(path, kAssimpFlags);
}

// libassimp crashes on some damaged files (an ASE model with one byte changed: signal 11) and
// runs away on others (a mutated COLLADA file: 1.8 GB). It reads the file first in a child
// process limited in CPU time and address space; only a file the child read without crashing is
// read again in this process. A crash or a limit becomes an InputError naming the file.
void read_in_contained_child(const std::string& path) {
  const rlim_t cpu_seconds = assimp_cpu_seconds();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return;  // no child: read in this process, uncontained
  if (pid == 0) {
    const rlimit cpu{cpu_seconds, cpu_seconds};
    ::setrlimit(RLIMIT_CPU, &cpu);
#if !RASTRACE_ASAN  // AddressSanitizer reserves terabytes of address space: every mmap would fail
    const rlimit memory{kAssimpMemoryBytes, kAssimpMemoryBytes};
    ::setrlimit(RLIMIT_AS, &memory);
#endif
    try {
      Assimp::Importer importer;
      read_with_assimp(importer, path);
    } catch (const std::bad_alloc&) {
      ::_exit(3);
    } catch (...) {
      ::_exit(4);
    }
    ::_exit(0);  // read or refused: this process reads it again and reports assimp's error
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 3)
    throw_in_file(path, "assimp needs more than " + std::to_string(kAssimpMemoryBytes >> 30) +
                            " GiB reading it: refused as damaged or hostile");
  if (WIFSIGNALED(status) && (WTERMSIG(status) == SIGXCPU || WTERMSIG(status) == SIGKILL))
    throw_in_file(path, "assimp took more than " + std::to_string(cpu_seconds) +
                            " s of CPU reading it: refused as damaged or hostile");
  if (WIFSIGNALED(status))
    throw_in_file(path, "assimp crashed reading it (signal " + std::to_string(WTERMSIG(status)) + ", " +
                            ::strsignal(WTERMSIG(status)) + "): the file is damaged or not what its extension says");
  // A sanitizer's crash handler turns the signal into an exit status.
  throw_in_file(path, "assimp crashed reading it (exit status " + std::to_string(WEXITSTATUS(status)) +
                          "): the file is damaged or not what its extension says");
}

}  // namespace

Mesh load_with_assimp(const std::string& path) {
  require_regular_file(path);
  read_in_contained_child(path);
  Assimp::Importer importer;
  const aiScene* scene = read_with_assimp(importer, path);
  if (!scene) throw_in_file(path, std::string("assimp cannot read it: ") + importer.GetErrorString());
  if (scene->mNumMeshes == 0) throw_in_file(path, "no triangle meshes in the file");

  Mesh mesh;
  mesh.name = path;
  for (unsigned m = 0; m < scene->mNumMaterials; ++m) {
    const aiMaterial& source = *scene->mMaterials[m];
    Material material;
    aiString name;
    if (source.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) material.name = name.C_Str();
    aiColor4D colour(1.0f, 1.0f, 1.0f, 1.0f);
    if (source.Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS ||
        source.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS)
      material.diffuse = glm::vec4(colour.r, colour.g, colour.b, colour.a);
    float opacity = 1.0f;
    if (source.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS) material.diffuse.a = opacity;
    read_texture(path, *scene, source, material);
    mesh.materials.push_back(std::move(material));
  }

  bool any_normals = false, any_uvs = false;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    any_normals |= scene->mMeshes[m]->HasNormals();
    any_uvs |= scene->mMeshes[m]->HasTextureCoords(0);
  }
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& source = *scene->mMeshes[m];
    if (!(source.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (unsigned v = 0; v < source.mNumVertices; ++v) {
      const aiVector3D& p = source.mVertices[v];
      mesh.positions.emplace_back(p.x, p.y, p.z);
      if (any_normals) {
        const aiVector3D n = source.HasNormals() ? source.mNormals[v] : aiVector3D(0.0f);
        mesh.normals.emplace_back(n.x, n.y, n.z);
      }
      if (any_uvs) {
        const aiVector3D t = source.HasTextureCoords(0) ? source.mTextureCoords[0][v] : aiVector3D(0.0f);
        mesh.uvs.emplace_back(t.x, t.y);
      }
    }
    for (unsigned f = 0; f < source.mNumFaces; ++f) {
      const aiFace& face = source.mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (unsigned k = 0; k < 3; ++k) {
        if (face.mIndices[k] >= source.mNumVertices)
          throw_in_file(path, "mesh " + std::to_string(m) + " face " + std::to_string(f) + ": index " +
                                  std::to_string(face.mIndices[k]) + " >= vertex count " +
                                  std::to_string(source.mNumVertices));
        mesh.indices.push_back(base + face.mIndices[k]);
      }
      mesh.face_material.push_back(source.mMaterialIndex);
    }
  }
  if (mesh.materials.empty()) mesh.face_material.clear();
  for (const auto& p : mesh.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw_in_file(path, "a vertex position is not finite (NaN or infinity)");
  if (mesh.indices.empty()) throw_in_file(path, "no triangles in the file");
  return mesh;
}

}  // namespace rastrace
