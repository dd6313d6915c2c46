#include "traces/chunk_codec.h"

#include <cstring>

namespace rastrace {

const char* to_string(RecordKind kind) {
  switch (kind) {
    case RecordKind::Vertex: return "vertex";
    case RecordKind::Texel: return "texel";
    default: return "address";
  }
}

namespace {

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

std::uint64_t zigzag(std::uint64_t delta) {  // delta is a two's complement difference
  return (delta << 1) ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(delta) >> 63);
}
std::uint64_t unzigzag(std::uint64_t z) { return (z >> 1) ^ (~(z & 1) + 1); }

constexpr std::uint8_t kEscapedBytes = 0x81;  // column mode: 1-byte deltas, 0xFF escapes to 8 bytes

// Encodes one field of every record: get(i) is the field's value in record i. The column uses the
// cheapest of: fixed-width deltas (0, 1, 2, 4 or 8 bytes), or 1-byte deltas where the rare large
// jump (a new texture row, a far vertex) escapes to an 8-byte delta stored after the bytes.
template <typename Get>
void put_column(std::string& out, std::size_t n, Get get) {
  std::uint64_t widest = 0, large = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const std::uint64_t z = zigzag(get(i) - get(i - 1));
    widest |= z;
    large += z >= 0xFF;
  }
  const std::uint8_t width = widest == 0 ? 0 : widest < 0x100 ? 1 : widest < 0x10000 ? 2 : widest < 0x100000000ull ? 4 : 8;
  const std::uint64_t deltas = n ? n - 1 : 0;
  const bool escaped = width > 1 && deltas + 4 + 8 * large < deltas * width;
  out.push_back(static_cast<char>(escaped ? kEscapedBytes : width));
  put<std::uint64_t>(out, n ? get(0) : 0);
  if (width == 0) return;
  if (escaped) {
    put<std::uint32_t>(out, static_cast<std::uint32_t>(large));
    const std::size_t start = out.size();
    out.resize(start + deltas + 8 * large);
    char* bytes = out.data() + start;
    char* exceptions = bytes + deltas;
    for (std::size_t i = 1; i < n; ++i) {
      const std::uint64_t z = zigzag(get(i) - get(i - 1));
      if (z < 0xFF) {
        bytes[i - 1] = static_cast<char>(z);
      } else {
        bytes[i - 1] = static_cast<char>(0xFF);
        std::memcpy(exceptions, &z, 8);
        exceptions += 8;
      }
    }
    return;
  }
  const std::size_t start = out.size();
  out.resize(start + deltas * width);
  char* p = out.data() + start;
  for (std::size_t i = 1; i < n; ++i, p += width) {
    const std::uint64_t z = zigzag(get(i) - get(i - 1));
    std::memcpy(p, &z, width);  // little endian: the low bytes
  }
}

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

template <int W, typename Set>
void decode_deltas(const std::uint8_t* p, std::size_t n, std::uint64_t value, Set set) {
  set(0, value);
  for (std::size_t i = 1; i < n; ++i, p += W) {
    std::uint64_t z = 0;
    std::memcpy(&z, p, W);
    value += unzigzag(z);
    set(i, value);
  }
}

// Decodes one column into set(i, value); checks the values fit in `limit`.
template <typename Set>
void get_column(Cursor& c, std::size_t n, std::uint64_t limit, const char* what, Set set) {
  const std::uint8_t width = c.get<std::uint8_t>(what);
  const std::uint64_t first = c.get<std::uint64_t>(what);
  if (!c.error.empty()) return;
  if (width != 0 && width != 1 && width != 2 && width != 4 && width != 8 && width != kEscapedBytes) {
    c.error = std::string("bad column width ") + std::to_string(width) + " in the " + what + " column";
    return;
  }
  if (width == kEscapedBytes) {
    const std::uint32_t large = c.get<std::uint32_t>(what);
    if (!c.error.empty() || n == 0) return;
    if (!c.take((n - 1) + std::size_t{large} * 8, what)) return;
    const std::uint8_t* bytes = c.p;
    const std::uint8_t* exceptions = c.p + (n - 1);
    const std::uint8_t* const exceptions_end = exceptions + std::size_t{large} * 8;
    std::uint64_t value = first, all = first;
    bool overrun = false;
    set(0, value);
    for (std::size_t i = 1; i < n; ++i) {
      std::uint64_t z = bytes[i - 1];
      if (z == 0xFF) [[unlikely]] {
        if (exceptions == exceptions_end) {
          overrun = true;
          z = 0;
        } else {
          std::memcpy(&z, exceptions, 8);
          exceptions += 8;
        }
      }
      value += unzigzag(z);
      all |= value;
      set(i, value);
    }
    c.p = exceptions_end;
    if (overrun || exceptions != exceptions_end)
      c.error = std::string("escaped deltas do not match their escapes in the ") + what + " column";
    else if (all > limit)
      c.error = std::string("a value in the ") + what + " column is out of range";
    return;
  }
  if (n == 0) return;
  const std::size_t bytes = (n - 1) * width;
  if (!c.take(bytes, what)) return;
  // Values are checked through the bitwise OR of all of them: one branch per column.
  std::uint64_t all = first;
  auto checked = [&](std::size_t i, std::uint64_t v) {
    all |= v;
    set(i, v);
  };
  switch (width) {
    case 0: for (std::size_t i = 0; i < n; ++i) checked(i, first); break;
    case 1: decode_deltas<1>(c.p, n, first, checked); break;
    case 2: decode_deltas<2>(c.p, n, first, checked); break;
    case 4: decode_deltas<4>(c.p, n, first, checked); break;
    default: decode_deltas<8>(c.p, n, first, checked); break;
  }
  c.p += bytes;
  if (all > limit) c.error = std::string("a value in the ") + what + " column is out of range";
}

}  // namespace

