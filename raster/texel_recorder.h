// Batches texel-access events for an EventSink: a fixed buffer filled by the sampler's hot loop
// and handed to the sink when full, so the per-event cost is a store and the virtual call is
// paid once per kCapacity events. With no sink, recording is a counter increment.
#pragma once

#include <array>
#include <cstdint>
#include <exception>
#include <span>

#include "traces/sink.h"

namespace rastrace {

// Where a texel read comes from: the texture and the fragment.
struct TexelSite {
  std::uint32_t texture = 0;
  std::uint16_t pixel_x = 0;
  std::uint16_t pixel_y = 0;
  std::uint32_t triangle = 0;
};

class TexelRecorder {
 public:
  static constexpr std::size_t kCapacity = 4096;

  explicit TexelRecorder(EventSink* sink = nullptr) : sink_(sink) {}
  TexelRecorder(const TexelRecorder&) = delete;
  TexelRecorder& operator=(const TexelRecorder&) = delete;
  // Destructors must not throw: while an error unwinds (a sink's write failed) the records are
  // dropped; a sink that fails here reports the failure again from its finish().
  ~TexelRecorder() {
    if (std::uncaught_exceptions() > 0) return;
    try {
      flush();
    } catch (...) {
    }
  }

  void record(const TexelSite& site, unsigned level, int x, int y) {
    ++reads_;
    if (!sink_) return;
    TexelAccess& event = buffer_[size_++];
    event.texture = site.texture;
    event.level = static_cast<std::uint8_t>(level);
    event.x = static_cast<std::uint32_t>(x);
    event.y = static_cast<std::uint32_t>(y);
    event.pixel_x = site.pixel_x;
    event.pixel_y = site.pixel_y;
    event.triangle = site.triangle;
    if (size_ == kCapacity) flush();
  }
  void flush() {
    if (sink_ && size_) sink_->texel_accesses(std::span<const TexelAccess>(buffer_.data(), size_));
    size_ = 0;
  }
  std::uint64_t reads() const { return reads_; }

 private:
  EventSink* sink_;
  std::size_t size_ = 0;
  std::uint64_t reads_ = 0;
  std::array<TexelAccess, kCapacity> buffer_;
};

}  // namespace rastrace
