#include "traces/chunk_codec.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "core/function_clones.h"
#include "traces/append_bytes.h"
#include "traces/column_encoder.h"
#include "traces/texel_lanes.h"

namespace rastrace {

const char* to_string(RecordKind kind) {
  switch (kind) {
    case RecordKind::Vertex:
      return "vertex";
    case RecordKind::Texel:
      return "texel";
    case RecordKind::Framebuffer:
      return "framebuffer";
    default:
      return "address";
  }
}

namespace {

std::uint64_t unzigzag(std::uint64_t z) { return (z >> 1) ^ (~(z & 1) + 1); }

struct Cursor {
  const std::uint8_t* p;
  const std::uint8_t* end;
  std::string error;
  bool take(std::size_t n, const char* what) {
    if (static_cast<std::size_t>(end - p) < n) {
      if (error.empty()) error = std::string("record data ends inside the ") + what;
      return false;
    }
    return true;
  }
  template <typename T>
  T get(const char* what) {
    T value{};
    if (!take(sizeof(T), what)) return value;
    std::memcpy(&value, p, sizeof(T));
    p += sizeof(T);
    return value;
  }
};

// One column being decoded: its header is parsed (and its bytes checked to be there) before any
// record is decoded, so that the record loop below needs no bounds checks.
struct Column {
  const char* what = "";
  std::uint64_t limit = 0;
  std::uint8_t mode = 0;
  std::uint64_t value = 0;  // the last decoded value
  std::uint64_t all = 0;    // bitwise OR of every value: one range check per column
  const std::uint8_t* deltas = nullptr;
  const std::uint8_t* exceptions = nullptr;  // mode kEscapedBytes: the next escaped delta
  const std::uint8_t* exceptions_end = nullptr;
  bool overrun = false;  // more escapes than escaped deltas
  // Mode kRuns: the next run's length and the records left in the current run. The lengths are
  // checked to add up to the records when the column is opened, so decoding never runs out.
  const std::uint8_t* lengths = nullptr;
  std::uint64_t run_left = 0;
};

// Mode kRuns after its mode byte and first value: checks that the run lengths add up to the
// records and skips the column's bytes.
bool open_runs(Cursor& c, std::size_t n, const char* what, Column& col) {
  const std::uint32_t runs = c.get<std::uint32_t>(what);
  const std::uint32_t large = c.get<std::uint32_t>(what);
  if (!c.error.empty()) return false;
  if (n == 0 || runs == 0 || runs > n || large >= runs) {
    c.error = std::to_string(runs) + " runs with " + std::to_string(large) + " escaped deltas for " +
              std::to_string(n) + " records in the " + what + " column (expected 1 to " + std::to_string(n) +
              " runs, fewer escapes)";
    return false;
  }
  if (!c.take(std::size_t{runs} + (runs - 1) + std::size_t{large} * 8, what)) return false;
  // The lengths' sum and whether one is 0, eight bytes at a time.
  std::uint64_t total = 0, zero_bytes = 0;
  std::uint32_t r = 0;
  for (; r + 8 <= runs; r += 8) {
    std::uint64_t eight;
    std::memcpy(&eight, c.p + r, 8);
    zero_bytes |= (eight - 0x0101010101010101ull) & ~eight & 0x8080808080808080ull;
    const std::uint64_t pairs = (eight & 0x00FF00FF00FF00FFull) + ((eight >> 8) & 0x00FF00FF00FF00FFull);
    total += (pairs * 0x0001000100010001ull) >> 48;  // the four 16-bit sums, added in the top lanes
  }
  bool empty_run = zero_bytes != 0;
  for (; r < runs; ++r) {
    total += c.p[r];
    empty_run |= c.p[r] == 0;
  }
  if (empty_run || total != n) {
    c.error = std::string("run lengths ") + (empty_run ? "include 0" : "add up to " + std::to_string(total)) + " for " +
              std::to_string(n) + " records in the " + what + " column";
    return false;
  }
  col.lengths = c.p + 1;
  col.run_left = c.p[0] - 1u;  // record 0, the column's first value, is decoded by the caller
  col.deltas = c.p + runs;
  col.exceptions = col.deltas + (runs - 1);
  col.exceptions_end = col.exceptions + std::size_t{large} * 8;
  c.p = col.exceptions_end;
  return true;
}

// Reads a column's header and skips its bytes; false (with c.error) when they are not all there.
// Mode kRuns is valid only where `runs` (trace version 4 on).
bool open_column(Cursor& c, std::size_t n, std::uint64_t limit, const char* what, Column& col, bool runs) {
  col.what = what;
  col.limit = limit;
  col.mode = c.get<std::uint8_t>(what);
  col.value = c.get<std::uint64_t>(what);
  col.all = n ? col.value : 0;  // no records, no values to check
  if (!c.error.empty()) return false;
  const std::uint8_t m = col.mode;
  if (m == kRuns && runs) return open_runs(c, n, what, col);
  if (m != 0 && m != 1 && m != 2 && m != 4 && m != 8 && m != kEscapedBytes) {
    c.error = std::string("bad column width ") + std::to_string(m) + " in the " + what + " column";
    return false;
  }
  if (m == kEscapedBytes) {
    const std::uint32_t large = c.get<std::uint32_t>(what);
    if (!c.error.empty()) return false;
    if (n == 0) return true;
    if (!c.take((n - 1) + std::size_t{large} * 8, what)) return false;
    col.deltas = c.p;
    col.exceptions = c.p + (n - 1);
    col.exceptions_end = col.exceptions + std::size_t{large} * 8;
    c.p = col.exceptions_end;
    return true;
  }
  if (n == 0) return true;
  if (!c.take((n - 1) * m, what)) return false;
  col.deltas = c.p;
  c.p += (n - 1) * m;
  return true;
}

// What went wrong in a decoded column, or "".
std::string column_error(const Column& col) {
  if ((col.mode == kEscapedBytes || col.mode == kRuns) && (col.overrun || col.exceptions != col.exceptions_end))
    return std::string("escaped deltas do not match their escapes in the ") + col.what + " column";
  if (col.all > col.limit)
    return std::string("a value in the ") + col.what + " column is out of range (at most " + std::to_string(col.limit) +
           ")";
  return "";
}

// Eight zig-zag coded 1-byte deltas, unpacked all at once into eight signed bytes.
inline std::uint64_t unzigzag8(std::uint64_t eight) {
  return ((eight >> 1) & 0x7F7F7F7F7F7F7F7Full) ^ ((eight & 0x0101010101010101ull) * 0xFF);
}

// Where a column's decoded values go: FieldOut into one field of an array of records, LaneOut
// into a contiguous lane (texel chunks, see decode_lane).
template <typename Record, typename Field, Field Record::*member>
struct FieldOut {
  Record* out;
  void set(std::size_t i, std::uint64_t value) const { out[i].*member = static_cast<Field>(value); }
};
struct LaneOut {
  std::uint32_t* lane;
  void set(std::size_t i, std::uint64_t value) const { lane[i] = static_cast<std::uint32_t>(value); }
};

// Adds eight deltas (signed bytes of `deltas`) to the running value, storing each sum at i..i+7.
template <typename Out>
inline void add8(std::uint64_t deltas, std::uint64_t& value, std::uint64_t& all, Out out, std::size_t i) {
  for (int k = 0; k < 8; ++k) {
    value += static_cast<std::uint64_t>(static_cast<std::int64_t>(static_cast<std::int8_t>(deltas >> (8 * k))));
    all |= value;
    out.set(i + k, value);
  }
}

template <int W, typename Out>
void decode_fixed(Column& col, Out out, std::size_t begin, std::size_t end) {
  std::uint64_t value = col.value, all = col.all;
  const std::uint8_t* p = col.deltas;
  std::size_t i = begin;
  if constexpr (W == 1) {
    for (; i + 8 <= end; i += 8, p += 8) {
      std::uint64_t eight;
      std::memcpy(&eight, p, 8);
      add8(unzigzag8(eight), value, all, out, i);
    }
  }
  for (; i < end; ++i, p += W) {
    std::uint64_t z = 0;
    std::memcpy(&z, p, W);
    value += unzigzag(z);
    all |= value;
    out.set(i, value);
  }
  col.value = value;
  col.all = all;
  col.deltas = p;
}

// A 1-byte zig-zag delta of mode 0x81 or 0x82, or for the escape 0xFF the column's next escaped
// delta (none left: overrun, reported after the column).
inline std::uint64_t full_delta(Column& col, std::uint64_t z) {
  if (z == 0xFF) [[unlikely]] {
    if (col.exceptions == col.exceptions_end) {
      col.overrun = true;
      return 0;
    }
    std::memcpy(&z, col.exceptions, 8);
    col.exceptions += 8;
  }
  return z;
}

// Whether the eight bytes at p hold an escape (0xFF) of mode 0x81.
inline bool has_escape(const std::uint8_t* p) {
  std::uint64_t eight;
  std::memcpy(&eight, p, 8);
  const std::uint64_t inverted = ~eight;  // an escape becomes a zero byte
  return ((inverted - 0x0101010101010101ull) & ~inverted & 0x8080808080808080ull) != 0;
}

template <typename Out>
void decode_escaped(Column& col, Out out, std::size_t begin, std::size_t end) {
  std::uint64_t value = col.value, all = col.all;
  const std::uint8_t* p = col.deltas;
  const auto step = [&](std::size_t i) {
    value += unzigzag(full_delta(col, p[i - begin]));
    all |= value;
    out.set(i, value);
  };
  std::size_t i = begin;
  for (; i + 8 <= end; i += 8) {
    if (has_escape(p + (i - begin))) [[unlikely]] {
      for (int k = 0; k < 8; ++k) step(i + k);
      continue;
    }
    std::uint64_t eight;
    std::memcpy(&eight, p + (i - begin), 8);
    add8(unzigzag8(eight), value, all, out, i);  // the common case: no escape
  }
  for (; i < end; ++i) step(i);
  col.value = value;
  col.all = all;
  col.deltas = p + (end - begin);
}

template <typename Out>
void decode_runs(Column& col, Out out, std::size_t begin, std::size_t end) {
  std::uint64_t value = col.value, all = col.all, left = col.run_left;
  const auto next_run = [&] {  // open_runs checked that the lengths cover every record
    left = *col.lengths++;
    value += unzigzag(full_delta(col, *col.deltas++));
    all |= value;
  };
  std::size_t i = begin;
  // Eight records at a time whatever the run's length: the stores past a short run's end are
  // overwritten by the runs after it (all before `end`), and no loop exit depends on the length.
  while (i + 8 <= end) {
    if (left == 0) next_run();
    for (int k = 0; k < 8; ++k) out.set(i + k, value);
    const std::uint64_t step = std::min<std::uint64_t>(left, 8);
    i += step;
    left -= step;
  }
  while (i < end) {
    if (left == 0) next_run();
    const std::size_t stop = std::min<std::size_t>(end, i + left);
    left -= stop - i;
    for (; i < stop; ++i) out.set(i, value);
  }
  col.value = value;
  col.all = all;
  col.run_left = left;
}

// Decodes records [begin, end) (begin >= 1) of one column into `out`.
template <typename Out>
void decode_into(Column& col, Out out, std::size_t begin, std::size_t end) {
  switch (col.mode) {
    case 0:
      for (std::size_t i = begin; i < end; ++i) out.set(i, col.value);
      break;
    case 1:
      decode_fixed<1>(col, out, begin, end);
      break;
    case 2:
      decode_fixed<2>(col, out, begin, end);
      break;
    case 4:
      decode_fixed<4>(col, out, begin, end);
      break;
    case 8:
      decode_fixed<8>(col, out, begin, end);
      break;
    case kRuns:
      decode_runs(col, out, begin, end);
      break;
    default:
      decode_escaped(col, out, begin, end);
      break;
  }
}

// Decodes records [begin, end) (begin >= 1) of one column into the field `member` of `out`.
template <typename Record, typename Field, Field Record::*member>
void decode_range(Column& col, Record* out, std::size_t begin, std::size_t end) {
  decode_into(col, FieldOut<Record, Field, member>{out}, begin, end);
}

// Records are decoded block by block, every column of a block before the next block, so the
// block (kBlock records of the output structs) stays in L1 while its fields are filled in.
constexpr std::size_t kBlock = 512;

// Texel chunks are decoded block by block into lanes, one contiguous uint32 array per column
// (texel_lanes.h), then interleaved into the records: each record is written once, and a
// run of equal values is a few wide stores, not a store per record into a field of the records.
// A lane has room for a run's fill to write past the block (kLaneFill values at a time).
constexpr std::size_t kLaneFill = 16;
constexpr std::size_t kLaneSlack = 256;  // the longest run, 255, rounded up to kLaneFill
constexpr std::size_t kLaneSize = kBlock + kLaneSlack;

// Stores kLaneFill copies of v (a few vector stores: the loop's count is fixed).
[[gnu::always_inline]] inline void fill_lane(std::uint32_t* p, std::uint32_t v) {
  for (std::size_t k = 0; k < kLaneFill; ++k) p[k] = v;
}

// Runs: the rest of the current run, then whole runs, each one fill of kLaneFill values (two
// 32-byte stores with AVX2), a few for the rare longer run; stores past a run's end are
// overwritten by the runs after it, or fall in the slack. One fill and a test, not a loop over
// the length: most runs of a rendered frame are 4 to 16 records, and the loop's setup cost about
// as much as the stores (texel column decoding 8% slower). The lengths were checked to add up to
// the records when the column was opened.
[[gnu::always_inline]] inline void decode_runs_lane(Column& col, std::uint32_t* lane, std::size_t count) {
  std::uint64_t value = col.value, all = col.all;
  const std::size_t rest = std::min<std::size_t>(col.run_left, count);
  for (std::size_t j = 0; j < rest; j += kLaneFill) fill_lane(lane + j, static_cast<std::uint32_t>(value));
  std::size_t i = rest;
  const std::uint8_t* lengths = col.lengths;
  const std::uint8_t* deltas = col.deltas;
  while (i < count) {
    const std::size_t length = *lengths++;
    value += unzigzag(full_delta(col, *deltas++));
    all |= value;
    const std::uint32_t v = static_cast<std::uint32_t>(value);
    fill_lane(lane + i, v);
    if (length > kLaneFill) [[unlikely]]
      for (std::size_t j = kLaneFill; j < length; j += kLaneFill) fill_lane(lane + i + j, v);
    i += length;
  }
  col.run_left = col.run_left - rest + (i - count);  // one of the two terms is 0
  col.lengths = lengths;
  col.deltas = deltas;
  col.value = value;
  col.all = all;
}

// 1-byte deltas (modes 1 and 0x81): eight records at a time by add_byte_deltas(), and by the
// scalar decoder the eight with an escape among them and the last records.
void decode_bytes_lane(Column& col, std::uint32_t* lane, std::size_t count) {
  const bool escapes = col.mode == kEscapedBytes;
  std::size_t i = 0;
  for (;;) {
    ByteDeltaSums sums{static_cast<std::uint32_t>(col.value)};
    const std::size_t done = add_byte_deltas(col.deltas, count - i, escapes, sums, lane + i);
    col.value = (col.value & ~std::uint64_t{0xFFFFFFFF}) | sums.value;  // exact while the value fits 32 bits
    col.all |= sums.left_32_bits ? ~std::uint64_t{0} : sums.ored;
    col.deltas += done;
    i += done;
    if (!escapes || i + 8 > count || !has_escape(col.deltas)) break;  // without AVX2: done = 0, no escape
    decode_into(col, LaneOut{lane}, i, i + 8);                        // an escape among the next eight
    i += 8;
  }
  decode_into(col, LaneOut{lane}, i, count);
}

// Decodes the column's next `count` records into lane[0..count) (the records of one block).
[[gnu::always_inline]] inline void decode_lane(Column& col, std::uint32_t* lane, std::size_t count) {
  switch (col.mode) {
    case 0:
      std::fill_n(lane, count, static_cast<std::uint32_t>(col.value));
      break;
    case kRuns:
      decode_runs_lane(col, lane, count);
      break;
    case 1:
    case kEscapedBytes:
      decode_bytes_lane(col, lane, count);
      break;
    default:
      decode_into(col, LaneOut{lane}, 0, count);
      break;
  }
}

// Decodes the first `decoded` columns of n texel records block by block into lanes and, unless
// `out` is null (a damaged chunk), interleaves them into out[0..n). AVX2 where the machine has
// it: a run's fill is then two 32-byte stores.
RASTRACE_CLONES("avx2", "default")
void decode_texel_blocks(Column* col, int decoded, bool details, TexelAccess* out, std::size_t n) {
  alignas(64) std::uint32_t lanes[7][kLaneSize];
  const TexelLanes block{lanes[0],
                         lanes[1],
                         lanes[2],
                         lanes[3],
                         details ? lanes[4] : nullptr,
                         details ? lanes[5] : nullptr,
                         details ? lanes[6] : nullptr};
  for (std::size_t begin = 0; begin < n; begin += kBlock) {
    const std::size_t count = std::min<std::size_t>(n - begin, kBlock);
    const std::size_t first = begin == 0;  // record 0 is every column's first value
    for (int k = 0; k < decoded; ++k) {
      if (first) lanes[k][0] = static_cast<std::uint32_t>(col[k].value);
      decode_lane(col[k], lanes[k] + first, count - first);
    }
    if (out) interleave_texels(block, count, out + begin);
  }
}

}  // namespace

namespace {
// Fields of every record, gathered into lanes for the column encoder (column_encoder.h), one lane
// per field, in one pass over the records. The lanes are in `storage`, overwritten by the next
// gather.
template <typename Record, typename... Field>
std::array<std::span<const std::uint32_t>, sizeof...(Field)> gather(std::vector<std::uint32_t>& storage,
                                                                    std::span<const Record> records, Field... field) {
  constexpr std::size_t kLanes = sizeof...(Field);
  const std::size_t n = records.size();
  storage.resize(kLanes * n);
  std::uint32_t* const lanes = storage.data();
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t lane = 0;
    ((lanes[lane++ * n + i] = field(records[i])), ...);
  }
  std::array<std::span<const std::uint32_t>, kLanes> spans;
  for (std::size_t lane = 0; lane < kLanes; ++lane) spans[lane] = {lanes + lane * n, n};
  return spans;
}
}  // namespace

