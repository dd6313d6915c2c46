// Where the renderer's events go: a trace file, a memory buffer, or a bank of live caches.
// Events arrive in batches so that the per-event cost is a store, not a virtual call.
#pragma once

#include <span>

#include "traces/events.h"

namespace rastrace {

class EventSink {
 public:
  virtual ~EventSink() = default;
  virtual void begin_draw(const DrawInfo& /*draw*/) {}
  virtual void vertex_fetches(std::span<const VertexFetch> /*fetches*/) {}
  virtual void texel_accesses(std::span<const TexelAccess> /*accesses*/) {}
  virtual void end_draw() {}
  // Byte addresses from imported (din) traces; the renderer never emits these.
  virtual void address_accesses(std::span<const AddressAccess> /*accesses*/) {}
  // End of the frame: flush buffers, finish files.
  virtual void finish() {}
};

}  // namespace rastrace
