#include "cache_sim/cache_spec.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "core/input_guard.h"
#include "core/units.h"

namespace rastrace {
namespace {

// Where a value came from, for errors: "--cache 'size=0,line=64B': size=0".
struct Context {
  const std::string& option;
  const std::string& text;
  std::string where(const std::string& detail) const { return option + " '" + excerpt(text, 80) + "': " + detail; }
};

enum KindMask : unsigned { kVertexKey = 1, kByteKey = 2, kBothKinds = 3 };

using Setter = void (*)(CacheSpec& spec, const std::vector<std::string>& values, const Context& context);

// One key of the grammar. New keys (presets such as model=..., sector=...) are new rows.
struct KeyRule {
  const char* name;
  unsigned kinds;
  bool alternatives;   // accepts a/b/c (and ranges where the values are numbers)
  const char* values;  // what is accepted, for errors and help
  Setter set_vertex;   // kinds & kVertexKey
  Setter set_byte;     // kinds & kByteKey
};

[[noreturn]] void bad_value(const Context& c, const char* key, const std::string& value, const std::string& expected) {
  throw InputError(c.where(std::string(key) + "=" + value + ": expected " + expected));
}

template <typename T>
void push_unique(std::vector<T>& out, const T& value) {
  if (std::find(out.begin(), out.end(), value) == out.end()) out.push_back(value);
}

// Alternatives of sizes or counts, ranges expanded (core/units.h does the ranges).
std::vector<std::uint64_t> numbers(const std::vector<std::string>& values, const Context& c, const char* key,
                                   bool bytes) {
  std::vector<std::uint64_t> out;
  const std::string what = c.option + " " + key;
  for (const std::string& v : values)
    for (const std::uint64_t n : bytes ? parse_byte_size_list(v, what) : parse_count_list(v, what)) push_unique(out, n);
  return out;
}

std::uint32_t at_most_32_bits(std::uint64_t n, const Context& c, const char* key, std::uint64_t limit) {
  if (n > limit) bad_value(c, key, std::to_string(n), "at most " + std::to_string(limit));
  return static_cast<std::uint32_t>(n);
}

void set_entries(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  s.entries.clear();
  for (const std::uint64_t k : numbers(values, c, "entries", false)) {
    if (k == 0 || k > (1u << 20)) bad_value(c, "entries", std::to_string(k), "1..1048576");
    s.entries.push_back(static_cast<unsigned>(k));
  }
}

std::string vertex_reuse_preset_names() {
  std::string out;
  for (const VertexReusePreset& preset : vertex_reuse_presets()) out += std::string(out.empty() ? "" : ", ") + preset.name;
  return out;
}

void set_vertex_model(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  for (const std::string& v : values) {
    if (v == "all") {
      for (const VertexReusePreset& preset : vertex_reuse_presets()) push_unique(s.models, std::string(preset.name));
      continue;
    }
    if (!find_vertex_reuse_preset(v)) bad_value(c, "model", v, vertex_reuse_preset_names() + " or all (vertex reuse presets), or attila (a depth or colour cache)");
    push_unique(s.models, v);
  }
}

void set_warp(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  s.warps.clear();
  for (const std::uint64_t w : numbers(values, c, "warp", false)) {
    if (w == 1 || w == 2 || w > 1024) bad_value(c, "warp", std::to_string(w), "0 (no warp limit) or 3..1024 vertices");
    push_unique(s.warps, static_cast<unsigned>(w));
  }
}

void set_primgroup(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  s.primgroups.clear();
  for (const std::uint64_t g : numbers(values, c, "primgroup", false)) {
    if (g > 65536) bad_value(c, "primgroup", std::to_string(g), "0 (no limit) or 1..65536 primitives");
    push_unique(s.primgroups, static_cast<unsigned>(g));
  }
}

void set_vertex_policy(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  s.vertex_policies.clear();
  for (const std::string& v : values) {
    if (v != "fifo" && v != "lru") bad_value(c, "policy", v, "fifo or lru (a vertex cache)");
    push_unique(s.vertex_policies, parse_vertex_cache_policy(v));
  }
}

void set_size(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  s.sizes = numbers(values, c, "size", true);
}

void set_line(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  s.lines.clear();
  for (const std::uint64_t l : numbers(values, c, "line", true))
    s.lines.push_back(at_most_32_bits(l, c, "line", 1u << 30));
}

void set_assoc(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  s.assocs.clear();
  for (const std::string& v : values) {
    if (v == "full") {
      push_unique(s.assocs, 0u);
      continue;
    }
    for (const std::uint64_t w : numbers({v}, c, "assoc", false)) {
      if (w == 0) bad_value(c, "assoc", v, "a number of ways >= 1 or full");
      push_unique(s.assocs, at_most_32_bits(w, c, "assoc", 1u << 31));
    }
  }
}

void set_byte_policy(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  s.policies.clear();
  for (const std::string& v : values) {
    if (v != "fifo" && v != "lru" && v != "random" && v != "opt")
      bad_value(c, "policy", v, "fifo, lru, random or opt (a byte cache)");
    push_unique(s.policies, parse_replacement_policy(v));
  }
}

void set_layout(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  const LayoutSpec base = s.layouts.front();  // texel and align may have been given first
  s.layouts.clear();
  for (const std::string& v : values) {
    LayoutSpec layout;
    try {
      layout = parse_layout(v);
    } catch (const InputError&) {
      bad_value(c, "layout", v, "linear, block2, block4, block8, block16 or morton");
    }
    layout.texel_bytes = base.texel_bytes;
    layout.alignment = base.alignment;
    if (std::none_of(s.layouts.begin(), s.layouts.end(),
                     [&](const LayoutSpec& l) { return l == layout; }))
      s.layouts.push_back(layout);
  }
}

// Every layout given (or the default) once per format: a format multiplies the layouts as a sweep
// dimension, and "trace" keeps the formats the trace records.
void set_format(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  std::vector<LayoutSpec> layouts;
  for (const LayoutSpec& base : s.layouts)
    for (const std::string& v : values) {
      LayoutSpec layout = base;
      if (v == "trace") {
        layout.format.reset();
      } else {
        try {
          layout.format = parse_texture_format(v, c.option + " format");
        } catch (const InputError&) {
          bad_value(c, "format", v, "trace, rgba8, bc1, bc3, bc4, bc5, bc7, astc4x4 or astc8x8");
        }
      }
      if (std::none_of(layouts.begin(), layouts.end(), [&](const LayoutSpec& l) {
            return l == layout;
          }))
        layouts.push_back(layout);
    }
  s.layouts = std::move(layouts);
}

std::uint64_t one_size(const std::vector<std::string>& values, const Context& c, const char* key) {
  return parse_byte_size(values.front(), c.option + " " + key);
}

void set_texel(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  const std::uint32_t texel = at_most_32_bits(one_size(values, c, "texel"), c, "texel", 16);
  for (LayoutSpec& l : s.layouts) l.texel_bytes = texel;
}

void set_align(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  const std::uint64_t align = one_size(values, c, "align");
  // Levels are aligned by rounding up offsets: beyond 1 GiB the arithmetic would overflow.
  if (align > (std::uint64_t{1} << 30)) bad_value(c, "align", values.front(), "an alignment of at most 1GiB");
  for (LayoutSpec& l : s.layouts) l.alignment = align;
}

void set_seed(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  s.seed = parse_count(values.front(), c.option + " seed");
}

void set_source(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  const std::string& v = values.front();
  if (v == "depth" || v == "colour") {
    s.buffer = v == "depth" ? FramebufferBuffer::Depth : FramebufferBuffer::Colour;
    return;
  }
  try {
    s.source = parse_sweep_source(v);
  } catch (const InputError&) {
    bad_value(c, "source", v, "texel, vertex, address, depth or colour");
  }
}

void set_pixel(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  const std::uint32_t pixel = at_most_32_bits(one_size(values, c, "pixel"), c, "pixel", 16);
  for (LayoutSpec& l : s.layouts) l.texel_bytes = pixel;
}

// ATTILA's depth and colour caches (del Barrio et al. 2006): 4 ways of 16 lines (ATTILA counts
// lines per way), each line an 8x8-pixel tile of 4-byte pixels: 256 B lines, 16 KiB, LRU.
void set_byte_model(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  if (values.size() != 1 || values.front() != "attila") bad_value(c, "model", values.front(), "attila");
  s.sizes = {16 * 1024};
  s.lines = {256};
  s.assocs = {4};
  s.policies = {ReplacementPolicy::Lru};
  const LayoutSpec base = s.layouts.front();
  LayoutSpec tiles = parse_layout("block8");
  tiles.texel_bytes = base.texel_bytes;
  tiles.alignment = base.alignment;
  s.layouts = {tiles};
}

void set_stride(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  s.stride = at_most_32_bits(one_size(values, c, "stride"), c, "stride", 1u << 20);
}

void set_sector(CacheSpec& s, const std::vector<std::string>& values, const Context& c) {
  s.sectors.clear();
  for (const std::uint64_t b : numbers(values, c, "sector", true)) {
    if (b == 0) bad_value(c, "sector", "0", "a power-of-two byte size no larger than the line, e.g. sector=32B");
    push_unique(s.sectors, at_most_32_bits(b, c, "sector", 1u << 30));
  }
}

// Vertex keys first, then byte keys, in the order the help lists them.
constexpr KeyRule kKeys[] = {
    {"entries", kVertexKey, true, "1..1048576, e.g. entries=16 or entries=4..64", set_entries, nullptr},
    // A vertex reuse preset or, with source=depth|colour, a framebuffer cache's model: the value
    // tells the cache's kind (byte_model_name).
    {"model", kBothKinds, true,
     "a reuse-model preset (nv-pascal|nv-maxwell|amd-gcn|intel|kerbl-nv|kerbl-nv-gl|kerbl-amd|kerbl-intel|all), or "
     "attila: ATTILA's depth and colour caches, size=16KiB,line=256B,assoc=4,policy=lru,layout=block8 (other keys "
     "override)",
     set_vertex_model, set_byte_model},
    {"warp", kVertexKey, true, "vertices per warp, flushing the FIFO (0 = none), e.g. warp=32", set_warp, nullptr},
    {"primgroup", kVertexKey, true, "primitives per warp, flushing the FIFO (0 = none), e.g. primgroup=32",
     set_primgroup, nullptr},
    {"size", kByteKey, true, "a byte size, e.g. size=16KiB or size=1KiB..64KiB", nullptr, set_size},
    {"line", kByteKey, true, "a byte size, e.g. line=64B or line=32B/64B", nullptr, set_line},
    {"sector", kByteKey, true, "sector bytes of a sectored line, e.g. line=128B,sector=32B (default: the line)",
     nullptr, set_sector},
    {"assoc", kByteKey, true, "ways or full, e.g. assoc=4 or assoc=1/2/4/full", nullptr, set_assoc},
    {"policy", kBothKinds, true, "fifo|lru (vertex cache), fifo|lru|random|opt (byte cache)", set_vertex_policy,
     set_byte_policy},
    {"layout", kByteKey, true, "linear|block2|block4|block8|block16|morton", nullptr, set_layout},
    {"format", kByteKey, true,
     "texture storage, trace|rgba8|bc1|bc3|bc4|bc5|bc7|astc4x4|astc8x8 (trace: as the trace records), e.g. "
     "format=rgba8/bc1/bc7",
     nullptr, set_format},
    {"texel", kByteKey, false, "texel bytes, e.g. texel=4B", nullptr, set_texel},
    {"align", kByteKey, false, "level alignment, e.g. align=4KiB", nullptr, set_align},
    {"seed", kByteKey, false, "the random policy's seed, e.g. seed=1", nullptr, set_seed},
    {"source", kByteKey, false, "texel|vertex|address|depth|colour", nullptr, set_source},
    {"stride", kByteKey, false, "bytes per vertex for source=vertex, e.g. stride=32B", nullptr, set_stride},
    {"pixel", kByteKey, false, "bytes per pixel for source=depth|colour, e.g. pixel=4B", nullptr, set_pixel},
};

std::string key_names() {
  std::string out;
  for (const KeyRule& k : kKeys) out += std::string(out.empty() ? "" : ", ") + k.name;
  return out;
}

const KeyRule* find_key(const std::string& name) {
  for (const KeyRule& k : kKeys)
    if (name == k.name) return &k;
  return nullptr;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t at = text.find(separator, start);
    parts.push_back(text.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) return parts;
    start = at + 1;
  }
}

bool all_digits(const std::string& s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)); });
}

