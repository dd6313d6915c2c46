// Records texel-access events for an EventSink through an EventWindow (traces/event_window.h):
// the sampler's hot loop stores an event, in the sink's own memory when it lends storage, else in
// a buffer handed to the sink when full, so the per-event cost is a store and the virtual call is
// paid once per kCapacity events. With no sink, recording is a counter increment.
#pragma once

#include <cstdint>
#include <span>

#include "traces/event_window.h"
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

  explicit TexelRecorder(EventSink* sink = nullptr) : sink_(sink), window_(sink) {}
  TexelRecorder(const TexelRecorder&) = delete;
  TexelRecorder& operator=(const TexelRecorder&) = delete;

  void record(const TexelSite& site, unsigned level, int x, int y) {
    ++reads_;
    if (!sink_) return;
    TexelAccess& event = *window_.reserve(1);
    event.texture = site.texture;
    event.level = static_cast<std::uint8_t>(level);
    event.x = static_cast<std::uint32_t>(x);
    event.y = static_cast<std::uint32_t>(y);
    event.pixel_x = site.pixel_x;
    event.pixel_y = site.pixel_y;
    event.triangle = site.triangle;
    window_.stored();
  }
  // Records a run of events as record() would one by one: same batches, same calls to the sink.
  void append(std::span<const TexelAccess> events) {
    reads_ += events.size();
    if (sink_) window_.append(events);
  }
  // The four texels of a bilinear footprint, (x0, y0), (x1, y0), (x0, y1), (x1, y1), with one
  // branch for the four: they are stored into the window's slack, and a full buffer hands the
  // sink exactly kCapacity events, as four record() calls would.
  void record_footprint(const TexelSite& site, unsigned level, int x0, int x1, int y0, int y1) {
    reads_ += 4;
    if (!sink_) return;
    TexelAccess event;
    event.texture = site.texture;
    event.level = static_cast<std::uint8_t>(level);
    event.pixel_x = site.pixel_x;
    event.pixel_y = site.pixel_y;
    event.triangle = site.triangle;
    TexelAccess* out = window_.reserve(4);
    const std::uint32_t xs[2] = {static_cast<std::uint32_t>(x0), static_cast<std::uint32_t>(x1)};
    const std::uint32_t ys[2] = {static_cast<std::uint32_t>(y0), static_cast<std::uint32_t>(y1)};
    for (int i = 0; i < 4; ++i) {
      out[i] = event;
      out[i].x = xs[i & 1];
      out[i].y = ys[i >> 1];
    }
    window_.stored();
  }
  void flush() { window_.flush(); }
  std::uint64_t reads() const { return reads_; }
  EventSink* sink() const { return sink_; }

 private:
  EventSink* sink_;
  std::uint64_t reads_ = 0;
  EventWindow<TexelAccess, kCapacity, 4> window_;  // 4: record_footprint's slack
};

}  // namespace rastrace
