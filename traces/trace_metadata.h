// What a trace file says about itself, in its JSON header: the scene, the ordering, the frame, the
// filter, the tool version, and the size of every texture level (so a texel trace replays through
// any texture memory layout on its own, without the scene), and each texture's storage format
// ("texture_formats", written only when a texture is block-compressed, so RGBA8 headers are as
// before).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/texture_format.h"

namespace rastrace {

// A mip level's size in texels and its texture's storage format (every level of a texture has the
// same): a texel trace records logical texels, and the format turns them into block addresses.
struct LevelSize {
  LevelSize() = default;
  LevelSize(std::uint32_t w, std::uint32_t h, TextureFormat f = TextureFormat::Rgba8) : width(w), height(h), format(f) {}

  std::uint32_t width = 0;
  std::uint32_t height = 0;
  TextureFormat format = TextureFormat::Rgba8;
  bool operator==(const LevelSize&) const = default;
};
// Per texture, its mip levels, level 0 first.
using TextureLevels = std::vector<std::vector<LevelSize>>;

struct TraceMetadata {
  std::string scene;        // scene spec or mesh path
  std::string ordering;     // triangle ordering name
  std::uint32_t width = 0;  // frame resolution in pixels
  std::uint32_t height = 0;
  std::string filter;        // texture filter mode ("nearest", "bilinear", "trilinear", ...)
  std::string tool_version;  // filled by the writer when empty
  TextureLevels textures;
  std::map<std::string, std::string> extra;  // anything else worth recording

  bool operator==(const TraceMetadata&) const = default;
};

// JSON text <-> metadata. from_json throws InputError naming `file` on malformed JSON.
std::string metadata_to_json(const TraceMetadata& metadata);
TraceMetadata metadata_from_json(const std::string& json, const std::string& file);

}  // namespace rastrace