// The spec a pre-grammar spelling meant, or "" when `text` is not one:
//   fifo:16 -> entries=16,policy=fifo          (render --vcache, texsweep --vcache)
//   16KiB,64B,4way,lru -> size=16KiB,line=64B,assoc=4,policy=lru   (render --tcache)
//   12,16 or 4..64 -> entries=12/16 or entries=4..64                 (vcache/adjacency --cache)
std::string old_spelling(const std::string& text) {
  const std::vector<std::string> items = split(text, ',');
  if (items.size() == 1) {
    const std::size_t colon = text.find(':');
    if (colon != std::string::npos && all_digits(text.substr(colon + 1)))
      return "entries=" + text.substr(colon + 1) + ",policy=" + text.substr(0, colon);
  }
  bool counts = true;
  for (const std::string& item : items) {
    const std::size_t dots = item.find("..");
    counts = counts && (all_digits(item) || (dots != std::string::npos && all_digits(item.substr(0, dots)) &&
                                             all_digits(item.substr(dots + 2))));
  }
  if (counts) {
    std::string out = "entries=";
    for (std::size_t i = 0; i < items.size(); ++i) out += (i ? "/" : "") + items[i];
    return out;
  }
  if (items.size() == 4) {
    std::string assoc = items[2];
    if (assoc == "direct")
      assoc = "1";
    else if (assoc.size() > 3 && assoc.ends_with("way"))
      assoc = assoc.substr(0, assoc.size() - 3);
    if (assoc == "full" || all_digits(assoc))
      return "size=" + items[0] + ",line=" + items[1] + ",assoc=" + assoc + ",policy=" + items[3];
  }
  return "";
}

}  // namespace

