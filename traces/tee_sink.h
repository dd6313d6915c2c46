// A sink that feeds several sinks: render once, and write the trace file while a bank of live
// caches simulates the same events.
#pragma once

#include <utility>
#include <vector>

#include "traces/sink.h"

namespace rastrace {

// Forwards every event, of every kind EventSink has, to each sink in turn, in the order given.
// The sinks are not owned; finish() finishes each of them once.
class TeeSink final : public EventSink {
 public:
  explicit TeeSink(std::vector<EventSink*> sinks) : sinks_(std::move(sinks)) {}
  void begin_frame(std::uint32_t frame) override;
  void begin_draw(const DrawInfo& draw) override;
  void vertex_fetches(std::span<const VertexFetch> fetches) override;
  void texel_accesses(std::span<const TexelAccess> accesses) override;
  void framebuffer_accesses(std::span<const FramebufferAccess> accesses) override;
  // True when any of the sinks wants them (each is then handed every framebuffer event).
  bool wants_framebuffer_events() const override;
  void end_draw() override;
  void address_accesses(std::span<const AddressAccess> accesses) override;
  void finish() override;

 private:
  std::vector<EventSink*> sinks_;
};

}  // namespace rastrace