void encode_vertex_records(const DrawInfo& draw, std::span<const VertexFetch> f, std::string& raw,
                           ColumnScratch& scratch) {
  raw.clear();
  append_bytes<std::uint32_t>(raw, draw.draw);
  const bool strip = draw.type == PrimitiveType::TriangleStrip;
  const bool restarts = strip && draw.restart_index.has_value();
  append_bytes<std::uint8_t>(raw, static_cast<std::uint8_t>(static_cast<std::uint8_t>(draw.type) |
                                                            (strip && !restarts ? kStripWithoutRestart : 0)));
  append_bytes<std::uint32_t>(raw, restarts ? *draw.restart_index : kStripRestart);
  put_column(raw, gather(scratch.lanes, f, [](const VertexFetch& r) { return r.vertex; })[0], scratch);
  const std::size_t start = raw.size();
  raw.resize(start + (f.size() + 7) / 8, 0);
  char* bitmap = raw.data() + start;
  for (std::size_t i = 0; i < f.size(); ++i)
    bitmap[i / 8] = static_cast<char>(bitmap[i / 8] | (f[i].primitive_start << (i % 8)));
}

void encode_texel_records(std::span<const TexelAccess> t, std::string& raw, ColumnScratch& scratch) {
  // The records as the writer's open chunk holds them, in the scratch's lane storage (borrowed).
  TexelColumns columns;
  std::swap(columns.lanes, scratch.lanes);
  columns.reset(t.size());
  columns.append(t);
  encode_texel_records(columns, raw, scratch);
  std::swap(columns.lanes, scratch.lanes);
}