std::size_t CacheSpec::combinations() const {
  if (kind == CacheKind::Vertex)
    return models.empty() ? vertex_policies.size() * entries.size() * warps.size() * primgroups.size() : models.size();
  return layouts.size() * policies.size() * lines.size() * sectors.size() * assocs.size() * sizes.size();
}

CacheSpec parse_cache_spec(const std::string& text, const std::string& option) {
  const Context c{option, text};
  if (text.empty()) throw InputError(option + ": empty cache spec; expected key=value items (" + key_names() + ")");
  struct Item {
    const KeyRule* key;
    std::vector<std::string> values;
  };
  std::vector<Item> items;
  // Empty items first: "12,,16" is a typo wherever it sits, whatever the other items say.
  for (const std::string& item : split(text, ','))
    if (item.empty()) throw InputError(c.where("empty item; expected key=value items separated by ','"));
  for (const std::string& item : split(text, ',')) {
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos) {
      if (const std::string spelled = old_spelling(text); !spelled.empty())
        throw InputError(c.where("write " + spelled));
      throw InputError(c.where("item '" + item + "': expected key=value, with key one of " + key_names()));
    }
    const std::string name = item.substr(0, eq);
    const KeyRule* key = find_key(name);
    if (!key) throw InputError(c.where("unknown key '" + name + "': expected one of " + key_names()));
    for (const Item& earlier : items)
      if (earlier.key == key) throw InputError(c.where("key '" + name + "' given twice"));
    std::vector<std::string> values = split(item.substr(eq + 1), '/');
    for (const std::string& v : values)
      if (v.empty()) throw InputError(c.where(name + "=" + item.substr(eq + 1) + ": expected " + key->values));
    if (values.size() > 1 && !key->alternatives)
      throw InputError(c.where(name + " takes one value, not alternatives: " + item.substr(eq + 1)));
    items.push_back({key, std::move(values)});
  }

  // The kind follows from the keys: entries means a vertex cache, any byte-only key a byte cache.
  const KeyRule* vertex_key = nullptr;
  const KeyRule* byte_key = nullptr;
  for (const Item& item : items) {
    unsigned kinds = item.key->kinds;
    if (std::string(item.key->name) == "model") kinds = item.values.front() == "attila" ? kByteKey : kVertexKey;
    if (kinds == kVertexKey) vertex_key = item.key;
    if (kinds == kByteKey && !byte_key) byte_key = item.key;
  }
  if (vertex_key && byte_key)
    throw InputError(c.where(std::string(vertex_key->name) + " (a vertex cache) and " + byte_key->name +
                             " (a byte cache) cannot be mixed in one spec"));
  CacheSpec spec;
  spec.kind = vertex_key ? CacheKind::Vertex : CacheKind::Byte;
  if (!vertex_key && !byte_key)
    throw InputError(
        c.where("missing entries=... or model=... (a vertex cache, e.g. entries=16,policy=fifo or model=kerbl-nv) or size=... "
                "(a byte cache, e.g. size=16KiB,line=64B,assoc=4,policy=lru)"));
  // A model comes first (the keys given beside it override it), then layouts: texel, pixel and
  // align apply to every layout, whichever order they were written in.
  const auto rank = [](const Item& i) {
    const std::string name = i.key->name;
    return name == "model" ? 0 : name == "layout" ? 1 : name == "format" ? 2 : 3;
  };
  std::stable_sort(items.begin(), items.end(), [&](const Item& a, const Item& b) { return rank(a) < rank(b); });
  for (const Item& item : items)
    (spec.kind == CacheKind::Vertex ? item.key->set_vertex : item.key->set_byte)(spec, item.values, c);
  if (!spec.models.empty()) {
    for (const Item& item : items)
      if (std::string name = item.key->name; name != "model")
        throw InputError(c.where("model= names a preset with all its parameters: drop " + name +
                                 "= (or spell the cache out, e.g. entries=32,policy=fifo,warp=32,primgroup=32)"));
    return spec;
  }
  if (spec.kind == CacheKind::Vertex && spec.entries.empty())
    throw InputError(c.where("missing entries=... (e.g. entries=16) or model=... (e.g. model=nv-pascal)"));
  if (spec.kind == CacheKind::Vertex &&
      std::find(spec.vertex_policies.begin(), spec.vertex_policies.end(), VertexCachePolicy::Lru) !=
          spec.vertex_policies.end() &&
      (spec.warps != std::vector<unsigned>{0} || spec.primgroups != std::vector<unsigned>{0}))
    throw InputError(c.where("warp= and primgroup= flush meshoptimizer's FIFO model: expected policy=fifo"));
  if (spec.kind == CacheKind::Byte && spec.sizes.empty())
    throw InputError(c.where("missing size=...: a byte cache needs its capacity, e.g. size=16KiB"));
  for (const Item& item : items) {
    const std::string name = item.key->name;
    if (name == "sector" && spec.buffer)
      throw InputError(c.where("sector= does not apply to a " + std::string(to_string(*spec.buffer)) +
                               " cache (a write-back cache of whole lines)"));
    if (name == "pixel" && !spec.buffer)
      throw InputError(c.where("pixel= is the bytes per pixel of a depth or colour cache: add source=depth or "
                               "source=colour (a texture cache's element is texel=)"));
    if (name == "layout" && spec.buffer &&
        std::any_of(spec.layouts.begin(), spec.layouts.end(), [](const LayoutSpec& l) { return l.format.has_value(); }))
      throw InputError(c.where("layout=...:FORMAT stores textures; a " + std::string(to_string(*spec.buffer)) +
                               " cache lays out pixels: drop the :FORMAT"));
    if ((name == "texel" || name == "stride" || name == "align" || name == "format") && spec.buffer)
      throw InputError(c.where(name + "= does not apply to a " + to_string(*spec.buffer) +
                               " cache: its element is a pixel (pixel=4B)"));
    if (name == "policy" && spec.buffer &&
        std::find(spec.policies.begin(), spec.policies.end(), ReplacementPolicy::Opt) != spec.policies.end())
      throw InputError(c.where("policy=opt: a depth or colour cache writes back what it evicts; expected fifo, lru "
                               "or random"));
  }
  if (spec.kind == CacheKind::Byte) {
    // Every configuration is simulated at once (16 bytes of state per line at least): refuse a
    // list whose caches cannot fit before any work starts, not with bad_alloc halfway through.
    std::uint64_t lines = 0;
    for (const std::uint64_t size : spec.sizes)
      for (const std::uint32_t line : spec.lines) lines += line ? size / line : 0;
    lines *= spec.assocs.size() * spec.policies.size() * spec.layouts.size();
    checked_bytes(lines, 16, c.where("the simulators of all " + std::to_string(spec.combinations()) + " caches"));
  }
  return spec;
}

