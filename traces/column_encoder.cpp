#include "traces/column_encoder.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "core/function_clones.h"
#include "traces/append_bytes.h"

namespace rastrace {

namespace {

// Runs pay only where they average this many records or more: shorter ones save zstd little and
// cost the decoder a run's overhead every record or two.
constexpr std::uint64_t kShortestAverageRun = 4;

inline std::uint64_t zigzag(std::uint64_t delta) {  // delta is a two's complement difference
  return (delta << 1) ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(delta) >> 63);
}

// The zig-zag delta from record i - 1's value to record i's.
template <typename T>
inline std::uint64_t delta_at(const T* v, std::size_t i) {
  return zigzag(std::uint64_t{v[i]} - std::uint64_t{v[i - 1]});
}

struct DeltaCounts {
  std::uint64_t widest = 0;   // the OR of every zig-zag delta: the fixed width they need
  std::uint64_t large = 0;    // deltas of 0xFF or more, escaped in modes 0x81 and 0x82
  std::uint64_t changes = 0;  // deltas other than 0: each starts a run
  bool small_steps = false;   // every delta lies in int32's range: 32-bit arithmetic is exact
};

template <typename T>
[[gnu::always_inline]] inline DeltaCounts count_deltas_of(const T* v, std::size_t n) {
  std::uint64_t widest = 0, large = 0, changes = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const std::uint64_t z = delta_at(v, i);
    widest |= z;
    large += z >= 0xFF;
    changes += z != 0;
  }
  return {widest, large, changes, false};
}

// The zig-zag delta in 32 bits: exact where the delta lies in int32's range.
inline std::uint32_t zigzag32(std::uint32_t delta) {
  return (delta << 1) ^ static_cast<std::uint32_t>(static_cast<std::int32_t>(delta) >> 31);
}

// The counts in 32-bit lanes, twice as many to a vector, beside the values' range: where it spans
// less than 2^31 (texel and pixel coordinates, triangle and texture numbers do) every delta is in
// int32's range and the counts are exact; elsewhere they are counted again in 64 bits.
[[gnu::always_inline]] inline DeltaCounts count_deltas_of(const std::uint32_t* v, std::size_t n) {
  if (n < 2) return {};
  std::uint32_t widest = 0, large = 0, changes = 0, lowest = v[0], highest = v[0];
  for (std::size_t i = 1; i < n; ++i) {
    const std::uint32_t z = zigzag32(v[i] - v[i - 1]);
    widest |= z;
    large += z >= 0xFF;
    changes += z != 0;
    lowest = std::min(lowest, v[i]);
    highest = std::max(highest, v[i]);
  }
  if (highest - lowest >= 0x80000000u) return count_deltas_of<std::uint32_t>(v, n);
  return {widest, large, changes, true};
}

// Fixed-width deltas (modes 1, 2, 4 and 8), little endian: a delta's low bytes.
template <typename Z, typename T>
[[gnu::always_inline]] inline void put_fixed_of(char* out, const T* v, std::size_t n) {
  for (std::size_t i = 1; i < n; ++i) {
    Z z;
    if constexpr (sizeof(Z) <= 4 && sizeof(T) == 4) {
      // A delta whose zig-zag fits 4 bytes lies in int32's range, so 32-bit arithmetic gives the
      // same bytes, in twice the lanes.
      z = static_cast<Z>(zigzag32(v[i] - v[i - 1]));
    } else {
      z = static_cast<Z>(delta_at(v, i));
    }
    std::memcpy(out + (i - 1) * sizeof(Z), &z, sizeof(Z));
  }
}

template <typename T>
[[gnu::always_inline]] inline void put_fixed_width(char* out, const T* v, std::size_t n, std::uint8_t width) {
  switch (width) {
    case 1:
      put_fixed_of<std::uint8_t>(out, v, n);
      break;
    case 2:
      put_fixed_of<std::uint16_t>(out, v, n);
      break;
    case 4:
      put_fixed_of<std::uint32_t>(out, v, n);
      break;
    default:
      put_fixed_of<std::uint64_t>(out, v, n);
      break;
  }
}

// Mode 0x81's bytes: each delta, or 0xFF where it is escaped.
template <typename T>
[[gnu::always_inline]] inline void put_capped_bytes(char* out, const T* v, std::size_t n, bool small_steps) {
  if constexpr (sizeof(T) == 4) {
    if (small_steps) {
      for (std::size_t i = 1; i < n; ++i) out[i - 1] = static_cast<char>(std::min(zigzag32(v[i] - v[i - 1]), 0xFFu));
      return;
    }
  }
  for (std::size_t i = 1; i < n; ++i) out[i - 1] = static_cast<char>(std::min<std::uint64_t>(delta_at(v, i), 0xFF));
}