void encode_vertex_records(const DrawInfo& draw, std::span<const VertexFetch> f, std::string& raw) {
  raw.clear();
  put<std::uint32_t>(raw, draw.draw);
  put<std::uint8_t>(raw, static_cast<std::uint8_t>(draw.type));
  put<std::uint32_t>(raw, draw.restart_index);
  put_column(raw, f.size(), [&](std::size_t i) { return std::uint64_t{f[i].vertex}; });
  const std::size_t start = raw.size();
  raw.resize(start + (f.size() + 7) / 8, 0);
  for (std::size_t i = 0; i < f.size(); ++i)
    if (f[i].primitive_start) raw[start + i / 8] = static_cast<char>(raw[start + i / 8] | (1 << (i % 8)));
}

void encode_texel_records(std::span<const TexelAccess> t, std::string& raw) {
  raw.clear();
  const std::size_t n = t.size();
  put_column(raw, n, [&](std::size_t i) { return std::uint64_t{t[i].texture}; });
  put_column(raw, n, [&](std::size_t i) { return std::uint64_t{t[i].level}; });
  put_column(raw, n, [&](std::size_t i) { return std::uint64_t{t[i].x}; });
  put_column(raw, n, [&](std::size_t i) { return std::uint64_t{t[i].y}; });
  put_column(raw, n, [&](std::size_t i) { return std::uint64_t{t[i].pixel_x}; });
  put_column(raw, n, [&](std::size_t i) { return std::uint64_t{t[i].pixel_y}; });
  put_column(raw, n, [&](std::size_t i) { return std::uint64_t{t[i].triangle}; });
}

void encode_address_records(std::span<const AddressAccess> a, std::string& raw) {
  raw.clear();
  put_column(raw, a.size(), [&](std::size_t i) { return a[i].address; });
  put_column(raw, a.size(), [&](std::size_t i) { return std::uint64_t{a[i].label}; });
}

std::string decode_vertex_records(std::span<const std::uint8_t> raw, std::uint32_t n, DrawInfo& draw,
                                  std::vector<VertexFetch>& out) {
  Cursor c{raw.data(), raw.data() + raw.size(), {}};
  draw.draw = c.get<std::uint32_t>("draw header");
  const std::uint8_t type = c.get<std::uint8_t>("draw header");
  draw.restart_index = c.get<std::uint32_t>("draw header");
  if (!c.error.empty()) return c.error;
  if (type > 2) return "unknown primitive type " + std::to_string(type) + " (expected 0, 1 or 2)";
  draw.type = static_cast<PrimitiveType>(type);
  out.resize(n);
  VertexFetch* f = out.data();
  get_column(c, n, 0xFFFFFFFFu, "vertex", [f](std::size_t i, std::uint64_t v) {
    f[i].vertex = static_cast<std::uint32_t>(v);
  });
  if (!c.take((n + 7) / 8, "primitive start bitmap")) return c.error;
  for (std::size_t i = 0; i < n; ++i) f[i].primitive_start = (c.p[i / 8] >> (i % 8)) & 1;
  c.p += (n + 7) / 8;
  if (c.error.empty() && c.p != c.end) return "unexpected bytes after the records";
  return c.error;
}

std::string decode_texel_records(std::span<const std::uint8_t> raw, std::uint32_t n, std::vector<TexelAccess>& out) {
  Cursor c{raw.data(), raw.data() + raw.size(), {}};
  out.resize(n);
  TexelAccess* t = out.data();
  get_column(c, n, 0xFFFFFFFFu, "texture", [t](std::size_t i, std::uint64_t v) { t[i].texture = static_cast<std::uint32_t>(v); });
  get_column(c, n, 0xFFu, "level", [t](std::size_t i, std::uint64_t v) { t[i].level = static_cast<std::uint8_t>(v); });
  get_column(c, n, 0xFFFFFFFFu, "x", [t](std::size_t i, std::uint64_t v) { t[i].x = static_cast<std::uint32_t>(v); });
  get_column(c, n, 0xFFFFFFFFu, "y", [t](std::size_t i, std::uint64_t v) { t[i].y = static_cast<std::uint32_t>(v); });
  get_column(c, n, 0xFFFFu, "pixel x", [t](std::size_t i, std::uint64_t v) { t[i].pixel_x = static_cast<std::uint16_t>(v); });
  get_column(c, n, 0xFFFFu, "pixel y", [t](std::size_t i, std::uint64_t v) { t[i].pixel_y = static_cast<std::uint16_t>(v); });
  get_column(c, n, 0xFFFFFFFFu, "triangle", [t](std::size_t i, std::uint64_t v) { t[i].triangle = static_cast<std::uint32_t>(v); });
  if (c.error.empty() && c.p != c.end) return "unexpected bytes after the records";
  return c.error;
}

std::string decode_address_records(std::span<const std::uint8_t> raw, std::uint32_t n,
                                   std::vector<AddressAccess>& out) {
  Cursor c{raw.data(), raw.data() + raw.size(), {}};
  out.resize(n);
  AddressAccess* a = out.data();
  get_column(c, n, ~std::uint64_t{0}, "address", [a](std::size_t i, std::uint64_t v) { a[i].address = v; });
  get_column(c, n, 0xFFu, "label", [a](std::size_t i, std::uint64_t v) { a[i].label = static_cast<std::uint8_t>(v); });
  if (c.error.empty() && c.p != c.end) return "unexpected bytes after the records";
  return c.error;
}

}  // namespace rastrace