std::vector<VertexCacheSpec> vertex_caches(const CacheSpec& spec) {
  std::vector<VertexCacheSpec> out;
  if (spec.kind != CacheKind::Vertex) return out;
  for (const std::string& model : spec.models) out.push_back(find_vertex_reuse_preset(model)->spec);
  if (!spec.models.empty()) return out;
  for (const VertexCachePolicy policy : spec.vertex_policies)
    for (const unsigned k : spec.entries)
      for (const unsigned warp : spec.warps)
        for (const unsigned primgroup : spec.primgroups) out.push_back(vertex_cache_spec(policy, k, warp, primgroup));
  return out;
}

std::vector<ByteCacheChoice> byte_caches(const CacheSpec& spec) {
  std::vector<ByteCacheChoice> out;
  if (spec.kind != CacheKind::Byte) return out;
  for (const LayoutSpec& layout : spec.layouts)
    for (const ReplacementPolicy policy : spec.policies)
      for (const std::uint32_t line : spec.lines)
        for (const std::uint32_t sector : spec.sectors)
        for (const std::uint32_t assoc : spec.assocs)
          for (const std::uint64_t size : spec.sizes) {
            ByteCacheChoice choice;
            choice.sector_bytes = sector;
            choice.cache.size_bytes = size;
            choice.cache.line_bytes = line;
            choice.cache.assoc = assoc;
            choice.cache.policy = policy;
            choice.cache.seed = spec.seed;
            choice.layout = layout;
            out.push_back(choice);
          }
  return out;
}

