// A trace's metadata states each texture's storage format when one is block-compressed, reads it
// back onto every level, and refuses a format it does not know, naming the file and the entry.
#include <gtest/gtest.h>

#include "core/error.h"
#include "traces/trace_metadata.h"

namespace rastrace {
namespace {

TraceMetadata two_textures(TextureFormat second) {
  TraceMetadata m;
  m.scene = "s";
  m.textures = {{{8, 8}, {4, 4}}, {{16, 4, second}, {8, 2, second}}};
  return m;
}

TEST(TextureFormats, RoundTripOntoEveryLevelOfEachTexture) {
  const TraceMetadata m = two_textures(TextureFormat::Bc7);
  const std::string json = metadata_to_json(m);
  EXPECT_NE(json.find("\"texture_formats\":[\"rgba8\",\"bc7\"]"), std::string::npos) << json;
  const TraceMetadata back = metadata_from_json(json, "t.rtrace");
  EXPECT_EQ(back, m);
  EXPECT_EQ(back.textures[1][1].format, TextureFormat::Bc7);
  EXPECT_EQ(back.textures[0][1].format, TextureFormat::Rgba8);
}

TEST(TextureFormats, AllRgba8HeadersAreWrittenAsBefore) {
  EXPECT_EQ(metadata_to_json(two_textures(TextureFormat::Rgba8)).find("texture_formats"), std::string::npos);
}

TEST(TextureFormats, AnUnknownNameOrCountIsAnErrorNamingTheFileAndEntry) {
  std::string json = metadata_to_json(two_textures(TextureFormat::Bc1));
  const std::string bad = json.substr(0, json.find("\"bc1\"")) + "\"dxt9\"" + json.substr(json.find("\"bc1\"") + 5);
  try {
    metadata_from_json(bad, "frame.rtrace");
    FAIL() << "dxt9 was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("frame.rtrace"), std::string::npos) << what;
    EXPECT_NE(what.find("texture_formats[1]"), std::string::npos) << what;
    EXPECT_NE(what.find("dxt9"), std::string::npos) << what;
  }
  const std::string short_list =
      json.substr(0, json.find("[\"rgba8\",")) + "[\"bc1\"]" + json.substr(json.find("\"bc1\"]") + 6);
  EXPECT_THROW(metadata_from_json(short_list, "frame.rtrace"), InputError);
}

}  // namespace
}  // namespace rastrace
