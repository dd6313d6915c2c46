// Where the renderer's events go: a trace file, a memory buffer, or a bank of live caches.
// Events arrive in batches so that the per-event cost is a store, not a virtual call.
//
// Lending (optional): a sink that keeps events in memory of its own may lend that memory to the
// recorders (traces/event_window.h), which then store each event once, where it stays, instead
// of filling a buffer that the sink copies. A lending sink says so in lends_storage(); then
// texel_slots(n) returns exactly n writable slots after the texel events it holds, and
// commit_texels(used) makes the first `used` of them events, as texel_accesses() with those
// events would, and drops the rest (likewise framebuffer_ and vertex_ slots). At most one span
// of each kind is lent at a time, and no other call for that kind comes while it is out; calls
// for other kinds may. A sink lends only if what it keeps is each kind's sequence of events:
// lent events reach it in other batches, and interleaved with the other kinds otherwise, than
// through the batch calls (the parallel rasterizer commits a whole batch of triangles' texels
// at once). Sinks that see batches or the interleaving (a trace file's chunk order depends on
// it, and a tee's sinks each need their own copy) do not lend, and get the batch calls as ever.
#pragma once

#include <cstddef>
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

  // Lending (see the top of this file). The defaults lend nothing; a sink overriding
  // lends_storage() to return true overrides all six.
  virtual bool lends_storage() const { return false; }
  // A lending sink whose events are read, if at all, after the frame, when they are long out of
  // the caches (a frame's tens of megabytes): the recorders then write lent slots with streaming
  // (non-temporal) stores, which skip reading each line before overwriting it and leave the
  // caches to the renderer. A sink that reads its slots back soon (a tile buffer copied out right
  // after) says false, the default: there cached stores are cheaper than reading from memory.
  virtual bool streams_lent_storage() const { return false; }
  virtual std::span<VertexFetch> vertex_slots(std::size_t /*count*/) { return {}; }
  virtual void commit_vertices(std::size_t /*used*/) {}
  virtual std::span<TexelAccess> texel_slots(std::size_t /*count*/) { return {}; }
  virtual void commit_texels(std::size_t /*used*/) {}
  virtual std::span<FramebufferAccess> framebuffer_slots(std::size_t /*count*/) { return {}; }
  virtual void commit_framebuffer(std::size_t /*used*/) {}
};

}  // namespace rastrace
