// Where the renderer's events go: a trace file, a memory buffer, or a bank of live caches.
// Events arrive in batches so that the per-event cost is a store, not a virtual call.
#pragma once

#include <cstdint>
#include <span>

#include "traces/events.h"

namespace rastrace {

class EventSink {
 public:
  virtual ~EventSink() = default;
  // A new frame starts (render --frames N, or a trace holding several frames): frame numbers
  // start at 0 and never decrease. A single-frame render may never call it. Forwarding sinks
  // forward it; caches keep their contents across frames (a sink that wants per-frame counts
  // takes them here).
  virtual void begin_frame(std::uint32_t /*frame*/) {}
  virtual void begin_draw(const DrawInfo& /*draw*/) {}
  virtual void vertex_fetches(std::span<const VertexFetch> /*fetches*/) {}
  virtual void texel_accesses(std::span<const TexelAccess> /*accesses*/) {}
  // Depth-test reads, depth writes and colour writes, per 2x2 quad.
  virtual void framebuffer_accesses(std::span<const FramebufferAccess> /*accesses*/) {}
  // Whether the rasterizer should record framebuffer events for this sink at all: a sink that
  // uses them says so, and a frame rendered for other sinks pays nothing for them.
  virtual bool wants_framebuffer_events() const { return false; }
  virtual void end_draw() {}
  // Byte addresses from imported (din) traces; the renderer never emits these.
  virtual void address_accesses(std::span<const AddressAccess> /*accesses*/) {}
  // End of the frame: flush buffers, finish files.
  virtual void finish() {}
};

}  // namespace rastrace
