#include "traces/trace_metadata.h"

#include <nlohmann/json.hpp>

#include "core/error.h"

namespace rastrace {

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
    m.width = j.at("resolution").at(0).get<std::uint32_t>();
    m.height = j.at("resolution").at(1).get<std::uint32_t>();
    m.filter = j.at("filter").get<std::string>();
    for (const auto& t : j.at("textures")) {
      std::vector<LevelSize> levels;
      for (const auto& l : t) levels.push_back({l.at(0).get<std::uint32_t>(), l.at(1).get<std::uint32_t>()});
      m.textures.push_back(std::move(levels));
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