void encode_texel_records(const TexelColumns& texels, std::string& raw, ColumnScratch& scratch) {
  raw.clear();
  for (std::size_t k = 0; k < TexelColumns::kFields; ++k) put_column(raw, texels.field(k), scratch);
}

void encode_address_records(std::span<const AddressAccess> a, std::string& raw, ColumnScratch& scratch) {
  raw.clear();
  scratch.wide_lane.resize(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) scratch.wide_lane[i] = a[i].address;
  put_column(raw, scratch.wide_lane, scratch);
  put_column(raw, gather(scratch.lanes, a, [](const AddressAccess& r) { return std::uint32_t{r.label}; })[0], scratch);
}

void encode_framebuffer_records(std::span<const FramebufferAccess> f, std::string& raw, ColumnScratch& scratch) {
  raw.clear();
  const auto lanes = gather(
      scratch.lanes, f, [](const FramebufferAccess& r) { return std::uint32_t{r.x}; },
      [](const FramebufferAccess& r) { return std::uint32_t{r.y}; },
      [](const FramebufferAccess& r) { return std::uint32_t{static_cast<std::uint8_t>(r.op)}; },
      [](const FramebufferAccess& r) { return std::uint32_t{r.mask}; },
      [](const FramebufferAccess& r) { return r.triangle; });
  for (const std::span<const std::uint32_t> lane : lanes) put_column(raw, lane, scratch);
}

