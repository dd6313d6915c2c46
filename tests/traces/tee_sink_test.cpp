// TeeSink hands every kind of event to every sink, in order: a tee that dropped one kind (the
// address events of imported traces, say) would make a live simulation disagree with its trace.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "traces/tee_sink.h"

namespace rastrace {
namespace {

// Writes one line per call, with the event's contents, so that the logs compare as strings.
class LoggingSink final : public EventSink {
 public:
  void begin_frame(std::uint32_t frame) override { log.push_back("begin_frame " + std::to_string(frame)); }
  void begin_draw(const DrawInfo& draw) override {
    log.push_back("begin_draw " + std::to_string(draw.draw) + " type " + std::to_string(int(draw.type)) + " restart " +
                  (draw.restart_index ? std::to_string(*draw.restart_index) : std::string("none")));
  }
  void vertex_fetches(std::span<const VertexFetch> fetches) override {
    std::string line = "vertex_fetches";
    for (const VertexFetch& f : fetches) line += " " + std::to_string(f.vertex) + (f.primitive_start ? "*" : "");
    log.push_back(line);
  }
  void texel_accesses(std::span<const TexelAccess> accesses) override {
    std::string line = "texel_accesses";
    for (const TexelAccess& a : accesses)
      line += " t" + std::to_string(a.texture) + "/l" + std::to_string(a.level) + "/" + std::to_string(a.x) + "," +
              std::to_string(a.y) + "@" + std::to_string(a.pixel_x) + "," + std::to_string(a.pixel_y) + "#" +
              std::to_string(a.triangle);
    log.push_back(line);
  }
  void end_draw() override { log.push_back("end_draw"); }
  void address_accesses(std::span<const AddressAccess> accesses) override {
    std::string line = "address_accesses";
    for (const AddressAccess& a : accesses) line += " " + std::to_string(a.address) + ":" + std::to_string(a.label);
    log.push_back(line);
  }
  void framebuffer_accesses(std::span<const FramebufferAccess> accesses) override {
    std::string line = "framebuffer_accesses";
    for (const FramebufferAccess& a : accesses)
      line += " " + std::to_string(a.x) + "," + std::to_string(a.y) + ":" + std::to_string(int(a.op)) + "/" +
              std::to_string(a.mask) + "#" + std::to_string(a.triangle);
    log.push_back(line);
  }
  bool wants_framebuffer_events() const override { return wants; }
  void finish() override { log.push_back("finish"); }

  std::vector<std::string> log;
  bool wants = false;
};

TEST(TeeSink, ForwardsEveryKindOfEventToEverySinkInOrder) {
  LoggingSink first, second;
  TeeSink tee({&first, &second});
  EventSink& sink = tee;  // through the interface, as the renderer and the replay call it

  const std::vector<VertexFetch> fetches = {{7, true}, {8, false}, {9, false}};
  const std::vector<TexelAccess> texels = {{1, 2, 30, 40, 5, 6, 0}, {0, 0, 3, 4, 5, 7, 1}};
  const std::vector<AddressAccess> addresses = {{0x1000, 0}, {0x2040, 1}, {0xFFFFFFFFFFull, 2}};
  sink.begin_frame(4);
  sink.begin_draw(DrawInfo{3, PrimitiveType::TriangleStrip, 65535});
  sink.vertex_fetches(fetches);
  sink.texel_accesses(texels);
  sink.framebuffer_accesses(std::vector<FramebufferAccess>{{4, 6, FramebufferOp::ColourWrite, 9, 12}});
  sink.end_draw();
  sink.address_accesses(addresses);
  sink.finish();

  const std::vector<std::string> expected = {
      "begin_frame 4",
      "begin_draw 3 type 1 restart 65535",
      "vertex_fetches 7* 8 9",
      "texel_accesses t1/l2/30,40@5,6#0 t0/l0/3,4@5,7#1",
      "framebuffer_accesses 4,6:2/9#12",
      "end_draw",
      "address_accesses 4096:0 8256:1 1099511627775:2",
      "finish",
  };
  EXPECT_EQ(first.log, expected);
  EXPECT_EQ(second.log, expected);
  // The renderer records framebuffer events when any sink of the tee wants them.
  EXPECT_FALSE(tee.wants_framebuffer_events());
  second.wants = true;
  EXPECT_TRUE(tee.wants_framebuffer_events());
}

}  // namespace
}  // namespace rastrace
