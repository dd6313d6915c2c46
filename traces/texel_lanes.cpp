#include "traces/texel_lanes.h"

#include <atomic>
#include <bit>
#include <cstddef>
#include <cstring>
#include <type_traits>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define RASTRACE_TEXEL_LANES_AVX2 1
#endif

namespace rastrace {
namespace {

// The record as four little-endian 32-bit words: texture and level (a zero byte after it) | x and
// y | pixel_x and pixel_y | triangle. Both paths below write exactly these bytes.
static_assert(std::is_trivially_copyable_v<TexelAccess> && sizeof(TexelAccess) == 16);
static_assert(offsetof(TexelAccess, texture) == 0 && offsetof(TexelAccess, level) == 2 &&
              offsetof(TexelAccess, x) == 4 && offsetof(TexelAccess, y) == 6 && offsetof(TexelAccess, pixel_x) == 8 &&
              offsetof(TexelAccess, pixel_y) == 10 && offsetof(TexelAccess, triangle) == 12);

void interleave_words(const TexelLanes& l, std::size_t begin, std::size_t count, TexelAccess* out) {
  for (std::size_t i = begin; i < count; ++i) {
    if constexpr (std::endian::native == std::endian::little) {
      const std::uint32_t words[4] = {
          (l.texture[i] & 0xFFFFu) | (l.level[i] & 0xFFu) << 16, (l.x[i] & 0xFFFFu) | l.y[i] << 16,
          l.pixel_x ? (l.pixel_x[i] & 0xFFFFu) | (l.pixel_y[i] << 16) : 0, l.triangle ? l.triangle[i] : 0};
      std::memcpy(static_cast<void*>(out + i), words, sizeof(words));
    } else {
      out[i] = TexelAccess{static_cast<std::uint16_t>(l.texture[i]),
                           static_cast<std::uint8_t>(l.level[i]),
                           static_cast<std::uint16_t>(l.x[i]),
                           static_cast<std::uint16_t>(l.y[i]),
                           static_cast<std::uint16_t>(l.pixel_x ? l.pixel_x[i] : 0),
                           static_cast<std::uint16_t>(l.pixel_y ? l.pixel_y[i] : 0),
                           l.triangle ? l.triangle[i] : 0};
    }
  }
}

void split_words(const TexelAccess* records, std::size_t begin, std::size_t count, std::uint32_t* lanes,
                 std::size_t stride) {
  for (std::size_t i = begin; i < count; ++i) {
    const TexelAccess& r = records[i];
    std::uint32_t* lane = lanes + i;
    lane[0] = r.texture;
    lane[stride] = r.level;
    lane[2 * stride] = r.x;
    lane[3 * stride] = r.y;
    lane[4 * stride] = r.pixel_x;
    lane[5 * stride] = r.pixel_y;
    lane[6 * stride] = r.triangle;
  }
}

#if RASTRACE_TEXEL_LANES_AVX2
__attribute__((target("avx2"))) inline __m256i load(const std::uint32_t* p) {
  return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
}

// Two 16-bit halves of each 32-bit lane: lo's low 16 bits, then hi's.
__attribute__((target("avx2"))) inline __m256i halves(__m256i lo, __m256i hi) {
  return _mm256_or_si256(_mm256_and_si256(lo, _mm256_set1_epi32(0xFFFF)), _mm256_slli_epi32(hi, 16));
}

// Records [0, returned) in groups of eight; the rest is interleave_words'.
__attribute__((target("avx2"))) std::size_t interleave_avx2(const TexelLanes& l, std::size_t count, TexelAccess* out) {
  const __m256i byte = _mm256_set1_epi32(0xFF), zero = _mm256_setzero_si256();
  const bool details = l.pixel_x != nullptr;
  std::size_t i = 0;
  for (; i + 8 <= count; i += 8) {
    // Word k of records 0-7, one record a lane.
    const __m256i a = halves(load(l.texture + i), _mm256_and_si256(load(l.level + i), byte));
    const __m256i b = halves(load(l.x + i), load(l.y + i));
    __m256i c = zero, d = zero;
    if (details) {
      c = halves(load(l.pixel_x + i), load(l.pixel_y + i));
      d = load(l.triangle + i);
    }
    // A 4x4 transposition within each 128-bit half: records 0-3 in the low halves, 4-7 in the high.
    const __m256i ab01 = _mm256_unpacklo_epi32(a, b), ab23 = _mm256_unpackhi_epi32(a, b);
    const __m256i cd01 = _mm256_unpacklo_epi32(c, d), cd23 = _mm256_unpackhi_epi32(c, d);
    const __m256i r0 = _mm256_unpacklo_epi64(ab01, cd01);  // record 0 | record 4
    const __m256i r1 = _mm256_unpackhi_epi64(ab01, cd01);  // record 1 | record 5
    const __m256i r2 = _mm256_unpacklo_epi64(ab23, cd23);  // record 2 | record 6
    const __m256i r3 = _mm256_unpackhi_epi64(ab23, cd23);  // record 3 | record 7
    auto* o = reinterpret_cast<__m256i*>(static_cast<void*>(out + i));
    _mm256_storeu_si256(o + 0, _mm256_permute2x128_si256(r0, r1, 0x20));
    _mm256_storeu_si256(o + 1, _mm256_permute2x128_si256(r2, r3, 0x20));
    _mm256_storeu_si256(o + 2, _mm256_permute2x128_si256(r0, r1, 0x31));
    _mm256_storeu_si256(o + 3, _mm256_permute2x128_si256(r2, r3, 0x31));
  }
  return i;
}

// The inverse, records [0, returned) in groups of eight into lanes `stride` apart; the rest is
// split_words'.
__attribute__((target("avx2"))) std::size_t split_avx2(const TexelAccess* records, std::size_t count,
                                                       std::uint32_t* lanes, std::size_t stride) {
  const __m256i low16 = _mm256_set1_epi32(0xFFFF), byte = _mm256_set1_epi32(0xFF);
  std::size_t i = 0;
  for (; i + 8 <= count; i += 8) {
    const auto* in = reinterpret_cast<const __m256i*>(static_cast<const void*>(records + i));
    const __m256i q0 = _mm256_loadu_si256(in + 0), q1 = _mm256_loadu_si256(in + 1);  // records 0|1, 2|3
    const __m256i q2 = _mm256_loadu_si256(in + 2), q3 = _mm256_loadu_si256(in + 3);  // records 4|5, 6|7
    const __m256i r0 = _mm256_permute2x128_si256(q0, q2, 0x20);                      // record 0 | record 4
    const __m256i r1 = _mm256_permute2x128_si256(q0, q2, 0x31);                      // record 1 | record 5
    const __m256i r2 = _mm256_permute2x128_si256(q1, q3, 0x20);                      // record 2 | record 6
    const __m256i r3 = _mm256_permute2x128_si256(q1, q3, 0x31);                      // record 3 | record 7
    // A 4x4 transposition within each 128-bit half: word k of records 0-7, one record a lane.
    const __m256i w01 = _mm256_unpacklo_epi32(r0, r1), w23 = _mm256_unpackhi_epi32(r0, r1);
    const __m256i v01 = _mm256_unpacklo_epi32(r2, r3), v23 = _mm256_unpackhi_epi32(r2, r3);
    const __m256i a = _mm256_unpacklo_epi64(w01, v01), b = _mm256_unpackhi_epi64(w01, v01);
    const __m256i c = _mm256_unpacklo_epi64(w23, v23), d = _mm256_unpackhi_epi64(w23, v23);
    const __m256i fields[kTexelLaneFields] = {_mm256_and_si256(a, low16),
                                              _mm256_and_si256(_mm256_srli_epi32(a, 16), byte),
                                              _mm256_and_si256(b, low16),
                                              _mm256_srli_epi32(b, 16),
                                              _mm256_and_si256(c, low16),
                                              _mm256_srli_epi32(c, 16),
                                              d};
    for (std::size_t k = 0; k < kTexelLaneFields; ++k)
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(lanes + k * stride + i), fields[k]);
  }
  return i;
}

// Eight records: the zig-zag bytes as signed 32-bit deltas, their prefix sums added to `base`
// (eight copies of the value before them) and stored; `base` moves on by the eight deltas' sum
// (found apart from it: one addition is all that each group waits for from the one before).
__attribute__((target("avx2"))) inline void add_eight(std::uint64_t zigzag, __m256i& base, __m256i& wrap, __m256i& ored,
                                                      std::uint32_t* lane) {
  const std::uint64_t signed_bytes =
      ((zigzag >> 1) & 0x7F7F7F7F7F7F7F7Full) ^ ((zigzag & 0x0101010101010101ull) * 0xFF);
  const __m256i d = _mm256_cvtepi8_epi32(_mm_cvtsi64_si128(static_cast<long long>(signed_bytes)));
  __m256i s = _mm256_add_epi32(d, _mm256_slli_si256(d, 4));  // prefix sums within each half
  s = _mm256_add_epi32(s, _mm256_slli_si256(s, 8));
  // The low half's total (its lane 3) added to the high half.
  s = _mm256_add_epi32(s, _mm256_shuffle_epi32(_mm256_permute2x128_si256(s, s, 0x08), 0xFF));
  const __m256i v = _mm256_add_epi32(base, s);
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(lane), v);
  // A step across 0 or 2^32: with 2^31 added to every value (which leaves their XORs alone) it
  // is a signed overflow of the value before plus the delta, whose sign bit is set in
  // (before ^ v) & ~(d ^ v).
  const __m256i before = _mm256_sub_epi32(v, d);
  wrap = _mm256_or_si256(wrap, _mm256_andnot_si256(_mm256_xor_si256(d, v), _mm256_xor_si256(before, v)));
  ored = _mm256_or_si256(ored, v);
  base = _mm256_add_epi32(base, _mm256_permutevar8x32_epi32(s, _mm256_set1_epi32(7)));
}