namespace {
ColumnScratch& thread_scratch() {
  thread_local ColumnScratch scratch;
  return scratch;
}
}  // namespace

void encode_vertex_records(const DrawInfo& draw, std::span<const VertexFetch> fetches, std::string& raw) {
  encode_vertex_records(draw, fetches, raw, thread_scratch());
}
void encode_texel_records(std::span<const TexelAccess> texels, std::string& raw) {
  encode_texel_records(texels, raw, thread_scratch());
}
void encode_address_records(std::span<const AddressAccess> addresses, std::string& raw) {
  encode_address_records(addresses, raw, thread_scratch());
}
void encode_framebuffer_records(std::span<const FramebufferAccess> accesses, std::string& raw) {
  encode_framebuffer_records(accesses, raw, thread_scratch());
}

std::string decode_vertex_records(std::span<const std::uint8_t> raw, std::uint32_t n, DrawInfo& draw,
                                  std::vector<VertexFetch>& out, bool runs) {
  Cursor c{raw.data(), raw.data() + raw.size(), {}};
  draw.draw = c.get<std::uint32_t>("draw header");
  const std::uint8_t type_byte = c.get<std::uint8_t>("draw header");
  const std::uint32_t restart = c.get<std::uint32_t>("draw header");
  if (!c.error.empty()) return c.error;
  const std::uint8_t type = type_byte & static_cast<std::uint8_t>(~kStripWithoutRestart);
  if (type > 2 || (type_byte != type && type != 1))
    return "unknown primitive type byte " + std::to_string(type_byte) + " (expected 0, 1, 2 or 129)";
  draw.type = static_cast<PrimitiveType>(type);
  // Files written before the flag existed store every strip's restart index, 0xFFFFFFFF included.
  draw.restart_index = type == 1 && type_byte == type ? RestartIndex{restart} : kNoRestart;
  // Allocate only once the bytes for n records are known to be there (the column, the bitmap):
  // a damaged count must not cost gigabytes before the error.
  Column vertex;
  if (!open_column(c, n, 0xFFFFFFFFu, "vertex", vertex, runs)) return c.error;
  if (!c.take((n + 7) / 8, "primitive start bitmap")) return c.error;
  out.resize(n);
  VertexFetch* f = out.data();
  if (n > 0) {
    f[0].vertex = static_cast<std::uint32_t>(vertex.value);
    decode_range<VertexFetch, std::uint32_t, &VertexFetch::vertex>(vertex, f, 1, n);
  }
  if (std::string error = column_error(vertex); !error.empty()) return error;
  for (std::size_t i = 0; i < n; ++i) f[i].primitive_start = (c.p[i / 8] >> (i % 8)) & 1;
  c.p += (n + 7) / 8;
  if (c.p != c.end) return "unexpected bytes after the records";
  return "";
}