namespace {
CacheSpec parse_one(const std::string& text, const std::string& option, CacheKind kind) {
  const CacheSpec spec = parse_cache_spec(text, option);
  if (spec.kind != kind)
    throw InputError(option + " '" + text + "': expected a " +
                     (kind == CacheKind::Vertex ? "post-transform vertex cache, e.g. entries=16,policy=fifo"
                                                : "byte cache, e.g. size=16KiB,line=64B,assoc=4,policy=lru"));
  if (spec.combinations() != 1)
    throw InputError(option + " '" + text + "': expected one cache, not " + std::to_string(spec.combinations()) +
                     " alternatives");
  return spec;
}
}  // namespace

VertexCacheSpec parse_vertex_cache(const std::string& text, const std::string& option) {
  return vertex_caches(parse_one(text, option, CacheKind::Vertex)).front();
}

ByteCacheChoice parse_byte_cache(const std::string& text, const std::string& option) {
  const ByteCacheChoice choice = byte_caches(parse_one(text, option, CacheKind::Byte)).front();
  if (choice.sector_bytes != 0)
    throw InputError(option + " '" + text + "': sector= is for replay and hierarchies (rastrace replay --cache, "
                     "--level); " + option + " simulates whole lines");
  try {
    validate(choice.cache);
  } catch (const InputError& e) {
    throw InputError(option + " '" + text + "': " + e.what());
  }
  return choice;
}

