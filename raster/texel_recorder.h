// Records texel-access events for an EventSink through an EventWindow (traces/event_window.h):
// the sampler's hot loop stores an event, in the sink's own memory when it lends storage, else in
// a buffer handed to the sink when full, so the per-event cost is a store and the virtual call is
// paid once per kCapacity events. With no sink, recording is a counter increment.
//
// An event is written as three 64-bit words, and into a sink that asks for it (sink.h) with
// streaming stores: a trilinear frame's tens of megabytes of events are then written to memory
// without first reading every line of it (on the grazing plane, with the words kept in registers,
// that halved what tracing to memory costs).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
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
  // The words' layout is the event's, padding zero, on a little-endian machine; elsewhere the
  // events are stored field by field.
  static constexpr bool kWords = std::endian::native == std::endian::little && sizeof(TexelAccess) == 24 &&
                                 offsetof(TexelAccess, level) == 4 && offsetof(TexelAccess, x) == 8 &&
                                 offsetof(TexelAccess, y) == 12 && offsetof(TexelAccess, pixel_x) == 16 &&
                                 offsetof(TexelAccess, pixel_y) == 18 && offsetof(TexelAccess, triangle) == 20;

 public:
  static constexpr std::size_t kCapacity = 4096;

  explicit TexelRecorder(EventSink* sink = nullptr) : sink_(sink), window_(sink) {}
  TexelRecorder(const TexelRecorder&) = delete;
  TexelRecorder& operator=(const TexelRecorder&) = delete;

  void record(const TexelSite& site, unsigned level, int x, int y) {
    ++reads_;
    if (!sink_) return;
    if constexpr (kWords) {
      const std::uint64_t words[3] = {head(site, level), xy(x, y), tail(site)};
      store(window_.reserve_streamed(1), words);
      window_.stored();
      return;
    }
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
  [[gnu::always_inline]] void record_footprint(const TexelSite& site, unsigned level, int x0, int x1, int y0, int y1) {
    reads_ += 4;
    if (!sink_) return;
    if constexpr (kWords) {
      const std::uint64_t h = head(site, level), t = tail(site);
      const std::uint64_t words[12] = {h, xy(x0, y0), t, h, xy(x1, y0), t, h, xy(x0, y1), t, h, xy(x1, y1), t};
      store(window_.reserve_streamed(4), words);
      window_.stored();
      return;
    }
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
  // Without a sink, recording is counting: a caller may count n reads at once instead of
  // recording them one by one (only when sink() is null).
  void count_unrecorded(std::uint64_t n) { reads_ += n; }
  EventSink* sink() const { return sink_; }

 private:
  static std::uint64_t head(const TexelSite& site, unsigned level) {
    return site.texture | std::uint64_t{static_cast<std::uint8_t>(level)} << 32;
  }
  static std::uint64_t xy(int x, int y) {
    return static_cast<std::uint32_t>(x) | std::uint64_t{static_cast<std::uint32_t>(y)} << 32;
  }
  static std::uint64_t tail(const TexelSite& site) {
    return std::uint64_t{site.pixel_x} | std::uint64_t{site.pixel_y} << 16 | std::uint64_t{site.triangle} << 32;
  }
  // Whole events' words into `out`. Streamed when the window streams: 16 bytes a store from a
  // 16-byte boundary, the word before it and any word after it 8 bytes a store (8-byte stores
  // alone made the grazing plane's traced frame 5% slower than this). Else as 16-byte vectors
  // where the count allows. No path copies the words through memory: with a fallback that did,
  // the compiler kept them in an array on the stack, stored twice, and the frame was 6% slower.
  template <std::size_t kCount>
  [[gnu::always_inline]] void store(TexelAccess* out, const std::uint64_t (&words)[kCount]) {
#if RASTRACE_STREAMING_STORES
    if (window_.streaming()) {
      if (reinterpret_cast<std::uintptr_t>(out) % 16 == 0)
        stream<0>(out, words);
      else
        stream<1>(out, words);
      return;
    }
    if constexpr (kCount % 2 == 0) {
      for (std::size_t i = 0; i < kCount; i += 2)
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out) + i / 2, pair(words, i));
      return;
    }
#endif
    std::memcpy(static_cast<void*>(out), words, sizeof words);
  }
#if RASTRACE_STREAMING_STORES
  template <std::size_t kCount>
  [[gnu::always_inline]] static __m128i pair(const std::uint64_t (&words)[kCount], std::size_t i) {
    return _mm_set_epi64x(static_cast<long long>(words[i + 1]), static_cast<long long>(words[i]));
  }
  // kAligned: the first of words[kAligned...] whose address is a multiple of 16; the window
  // streams only spans of 8-byte aligned events.
  template <std::size_t kAligned, std::size_t kCount>
  [[gnu::always_inline]] static void stream(TexelAccess* out, const std::uint64_t (&words)[kCount]) {
    auto* to = reinterpret_cast<long long*>(out);
    if constexpr (kAligned == 1) _mm_stream_si64(to, static_cast<long long>(words[0]));
    constexpr std::size_t kEnd = kAligned + (kCount - kAligned) / 2 * 2;
    for (std::size_t i = kAligned; i < kEnd; i += 2)
      _mm_stream_si128(reinterpret_cast<__m128i*>(to + i), pair(words, i));
    if constexpr (kEnd < kCount) _mm_stream_si64(to + kEnd, static_cast<long long>(words[kEnd]));
  }
#endif

  EventSink* sink_;
  std::uint64_t reads_ = 0;
  EventWindow<TexelAccess, kCapacity, 4> window_;  // 4: record_footprint's slack
};

}  // namespace rastrace