__attribute__((target("avx2"))) std::size_t add_byte_deltas_avx2(const std::uint8_t* deltas, std::size_t count,
                                                                 bool escapes, ByteDeltaSums& sums,
                                                                 std::uint32_t* lane) {
  __m256i base = _mm256_set1_epi32(static_cast<int>(sums.value));
  __m256i wrap = _mm256_setzero_si256(), ored = _mm256_setzero_si256();
  std::size_t i = 0;
  for (; i + 8 <= count; i += 8) {
    std::uint64_t eight;
    std::memcpy(&eight, deltas + i, 8);
    const std::uint64_t inverted = ~eight;  // an escape (0xFF) becomes a zero byte
    if (escapes && ((inverted - 0x0101010101010101ull) & ~inverted & 0x8080808080808080ull)) break;
    add_eight(eight, base, wrap, ored, lane + i);
  }
  sums.value = static_cast<std::uint32_t>(_mm256_cvtsi256_si32(base));
  // Bit 31 of `wrap`: some step crossed 0 or 2^32.
  sums.left_32_bits |= _mm256_movemask_ps(_mm256_castsi256_ps(wrap)) != 0;
  __m128i o = _mm_or_si128(_mm256_castsi256_si128(ored), _mm256_extracti128_si256(ored, 1));
  o = _mm_or_si128(o, _mm_shuffle_epi32(o, 0x4E));
  o = _mm_or_si128(o, _mm_shuffle_epi32(o, 0xB1));
  sums.ored |= static_cast<std::uint32_t>(_mm_cvtsi128_si32(o));
  return i;
}