// The passes over every record, one copy per instruction set (the lanes are 32-bit values in all
// but the address column, where the plain copy does).
RASTRACE_CLONES("avx2", "default")
DeltaCounts count_deltas(const std::uint32_t* v, std::size_t n) { return count_deltas_of(v, n); }
DeltaCounts count_deltas(const std::uint64_t* v, std::size_t n) { return count_deltas_of(v, n); }
RASTRACE_CLONES("avx2", "default")
void put_fixed(char* out, const std::uint32_t* v, std::size_t n, std::uint8_t width) {
  put_fixed_width(out, v, n, width);
}
void put_fixed(char* out, const std::uint64_t* v, std::size_t n, std::uint8_t width) {
  put_fixed_width(out, v, n, width);
}
RASTRACE_CLONES("avx2", "default")
void put_capped(char* out, const std::uint32_t* v, std::size_t n, bool small_steps) {
  put_capped_bytes(out, v, n, small_steps);
}
void put_capped(char* out, const std::uint64_t* v, std::size_t n, bool small_steps) {
  put_capped_bytes(out, v, n, small_steps);
}

// One delta of modes 0x81 and 0x82: a byte, or 0xFF and the delta's 8 bytes at `exceptions`.
inline void put_escapable(char*& bytes, char*& exceptions, std::uint64_t z) {
  if (z < 0xFF) {
    *bytes++ = static_cast<char>(z);
    return;
  }
  *bytes++ = static_cast<char>(0xFF);
  std::memcpy(exceptions, &z, 8);
  exceptions += 8;
}

// Lists in change[0..) the records i >= 1 whose value differs from record i - 1's, in order,
// without a branch: in the columns that take runs a change comes every few records, at no
// pattern a branch predictor could learn. Returns how many. AVX2: eight records at a time, the
// changed ones packed by a permutation looked up from their mask.
std::size_t list_changes_portable(const std::uint32_t* v, std::size_t n, std::uint32_t* change, std::size_t i,
                                  std::size_t count) {
  for (; i < n; ++i) {
    change[count] = static_cast<std::uint32_t>(i);
    count += v[i] != v[i - 1];
  }
  return count;
}

#if defined(__x86_64__)
// kPack[mask]: the lanes of `mask`'s set bits, in order, as a permutation of eight 32-bit lanes.
constexpr auto kPack = [] {
  std::array<std::array<std::uint32_t, 8>, 256> pack{};
  for (unsigned mask = 0; mask < 256; ++mask) {
    unsigned k = 0;
    for (unsigned lane = 0; lane < 8; ++lane)
      if (mask >> lane & 1) pack[mask][k++] = lane;
  }
  return pack;
}();

__attribute__((target("avx2,popcnt"))) std::size_t list_changes_avx2(const std::uint32_t* v, std::size_t n,
                                                                     std::uint32_t* change) {
  std::size_t i = 1, count = 0;
  __m256i index = _mm256_setr_epi32(1, 2, 3, 4, 5, 6, 7, 8);
  const __m256i eight = _mm256_set1_epi32(8);
  for (; i + 8 <= n; i += 8) {
    const __m256i here = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(v + i));
    const __m256i before = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(v + i - 1));
    const unsigned same =
        static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(here, before))));
    const unsigned changed = ~same & 0xFFu;
    const __m256i order = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(kPack[changed].data()));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(change + count), _mm256_permutevar8x32_epi32(index, order));
    count += static_cast<std::size_t>(_mm_popcnt_u32(changed));
    index = _mm256_add_epi32(index, eight);
  }
  return list_changes_portable(v, n, change, i, count);
}
#endif

std::atomic<bool> g_simd{true};  // use_column_encoder_simd()

// `change` has room for n + 7 entries (the AVX2 loop stores eight at a time).
std::size_t list_changes(const std::uint32_t* v, std::size_t n, std::uint32_t* change) {
#if defined(__x86_64__)
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("popcnt");
  if (avx2 && g_simd.load(std::memory_order_relaxed)) return list_changes_avx2(v, n, change);
#endif
  return list_changes_portable(v, n, change, 1, 0);
}
std::size_t list_changes(const std::uint64_t* v, std::size_t n, std::uint32_t* change) {
  std::size_t count = 0;
  for (std::size_t i = 1; i < n; ++i) {
    change[count] = static_cast<std::uint32_t>(i);
    count += v[i] != v[i - 1];
  }
  return count;
}

