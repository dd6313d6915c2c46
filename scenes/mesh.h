// The mesh every module works on: a triangle list with the file's own vertex sharing.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/texture_format.h"

namespace rastrace {

// Where a material's texture comes from: a file, or one of the procedural textures.
struct TextureSource {
  enum class Kind { None, File, Checker, FourColour, Gradient };
  Kind kind = Kind::None;
  std::string path;  // Kind::File: resolved path of the image
  int size = 256;    // procedural: width and height in texels
  int checks = 8;    // Kind::Checker: squares per side
  // Kind::File with the image inside the model (glTF/GLB, FBX...): the encoded image file (PNG,
  // JPEG...) as bytes; `path` then names it "model.glb#*0" (no such file on disk).
  std::shared_ptr<const std::vector<std::uint8_t>> embedded;
  // How the texels are stored: every mip level is encoded to this format and decoded back at load.
  TextureFormat format = TextureFormat::Rgba8;
};

struct Material {
  std::string name;
  glm::vec4 diffuse{1.0f, 1.0f, 1.0f, 1.0f};  // modulates the texture
  TextureSource texture_source;               // where the texture comes from (loaders fill this)
  int texture = -1;                           // index into Scene::textures once a scene is loaded; -1: untextured
};

// A regular W x H quad grid laid out as in Castano's article (vertex (x, y) = (W+1)*y + x).
struct GridShape {
  int width = 0;
  int height = 0;
};

struct Mesh {
  std::string name;  // file name or procedural description
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;            // empty, or one per vertex
  std::vector<glm::vec2> uvs;                // empty, or one per vertex
  std::vector<std::uint32_t> indices;        // three per triangle, counter-clockwise front faces
  std::vector<std::uint32_t> face_material;  // empty (all material 0), or one per triangle
  std::vector<Material> materials;           // may be empty: one default white material
  std::optional<GridShape> grid;             // set by the procedural grid generator

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t face_count() const { return indices.size() / 3; }
  std::uint32_t material_of(std::size_t face) const { return face_material.empty() ? 0u : face_material[face]; }
};

}  // namespace rastrace
