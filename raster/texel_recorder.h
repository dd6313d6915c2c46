// Records texel-access events for an EventSink through an EventWindow (traces/event_window.h):
// the sampler's hot loop stores an event, in the sink's own memory when it lends storage, else in
// a buffer handed to the sink when full, so the per-event cost is a store and the virtual call is
// paid once per kCapacity events. With no sink, recording is a counter increment.
//
// An event is written as two 64-bit words, and into a sink that asks for it (sink.h) with
// streaming stores: a trilinear frame's tens of megabytes of events are then written to memory
// without first reading every line of it (on the grazing plane, with the words kept in registers,
// that halved what tracing to memory costs).
#pragma once

#include <atomic>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

#include "traces/event_window.h"
#include "traces/sink.h"

// record_quad's vector path: AVX2, chosen at run time, on x86-64 with GCC or clang.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define RASTRACE_TEXEL_QUAD_AVX2 1
#else
#define RASTRACE_TEXEL_QUAD_AVX2 0
#endif

namespace rastrace {

// Where a texel read comes from: the texture and the fragment.
struct TexelSite {
  std::uint16_t texture = 0;
  std::uint16_t pixel_x = 0;
  std::uint16_t pixel_y = 0;
  std::uint32_t triangle = 0;
};

class TexelRecorder {
  // The words' layout is the event's, padding zero, on a little-endian machine; elsewhere the
  // events are stored field by field.
  static constexpr bool kWords = std::endian::native == std::endian::little && sizeof(TexelAccess) == 16 &&
                                 offsetof(TexelAccess, level) == 2 && offsetof(TexelAccess, x) == 4 &&
                                 offsetof(TexelAccess, y) == 6 && offsetof(TexelAccess, pixel_x) == 8 &&
                                 offsetof(TexelAccess, pixel_y) == 10 && offsetof(TexelAccess, triangle) == 12;

 public:
  static constexpr std::size_t kCapacity = 4096;

  explicit TexelRecorder(EventSink* sink = nullptr) : sink_(sink), window_(sink) {}
  TexelRecorder(const TexelRecorder&) = delete;
  TexelRecorder& operator=(const TexelRecorder&) = delete;

  void record(const TexelSite& site, unsigned level, int x, int y) {
    ++reads_;
    if (!sink_) return;
    if constexpr (kWords) {
      const std::uint64_t words[2] = {head(site, level, x, y), tail(site)};
      store(window_.reserve_streamed(1), words);
      window_.stored();
      return;
    }
    TexelAccess& event = *window_.reserve(1);
    event.texture = site.texture;
    event.level = static_cast<std::uint8_t>(level);
    event.x = static_cast<std::uint16_t>(x);
    event.y = static_cast<std::uint16_t>(y);
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
      const std::uint64_t h = head(site, level, 0, 0), t = tail(site);
      const std::uint64_t words[8] = {h | xy(x0, y0), t, h | xy(x1, y0), t, h | xy(x0, y1), t, h | xy(x1, y1), t};
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
    const std::uint16_t xs[2] = {static_cast<std::uint16_t>(x0), static_cast<std::uint16_t>(x1)};
    const std::uint16_t ys[2] = {static_cast<std::uint16_t>(y0), static_cast<std::uint16_t>(y1)};
    for (int i = 0; i < 4; ++i) {
      out[i] = event;
      out[i].x = xs[i & 1];
      out[i].y = ys[i >> 1];
    }
    window_.stored();
  }
  // The footprints of a whole quad's four pixels: pixel p (at (qx + (p & 1), qy + (p >> 1)))
  // reads the 2x2 texels of lane p in `level`, then, kTwoLevels (trilinear), those of lane p + 4
  // in level + 1. The same events and batches as the record_footprint() calls in that order,
  // built in vector lanes and stored whole: the calls' scalar word building and window checks
  // were a third of what tracing the grazing plane cost.
  using Lanes = std::int32_t __attribute__((vector_size(32)));
  template <bool kTwoLevels>
  [[gnu::always_inline]] void record_quad(const TexelSite& site, unsigned level, int qx, int qy, const Lanes& x0,
                                          const Lanes& x1, const Lanes& y0, const Lanes& y1) {
#if RASTRACE_TEXEL_QUAD_AVX2
    if (sink_ && kWords && vector_quads()) {
      record_quad_avx2<kTwoLevels>(site, level, qx, qy, x0, x1, y0, y1);
      return;
    }
#endif
    for (int p = 0; p < 4; ++p) {
      TexelSite pixel = site;
      pixel.pixel_x = static_cast<std::uint16_t>(qx + (p & 1));
      pixel.pixel_y = static_cast<std::uint16_t>(qy + (p >> 1));
      for (int l = 0; l < (kTwoLevels ? 2 : 1); ++l)
        record_footprint(pixel, level + l, x0[p + 4 * l], x1[p + 4 * l], y0[p + 4 * l], y1[p + 4 * l]);
    }
  }
  void flush() { window_.flush(); }
  std::uint64_t reads() const { return reads_; }
  // False: record_quad() stores footprint by footprint from now on, as on a machine without AVX2
  // (for tests of that path on any machine; true, the default, uses AVX2 where there is one).
  static void use_vector_quads(bool enabled) { vector_quads_wanted().store(enabled, std::memory_order_relaxed); }
  // Without a sink, recording is counting: a caller may count n reads at once instead of
  // recording them one by one (only when sink() is null).
  void count_unrecorded(std::uint64_t n) { reads_ += n; }
  EventSink* sink() const { return sink_; }

