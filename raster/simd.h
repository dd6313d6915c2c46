// Four-lane vectors for the quad stage, in GCC's vector extensions (GCC and clang both accept
// them): a lane per pixel of a 2x2 quad, or a lane per channel of an RGBA colour. The compiler
// maps them to the target's SIMD registers (two SSE2 registers for the 64-bit lanes on baseline
// x86-64), with no intrinsics to keep per instruction set.
//
// Every operation here is lane-wise and the same IEEE operation the scalar code performs on one
// value, in the same order: the vector code gives the scalar code's results bit for bit (the
// build does not contract a*b+c into fused multiply-adds: C++20 without GNU extensions, and
// baseline x86-64 has no FMA). A scalar operand of a binary operation is broadcast to every lane.
// No function here returns a 64-bit-lane vector: without AVX that return would change the ABI.
#pragma once

#include <cstdint>
#include <cstring>

namespace rastrace::simd {

using f32x4 = float __attribute__((vector_size(16)));
using i32x4 = std::int32_t __attribute__((vector_size(16)));
using i64x4 = std::int64_t __attribute__((vector_size(32)));

inline f32x4 splat(float x) { return f32x4{x, x, x, x}; }
inline i32x4 splat(std::int32_t x) { return i32x4{x, x, x, x}; }

// Bit i set where lane i is >= 0.
inline unsigned non_negative_mask(const i64x4& v) {
  const i64x4 sign = v >> 63;  // 0 or -1
  return static_cast<unsigned>((~sign[0] & 1) | (~sign[1] & 2) | (~sign[2] & 4) | (~sign[3] & 8));
}

// The number of bits set in a 4-bit lane mask, from a table: baseline x86-64 has no popcnt
// instruction, and std::popcount there is a call into libgcc.
// The table has static storage: a local constexpr array indexed at run time was copied onto the
// stack at every call.
inline constexpr unsigned char kLanesSet[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
inline unsigned lanes_set(unsigned mask) { return kLanesSet[mask & 15u]; }

// Bit i set where lane i of a comparison's result is true (-1).
inline unsigned lanes_true(i32x4 comparison) {
  return static_cast<unsigned>((comparison[0] & 1) | (comparison[1] & 2) | (comparison[2] & 4) | (comparison[3] & 8));
}
// The inverse: lane i is -1 where bit i of `mask` is set, else 0.
inline i32x4 lanes_of(unsigned mask) {
  const i32x4 bits{1, 2, 4, 8};
  return (splat(static_cast<std::int32_t>(mask)) & bits) != splat(0);
}

// static_cast<float> of each lane (one cvtsi2ss per lane on SSE2: exact as the scalar cast).
inline f32x4 to_float(const i64x4& v) { return __builtin_convertvector(v, f32x4); }
inline f32x4 to_float(i32x4 v) { return __builtin_convertvector(v, f32x4); }
// static_cast<int> of each lane (truncation); lanes must be within the int range.
inline i32x4 truncate(f32x4 v) { return __builtin_convertvector(v, i32x4); }

// floor() of lanes with |u| < 2^31, as the scalar sampler's floor_int.
inline i32x4 floor_int(f32x4 u) {
  const i32x4 i = truncate(u);
  return i + (to_float(i) > u);  // a true comparison is -1
}

// std::clamp(v, lo, hi) per lane: lo below lo, hi above hi, else v (NaN stays NaN).
inline f32x4 clamp(f32x4 v, float lo, float hi) {
  const f32x4 low = splat(lo), high = splat(hi);
  return v < low ? low : (high < v ? high : v);
}
inline i32x4 clamp(i32x4 v, std::int32_t lo, std::int32_t hi) {
  const i32x4 low = splat(lo), high = splat(hi);
  return v < low ? low : (high < v ? high : v);
}

// 0 where a lane is infinite or NaN, else the lane (x - x is 0 only for finite x).
inline f32x4 finite_or_zero(f32x4 v) { return (v - v) == splat(0.0f) ? v : splat(0.0f); }

// The four bytes of an RGBA8 texel as floats 0..255.
inline f32x4 bytes_to_float(const std::uint8_t* p) {
  return f32x4{static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]), static_cast<float>(p[3])};
}

}  // namespace rastrace::simd
