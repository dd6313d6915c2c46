// Records framebuffer events (depth-test reads, depth writes, colour writes of a 2x2 quad) for an
// EventSink through an EventWindow, as TexelRecorder records texel reads: the raster loop stores
// an event, the virtual call is paid once per kCapacity events. Without a sink that wants
// framebuffer events, record() is one predictable branch.
#pragma once

#include <cstdint>
#include <span>

#include "traces/event_window.h"
#include "traces/sink.h"

namespace rastrace {

class FramebufferRecorder {
 public:
  static constexpr std::size_t kCapacity = 4096;

  // Records only when `sink` is set and wants framebuffer events.
  explicit FramebufferRecorder(EventSink* sink = nullptr)
      : sink_(sink && sink->wants_framebuffer_events() ? sink : nullptr), window_(sink_) {}
  FramebufferRecorder(const FramebufferRecorder&) = delete;
  FramebufferRecorder& operator=(const FramebufferRecorder&) = delete;

  bool active() const { return sink_ != nullptr; }
  // The test inline, the store apart: the quad stage records three times per quad, and as one
  // function too large to inline it cost a call each time even with no sink.
  [[gnu::always_inline]] void record(FramebufferOp op, int quad_x, int quad_y, unsigned mask, std::uint32_t triangle) {
    if (sink_) store(op, quad_x, quad_y, mask, triangle);
  }
  // Records a run of events as record() would one by one: same batches, same calls to the sink.
  void append(std::span<const FramebufferAccess> events) {
    if (!sink_) return;
    records_ += events.size();
    window_.append(events);
  }
  // Events recorded (0 while inactive).
  std::uint64_t records() const { return records_; }
  void flush() { window_.flush(); }

 private:
  void store(FramebufferOp op, int quad_x, int quad_y, unsigned mask, std::uint32_t triangle) {
    ++records_;
    FramebufferAccess& event = *window_.reserve(1);
    event.x = static_cast<std::uint16_t>(quad_x);
    event.y = static_cast<std::uint16_t>(quad_y);
    event.op = op;
    event.mask = static_cast<std::uint8_t>(mask);
    event.triangle = triangle;
    window_.stored();
  }

  EventSink* sink_;
  std::uint64_t records_ = 0;
  EventWindow<FramebufferAccess, kCapacity> window_;
};

}  // namespace rastrace