std::string decode_texel_records(std::span<const std::uint8_t> raw, std::uint32_t n, std::vector<TexelAccess>& out,
                                 bool details, bool runs) {
  Cursor c{raw.data(), raw.data() + raw.size(), {}};
  Column col[7];
  // TexelAccess's field widths: 16 bits but for the level (8) and the triangle (32).
  const std::uint64_t limits[7] = {0xFFFFu, 0xFFu, 0xFFFFu, 0xFFFFu, 0xFFFFu, 0xFFFFu, 0xFFFFFFFFu};
  const char* names[7] = {"texture", "level", "x", "y", "pixel x", "pixel y", "triangle"};
  // Columns after a damaged header are not decoded; the ones before it are, and their errors
  // come first (the order a column-by-column decoder would report them in).
  int opened = 0;
  while (opened < 7 && open_column(c, n, limits[opened], names[opened], col[opened], runs)) ++opened;
  const bool all = opened == 7;
  if (opened == 0) return c.error;
  out.resize(n);  // after the headers: their bytes are there (see decode_vertex_records)
  // Without details only the address columns are decoded (and checked): at most the first four.
  // A damaged chunk (not all columns opened) is decoded for its errors only, never interleaved.
  const int decoded = details ? opened : std::min(opened, 4);
  decode_texel_blocks(col, decoded, details, all ? out.data() : nullptr, n);
  for (int k = 0; k < decoded; ++k)
    if (std::string error = column_error(col[k]); !error.empty()) return error;
  if (!all) return c.error;
  if (c.p != c.end) return "unexpected bytes after the records";
  return "";
}