 private:
  // texture | level | a zero byte | x | y, then pixel_x | pixel_y | triangle.
  static std::uint64_t head(const TexelSite& site, unsigned level, int x, int y) {
    return site.texture | std::uint64_t{static_cast<std::uint8_t>(level)} << 16 | xy(x, y);
  }
  static std::uint64_t xy(int x, int y) {
    return std::uint64_t{static_cast<std::uint16_t>(x)} << 32 | std::uint64_t{static_cast<std::uint16_t>(y)} << 48;
  }
  static std::uint64_t tail(const TexelSite& site) {
    return std::uint64_t{site.pixel_x} | std::uint64_t{site.pixel_y} << 16 | std::uint64_t{site.triangle} << 32;
  }
  static std::atomic<bool>& vector_quads_wanted() {
    static std::atomic<bool> wanted{true};
    return wanted;
  }
#if RASTRACE_TEXEL_QUAD_AVX2
  static bool vector_quads() {
    static const bool has_avx2 = (__builtin_cpu_init(), __builtin_cpu_supports("avx2"));
    return has_avx2 && vector_quads_wanted().load(std::memory_order_relaxed);
  }
  // record_quad() on a sink, in AVX2 and out of line: inlined into the quad loop, its vector code
  // made the untraced frames on every core 4-5% slower (the grazing plane's), though it never ran
  // there. Called, it costs little: the filter kernel's call just before has already spilled the
  // loop's vectors. Events are assembled by in-lane unpacks, with one lane-crossing step per
  // stored vector, in straight-line code: written with generic shuffles, GCC kept the 4x4
  // transposition on the stack and looped over the pixels, and the grazing plane's traced frame
  // cost 4-6% more.
  template <bool kTwoLevels>
  [[gnu::noinline]] __attribute__((target("avx2"))) void record_quad_avx2(const TexelSite& site, unsigned level, int qx,
                                                                          int qy, const Lanes& x0, const Lanes& x1,
                                                                          const Lanes& y0, const Lanes& y1) {
    constexpr int kLevels = kTwoLevels ? 2 : 1;
    reads_ += 16 * kLevels;
    const __m256i low16 = _mm256_set1_epi32(0xFFFF);
    const __m256i ux0 = _mm256_and_si256(reinterpret_cast<__m256i>(x0), low16);
    const __m256i ux1 = _mm256_and_si256(reinterpret_cast<__m256i>(x1), low16);
    const __m256i uy0 = _mm256_slli_epi32(reinterpret_cast<__m256i>(y0), 16);
    const __m256i uy1 = _mm256_slli_epi32(reinterpret_cast<__m256i>(y1), 16);
    // Word 1 (x | y << 16) of footprint texel k, lane j (pixel j & 3, level j >> 2).
    const __m256i xy[4] = {_mm256_or_si256(ux0, uy0), _mm256_or_si256(ux1, uy0), _mm256_or_si256(ux0, uy1),
                           _mm256_or_si256(ux1, uy1)};
    // Word 0 (texture, level) of each lane: the low half's level, then the high half's; words 2
    // and 3 (pixel, triangle) of pixels 0 and 1, then 2 and 3, in each half.
    const auto w0 = static_cast<int>(head(site, level, 0, 0));
    const auto w0_next = static_cast<int>(head(site, level + 1, 0, 0));
    const __m256i texture_level = _mm256_setr_epi32(w0, w0, w0, w0, w0_next, w0_next, w0_next, w0_next);
    const __m256i pixel_x =
        _mm256_and_si256(_mm256_add_epi32(_mm256_set1_epi32(qx), _mm256_setr_epi32(0, 1, 0, 1, 0, 1, 0, 1)), low16);
    const __m256i pixel_y =
        _mm256_slli_epi32(_mm256_add_epi32(_mm256_set1_epi32(qy), _mm256_setr_epi32(0, 0, 1, 1, 0, 0, 1, 1)), 16);
    const __m256i pixel = _mm256_or_si256(pixel_x, pixel_y);
    const __m256i triangle = _mm256_set1_epi32(static_cast<int>(site.triangle));
    const __m256i tail01 = _mm256_unpacklo_epi32(pixel, triangle), tail23 = _mm256_unpackhi_epi32(pixel, triangle);
    // Pixel p's event for texel k: `level`'s in the low half, level + 1's in the high half.
    __m256i head01[4], head23[4];
    for (int k = 0; k < 4; ++k) {
      head01[k] = _mm256_unpacklo_epi32(texture_level, xy[k]);
      head23[k] = _mm256_unpackhi_epi32(texture_level, xy[k]);
    }
    // Pixel p's events in order: texels 0-3 of `level`, then (kTwoLevels) texels 0-3 of level + 1.
    TexelAccess* out = window_.reserve_streamed(16 * kLevels);
    const QuadStores how = quad_stores(out);
    for (int p = 0; p < 4; ++p) {
      const __m256i* heads = p < 2 ? head01 : head23;
      const __m256i tail = p < 2 ? tail01 : tail23;
      __m256i k[4];
      for (int i = 0; i < 4; ++i)
        k[i] = p % 2 == 0 ? _mm256_unpacklo_epi64(heads[i], tail) : _mm256_unpackhi_epi64(heads[i], tail);
      const __m256i events[4] = {
          _mm256_permute2x128_si256(k[0], k[1], 0x20), _mm256_permute2x128_si256(k[2], k[3], 0x20),
          _mm256_permute2x128_si256(k[0], k[1], 0x31), _mm256_permute2x128_si256(k[2], k[3], 0x31)};
      store_vectors<2 * kLevels>(how, out + 4 * kLevels * p, events);
    }
    window_.stored();
  }
  // How record_quad_avx2 stores a quad's events, decided once per quad: streamed when the window
  // streams, 32 bytes a store where `out` allows it (the usual case: quads record even numbers of
  // events), else 16; or with ordinary stores.
  enum class QuadStores { Plain, Stream32, Stream16 };
  QuadStores quad_stores(const TexelAccess* out) const {
    if (!window_.streaming()) return QuadStores::Plain;
    const auto at = reinterpret_cast<std::uintptr_t>(out);
    return at % 32 == 0 ? QuadStores::Stream32 : at % 16 == 0 ? QuadStores::Stream16 : QuadStores::Plain;
  }
  // The first kCount of the vectors, two whole events each, into out[0..2 kCount).
  template <int kCount>
  [[gnu::always_inline]] __attribute__((target("avx2"))) static void store_vectors(QuadStores how, TexelAccess* out,
                                                                                   const __m256i (&events)[4]) {
    auto* to = reinterpret_cast<__m256i*>(out);
    switch (how) {
      case QuadStores::Stream32:
        for (int i = 0; i < kCount; ++i) _mm256_stream_si256(to + i, events[i]);
        return;
      case QuadStores::Stream16: {
        auto* halves = reinterpret_cast<__m128i*>(out);  // 16-byte aligned only: no __m256i pointer
        for (int i = 0; i < kCount; ++i) {
          _mm_stream_si128(halves + 2 * i, _mm256_castsi256_si128(events[i]));
          _mm_stream_si128(halves + 2 * i + 1, _mm256_extracti128_si256(events[i], 1));
        }
        return;
      }
      case QuadStores::Plain:
        break;
    }
    for (int i = 0; i < kCount; ++i) _mm256_storeu_si256(to + i, events[i]);
  }
#endif
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
  EventWindow<TexelAccess, kCapacity, 32> window_;  // 32: record_quad's slack
};

}  // namespace rastrace