SweepSpec sweep_spec(const CacheSpec& spec, SweepSource fallback) {
  if (spec.sectors.size() != 1 || spec.sectors.front() != 0)
    throw InputError("sector=: sectored caches are replayed (rastrace replay --cache ...,sector=32B), not swept");
  if (spec.buffer)
    throw InputError(std::string("source=") + to_string(*spec.buffer) +
                     ": depth and colour caches are replayed (rastrace replay --cache ...,source=" +
                     to_string(*spec.buffer) + "), not swept");
  SweepSpec out;
  out.source = spec.source.value_or(fallback);
  out.sizes = spec.sizes;
  out.lines = spec.lines;
  out.assocs = spec.assocs;
  out.policies = spec.policies;
  out.layouts = spec.layouts;
  out.stride = spec.stride;
  out.seed = spec.seed;
  return out;
}

std::string format_cache_spec(const CacheConfig& cache) {
  return "size=" + format_byte_size(cache.size_bytes) + ",line=" + format_byte_size(cache.line_bytes) +
         ",assoc=" + (cache.assoc == 0 ? std::string("full") : std::to_string(cache.assoc)) +
         ",policy=" + to_string(cache.policy);
}

FramebufferCacheSpec attila_framebuffer_cache(FramebufferBuffer buffer) {
  return parse_framebuffer_cache("model=attila", "model", buffer);
}