std::atomic<bool> g_simd{true};  // use_texel_lane_simd()

bool has_avx2() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has && g_simd.load(std::memory_order_relaxed);
}
#endif

}  // namespace

std::size_t add_byte_deltas(const std::uint8_t* deltas, std::size_t count, bool escapes, ByteDeltaSums& sums,
                            std::uint32_t* lane) {
#if RASTRACE_TEXEL_LANES_AVX2
  if (has_avx2()) return add_byte_deltas_avx2(deltas, count, escapes, sums, lane);
#endif
  return 0;
}

void interleave_texels(const TexelLanes& lanes, std::size_t count, TexelAccess* out) {
  std::size_t done = 0;
#if RASTRACE_TEXEL_LANES_AVX2
  if constexpr (std::endian::native == std::endian::little)
    if (has_avx2()) done = interleave_avx2(lanes, count, out);
#endif
  interleave_words(lanes, done, count, out);
}

void split_texels(const TexelAccess* records, std::size_t count, std::uint32_t* lanes, std::size_t stride) {
  std::size_t done = 0;
#if RASTRACE_TEXEL_LANES_AVX2
  if constexpr (std::endian::native == std::endian::little)
    if (has_avx2()) done = split_avx2(records, count, lanes, stride);
#endif
  split_words(records, done, count, lanes, stride);
}

void split_texels_portable(const TexelAccess* records, std::size_t count, std::uint32_t* lanes, std::size_t stride) {
  split_words(records, 0, count, lanes, stride);
}

void use_texel_lane_simd(bool enabled) {
#if RASTRACE_TEXEL_LANES_AVX2
  g_simd.store(enabled, std::memory_order_relaxed);
#else
  (void)enabled;
#endif
}

void interleave_texels_portable(const TexelLanes& lanes, std::size_t count, TexelAccess* out) {
  interleave_words(lanes, 0, count, out);
}

}  // namespace rastrace