std::string decode_framebuffer_records(std::span<const std::uint8_t> raw, std::uint32_t n,
                                       std::vector<FramebufferAccess>& out, bool runs) {
  Cursor c{raw.data(), raw.data() + raw.size(), {}};
  Column col[5];
  // Range checks OR every value of a column, so limits are all-ones masks; the operation's
  // exact range (0..kFramebufferOps-1) is checked record by record below.
  const std::uint64_t limits[5] = {0xFFFFu, 0xFFFFu, 0x3u, 0xFu, 0xFFFFFFFFu};
  const char* names[5] = {"x", "y", "operation", "mask", "triangle"};
  for (int k = 0; k < 5; ++k)
    if (!open_column(c, n, limits[k], names[k], col[k], runs)) return c.error;
  out.resize(n);  // after the headers: their bytes are there (see decode_vertex_records)
  FramebufferAccess* f = out.data();
  if (n > 0) {
    f[0].x = static_cast<std::uint16_t>(col[0].value);
    f[0].y = static_cast<std::uint16_t>(col[1].value);
    f[0].op = static_cast<FramebufferOp>(static_cast<std::uint8_t>(col[2].value));
    f[0].mask = static_cast<std::uint8_t>(col[3].value);
    f[0].triangle = static_cast<std::uint32_t>(col[4].value);
  }
  for (std::size_t begin = 1; begin < n; begin += kBlock) {
    const std::size_t end = std::min<std::size_t>(n, begin + kBlock);
    decode_range<FramebufferAccess, std::uint16_t, &FramebufferAccess::x>(col[0], f, begin, end);
    decode_range<FramebufferAccess, std::uint16_t, &FramebufferAccess::y>(col[1], f, begin, end);
    decode_range<FramebufferAccess, FramebufferOp, &FramebufferAccess::op>(col[2], f, begin, end);
    decode_range<FramebufferAccess, std::uint8_t, &FramebufferAccess::mask>(col[3], f, begin, end);
    decode_range<FramebufferAccess, std::uint32_t, &FramebufferAccess::triangle>(col[4], f, begin, end);
  }
  for (int k = 0; k < 5; ++k)
    if (std::string error = column_error(col[k]); !error.empty()) return error;
  for (std::size_t i = 0; i < n; ++i)
    if (static_cast<std::uint8_t>(f[i].op) >= kFramebufferOps)
      return "operation " + std::to_string(static_cast<int>(f[i].op)) + " in record " + std::to_string(i) +
             ": expected 0 (depth read), 1 (depth write) or 2 (colour write)";
  if (c.p != c.end) return "unexpected bytes after the records";
  return "";
}

std::string decode_address_records(std::span<const std::uint8_t> raw, std::uint32_t n, std::vector<AddressAccess>& out,
                                   bool runs) {
  Cursor c{raw.data(), raw.data() + raw.size(), {}};
  Column address, label;
  if (!open_column(c, n, ~std::uint64_t{0}, "address", address, runs)) return c.error;
  const bool both = open_column(c, n, 0xFFu, "label", label, runs);
  out.resize(n);  // after the headers: their bytes are there (see decode_vertex_records)
  AddressAccess* a = out.data();
  if (n > 0) a[0] = {address.value, static_cast<std::uint8_t>(label.value)};
  for (std::size_t begin = 1; begin < n; begin += kBlock) {
    const std::size_t end = std::min<std::size_t>(n, begin + kBlock);
    decode_range<AddressAccess, std::uint64_t, &AddressAccess::address>(address, a, begin, end);
    if (both) decode_range<AddressAccess, std::uint8_t, &AddressAccess::label>(label, a, begin, end);
  }
  if (std::string error = column_error(address); !error.empty()) return error;
  if (!both) return c.error;
  if (std::string error = column_error(label); !error.empty()) return error;
  if (c.p != c.end) return "unexpected bytes after the records";
  return "";
}

}  // namespace rastrace