std::vector<FramebufferCacheSpec> framebuffer_caches(const CacheSpec& spec) {
  std::vector<FramebufferCacheSpec> out;
  if (spec.kind != CacheKind::Byte || !spec.buffer) return out;
  for (const ByteCacheChoice& choice : byte_caches(spec)) out.push_back({*spec.buffer, choice.cache, choice.layout});
  return out;
}

FramebufferCacheSpec parse_framebuffer_cache(const std::string& text, const std::string& option,
                                             FramebufferBuffer buffer) {
  // The option names the buffer, so source= may be left out.
  bool has_source = false;
  for (const std::string& item : split(text, ',')) has_source = has_source || item.rfind("source=", 0) == 0;
  const std::string full = has_source ? text : "source=" + std::string(to_string(buffer)) + "," + text;
  const CacheSpec spec = parse_cache_spec(full, option);
  if (spec.kind != CacheKind::Byte || !spec.buffer || *spec.buffer != buffer)
    throw InputError(option + " '" + text + "': expected a " + to_string(buffer) +
                     " cache, e.g. model=attila or size=16KiB,line=256B,assoc=4,policy=lru,layout=block8,pixel=4B");
  const std::vector<FramebufferCacheSpec> caches = framebuffer_caches(spec);
  if (caches.size() != 1)
    throw InputError(option + " '" + text + "': expected one cache, not " + std::to_string(caches.size()) +
                     " alternatives");
  try {
    validate(caches.front().cache);
  } catch (const InputError& e) {
    throw InputError(option + " '" + text + "': " + e.what());
  }
  return caches.front();
}

std::string format_framebuffer_cache_spec(const FramebufferCacheSpec& cache) {
  return "source=" + std::string(to_string(cache.buffer)) + "," + format_cache_spec(cache.cache) +
         ",layout=" + layout_name(cache.layout) + ",pixel=" + format_byte_size(cache.layout.texel_bytes);
}

std::string format_cache_spec(const VertexCacheSpec& cache) {
  return cache.preset.empty() ? vertex_reuse_name(cache) : "model=" + cache.preset;
}

std::string cache_spec_keys_help() {
  std::string out;
  for (const KeyRule& k : kKeys)
    out += std::string("  ") + k.name +
           (k.kinds == kVertexKey ? " (vertex)"
            : k.kinds == kByteKey ? " (byte)"
                                  : "") +
           ": " + k.values + "\n";
  return out;
}

}  // namespace rastrace
