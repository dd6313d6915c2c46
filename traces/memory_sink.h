// An in-memory sink: keeps every event, for tests and for replaying without a file.
#pragma once

#include <vector>

#include "traces/sink.h"

namespace rastrace {

class MemorySink final : public EventSink {
 public:
  void begin_draw(const DrawInfo& draw) override;
  void vertex_fetches(std::span<const VertexFetch> fetches) override;
  void texel_accesses(std::span<const TexelAccess> accesses) override;
  void framebuffer_accesses(std::span<const FramebufferAccess> accesses) override;
  bool wants_framebuffer_events() const override { return true; }

  std::vector<DrawInfo> draws;
  std::vector<std::size_t> draw_first_fetch;  // index into fetches where each draw starts
  std::vector<VertexFetch> fetches;
  std::vector<TexelAccess> texels;
  std::vector<FramebufferAccess> framebuffer;
};

}  // namespace rastrace
