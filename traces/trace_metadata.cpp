#include "traces/trace_metadata.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/json_integer.h"

namespace rastrace {

namespace {
constexpr std::uint32_t kMaxLevelSide = 65536;  // texels a side of one mip level
}  // namespace

std::string metadata_to_json(const TraceMetadata& m) {
  nlohmann::json j;
  j["tool"] = "rastrace";
  j["tool_version"] = m.tool_version;
  j["scene"] = m.scene;
  j["ordering"] = m.ordering;
  j["resolution"] = {m.width, m.height};
  j["filter"] = m.filter;
  nlohmann::json textures = nlohmann::json::array();
  for (const auto& levels : m.textures) {
    nlohmann::json t = nlohmann::json::array();
    for (const LevelSize& l : levels) t.push_back({l.width, l.height});
    textures.push_back(t);
  }
  j["textures"] = textures;
  const auto compressed = [](const std::vector<LevelSize>& levels) {
    return !levels.empty() && is_compressed(levels.front().format);
  };
  if (std::any_of(m.textures.begin(), m.textures.end(), compressed)) {
    nlohmann::json formats = nlohmann::json::array();
    for (const auto& levels : m.textures)
      formats.push_back(to_string(levels.empty() ? TextureFormat::Rgba8 : levels.front().format));
    j["texture_formats"] = formats;
  }
  j["extra"] = m.extra;
  return j.dump();
}

TraceMetadata metadata_from_json(const std::string& text, const std::string& file) {
  TraceMetadata m;
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    m.tool_version = j.at("tool_version").get<std::string>();
    m.scene = j.at("scene").get<std::string>();
    m.ordering = j.at("ordering").get<std::string>();
    m.width = json_integer<std::uint32_t>(j.at("resolution").at(0), file + ": metadata header: resolution[0]");
    m.height = json_integer<std::uint32_t>(j.at("resolution").at(1), file + ": metadata header: resolution[1]");
    m.filter = j.at("filter").get<std::string>();
    for (std::size_t i = 0; i < j.at("textures").size(); ++i) {
      std::vector<LevelSize> levels;
      const auto& t = j.at("textures").at(i);
      for (std::size_t k = 0; k < t.size(); ++k) {
        const std::string where = file + ": metadata header: textures[" + std::to_string(i) + "][" + std::to_string(k) + "]";
        const LevelSize level{json_integer<std::uint32_t>(t.at(k).at(0), where + "[0]"),
                              json_integer<std::uint32_t>(t.at(k).at(1), where + "[1]")};
        // Layouts round a side up to a power of two in 32 bits; no GPU texture is wider than 32768.
        if (level.width > kMaxLevelSide || level.height > kMaxLevelSide)
          throw InputError(where + ": level of " + std::to_string(level.width) + "x" + std::to_string(level.height) +
                           " texels: expected at most " + std::to_string(kMaxLevelSide) + " a side");
        levels.push_back(level);
      }
      m.textures.push_back(std::move(levels));
    }
    if (j.contains("texture_formats")) {
      const auto& formats = j.at("texture_formats");
      if (!formats.is_array() || formats.size() != m.textures.size())
        throw InputError(file + ": metadata header: texture_formats: expected an array of " +
                         std::to_string(m.textures.size()) + " format names, one per texture");
      for (std::size_t i = 0; i < formats.size(); ++i) {
        const TextureFormat format = parse_texture_format(
            formats.at(i).get<std::string>(), file + ": metadata header: texture_formats[" + std::to_string(i) + "]");
        for (LevelSize& level : m.textures[i]) level.format = format;
      }
    }
    if (j.contains("extra")) m.extra = j.at("extra").get<std::map<std::string, std::string>>();
  } catch (const nlohmann::json::exception& e) {
    throw_in_file(file, std::string("metadata header: ") + e.what() +
                            ": expected the JSON object written by rastrace (scene, ordering, resolution, "
                            "filter, tool_version, textures)");
  }
  return m;
}

}  // namespace rastrace