// Mode kRuns: u32 runs | u32 escaped deltas | the runs' lengths (1 byte each, 1..255) | the deltas
// between consecutive runs' values (runs - 1 bytes, zig-zag, 0xFF escapes) | the escaped deltas (8
// bytes each). The first run's value is the column's first value; a stretch of equal values
// longer than a run continues in runs whose delta is 0. Fields that hold still for several
// records (the mip level of a bilinear footprint, a fragment's pixel and triangle over its
// texels) cost two bytes a run instead of one a record, and zstd has half as much to produce.
// The runs are found in one pass into scratch space, since whether they pay depends on how many
// there are; `large` is the column's count of escaped deltas.
// find_runs() returns the count of runs and leaves them in `bytes` (ColumnScratch::runs); the
// changes are listed in `changes` first.
template <typename T>
std::uint64_t find_runs(const T* v, std::size_t n, std::uint64_t large, std::vector<std::uint32_t>& changes,
                        std::vector<char>& bytes) {
  changes.resize(n + 8);
  const std::uint32_t* const change = changes.data();
  const std::size_t count = list_changes(v, n, changes.data());
  bytes.resize(2 * n + 8 * large);
  char* const first_length = bytes.data();
  char* lengths = first_length;
  char* deltas = first_length + n;
  char* exceptions = first_length + 2 * n;
  std::size_t start = 0;
  auto end_stretch = [&](std::size_t end) {  // records [start, end) hold one value
    std::uint64_t left = end - start;
    for (; left > kLongestRun; left -= kLongestRun) {
      *lengths++ = static_cast<char>(kLongestRun);
      *deltas++ = 0;
    }
    *lengths++ = static_cast<char>(left);
  };
  for (std::size_t c = 0; c < count; ++c) {
    const std::size_t i = change[c];
    end_stretch(i);
    put_escapable(deltas, exceptions, delta_at(v, i));
    start = i;
  }
  end_stretch(n);
  return static_cast<std::uint64_t>(lengths - first_length);
}

void put_runs(std::string& out, std::uint64_t first, std::size_t n, std::uint64_t large, std::uint64_t runs,
              const std::vector<char>& bytes) {
  out.push_back(static_cast<char>(kRuns));
  append_bytes<std::uint64_t>(out, first);
  append_bytes<std::uint32_t>(out, static_cast<std::uint32_t>(runs));
  append_bytes<std::uint32_t>(out, static_cast<std::uint32_t>(large));
  out.append(bytes.data(), runs);
  out.append(bytes.data() + n, runs - 1);
  out.append(bytes.data() + 2 * n, 8 * large);
}

// The column uses the cheapest of: fixed-width deltas (0, 1, 2, 4 or 8 bytes), 1-byte deltas
// where the rare large jump (a new texture row, a far vertex) escapes to an 8-byte delta stored
// after the bytes, or runs of equal values.
template <typename T>
void put_column_of(std::string& out, const T* v, std::size_t n, ColumnScratch& scratch) {
  const DeltaCounts counts = count_deltas(v, n);
  const std::uint64_t widest = counts.widest, large = counts.large;
  const std::uint8_t width = widest == 0               ? 0
                             : widest < 0x100          ? 1
                             : widest < 0x10000        ? 2
                             : widest < 0x100000000ull ? 4
                                                       : 8;
  const std::uint64_t deltas = n ? n - 1 : 0;
  const bool escaped = width > 1 && deltas + 4 + 8 * large < deltas * width;
  const std::uint64_t plain = escaped ? deltas + 4 + 8 * large : deltas * width;
  // Every escaped delta is a change, so it starts a run: runs hold the same escapes.
  auto runs_pay = [&](std::uint64_t runs) {
    return runs * kShortestAverageRun <= n && 8 + 2 * runs - 1 + 8 * large < plain;
  };
  // Splitting long stretches only adds runs, so the runs without splits (one per change) rule
  // most columns out before the runs are counted exactly.
  if (width != 0 && runs_pay(counts.changes + 1)) {
    const std::uint64_t runs = find_runs(v, n, large, scratch.changes, scratch.runs);
    if (runs_pay(runs)) {
      put_runs(out, v[0], n, large, runs, scratch.runs);
      return;
    }
  }
  out.push_back(static_cast<char>(escaped ? kEscapedBytes : width));
  append_bytes<std::uint64_t>(out, n ? std::uint64_t{v[0]} : 0);
  if (width == 0) return;
  if (escaped) {
    append_bytes<std::uint32_t>(out, static_cast<std::uint32_t>(large));
    const std::size_t start = out.size();
    out.resize(start + deltas + 8 * large);
    char* bytes = out.data() + start;
    put_capped(bytes, v, n, counts.small_steps);
    char* exceptions = bytes + deltas;
    for (std::uint64_t i = 1, left = large; left != 0; ++i) {
      const std::uint64_t z = delta_at(v, i);
      if (z < 0xFF) continue;
      std::memcpy(exceptions, &z, 8);
      exceptions += 8;
      --left;
    }
    return;
  }
  const std::size_t start = out.size();
  out.resize(start + deltas * width);
  put_fixed(out.data() + start, v, n, width);
}

// Positions, counts and the mode headers' fields are 32-bit.
void check_records(std::size_t n) {
  if (n > kMostColumnRecords)
    throw std::length_error("a trace column of " + std::to_string(n) + " records (at most " +
                            std::to_string(kMostColumnRecords) + ")");
}

}  // namespace

void put_column(std::string& out, std::span<const std::uint32_t> values, ColumnScratch& scratch) {
  check_records(values.size());
  put_column_of(out, values.data(), values.size(), scratch);
}

void put_column(std::string& out, std::span<const std::uint64_t> values, ColumnScratch& scratch) {
  check_records(values.size());
  put_column_of(out, values.data(), values.size(), scratch);
}

void use_column_encoder_simd(bool enabled) { g_simd.store(enabled, std::memory_order_relaxed); }

}  // namespace rastrace
