// Batches framebuffer events (depth-test reads, depth writes, colour writes of a 2x2 quad) for an
// EventSink, as TexelRecorder batches texel reads: the raster loop stores an event, the virtual
// call is paid once per kCapacity events. Without a sink that wants framebuffer events, record()
// is one predictable branch.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <exception>
#include <span>

#include "traces/sink.h"

namespace rastrace {

class FramebufferRecorder {
 public:
  static constexpr std::size_t kCapacity = 4096;

  // Records only when `sink` is set and wants framebuffer events.
  explicit FramebufferRecorder(EventSink* sink = nullptr)
      : sink_(sink && sink->wants_framebuffer_events() ? sink : nullptr) {}
  FramebufferRecorder(const FramebufferRecorder&) = delete;
  FramebufferRecorder& operator=(const FramebufferRecorder&) = delete;
  // Destructors must not throw: while an error unwinds (a sink's write failed) the records are
  // dropped; a sink that fails here reports the failure again from its finish().
  ~FramebufferRecorder() {
    if (std::uncaught_exceptions() > 0) return;
    try {
      flush();
    } catch (...) {
    }
  }

  bool active() const { return sink_ != nullptr; }
  void record(FramebufferOp op, int quad_x, int quad_y, unsigned mask, std::uint32_t triangle) {
    if (!sink_) return;
    ++records_;
    FramebufferAccess& event = buffer_[size_++];
    event.x = static_cast<std::uint16_t>(quad_x);
    event.y = static_cast<std::uint16_t>(quad_y);
    event.op = op;
    event.mask = static_cast<std::uint8_t>(mask);
    event.triangle = triangle;
    if (size_ == kCapacity) flush();
  }
  // Records a run of events as record() would one by one: same batches, same calls to the sink.
  void append(std::span<const FramebufferAccess> events) {
    if (!sink_) return;
    records_ += events.size();
    while (!events.empty()) {
      const std::size_t take = std::min(kCapacity - size_, events.size());
      std::memcpy(buffer_.data() + size_, events.data(), take * sizeof(FramebufferAccess));
      size_ += take;
      events = events.subspan(take);
      if (size_ == kCapacity) flush();
    }
  }
  // Events recorded (0 while inactive).
  std::uint64_t records() const { return records_; }
  void flush() {
    if (sink_ && size_) sink_->framebuffer_accesses(std::span<const FramebufferAccess>(buffer_.data(), size_));
    size_ = 0;
  }

 private:
  EventSink* sink_;
  std::size_t size_ = 0;
  std::uint64_t records_ = 0;
  std::array<FramebufferAccess, kCapacity> buffer_;
};

}  // namespace rastrace
