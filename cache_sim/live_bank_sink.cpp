#include "cache_sim/live_bank_sink.h"

#include <bit>
#include <stdexcept>

#include "cache_sim/opt_cache.h"
#include "core/error.h"

namespace rastrace {

struct LiveBankSink::LineGroup {
  std::uint32_t line_shift = 0;
  std::vector<std::uint64_t> lines;
  std::unique_ptr<LruStackProfile> profile;
  bool keep_for_opt = false;
  std::vector<std::uint64_t> opt_lines;
  std::vector<std::size_t> caches;
};

struct LiveBankSink::AddressStream {
  enum class Kind { Texture, VertexBuffer, Address } kind = Kind::Address;
  LayoutSpec layout_spec;
  std::unique_ptr<TextureLayout> layout;
  std::uint32_t stride = 0;
  std::vector<std::uint64_t> addresses;
  std::vector<LineGroup> groups;
};

struct LiveBankSink::BankCache {
  CacheConfig config;
  std::unique_ptr<ByteCache> cache;  // null for opt
  std::size_t stream = 0;
  std::size_t group = 0;
  CacheStats opt_stats;
};

struct LiveBankSink::FramebufferCache {
  FramebufferCache(const FramebufferCacheSpec& s, const FrameSize& frame)
      : spec(s), layout(s.layout, TextureLevels{{LevelSize{frame.width, frame.height}}}), cache(s.cache) {}
  FramebufferCacheSpec spec;
  TextureLayout layout;  // one "texture" of one level: the frame, one element per pixel
  WriteBackCache cache;
};

const char* to_string(FramebufferBuffer buffer) { return buffer == FramebufferBuffer::Depth ? "depth" : "colour"; }

LiveBankSink::LiveBankSink(CacheBankConfig config, TextureLevels textures, FrameSize frame)
    : config_(std::move(config)), textures_(std::move(textures)), frame_(frame) {
  if (!config_.framebuffer.empty() && (frame_.width == 0 || frame_.height == 0))
    throw InputError("depth and colour caches need the frame's size (a trace's metadata gives its resolution)");
  for (const FramebufferCacheSpec& spec : config_.framebuffer) framebuffer_caches_.emplace_back(spec, frame_);
  for (const VertexCachePolicy policy : {VertexCachePolicy::Fifo, VertexCachePolicy::Lru}) {
    std::vector<unsigned> sizes;
    for (const VertexCacheSpec& spec : config_.vertex)
      if (!spec.batched() && spec.policy == policy) sizes.push_back(spec.entries);
    if (!sizes.empty()) vertex_caches_.emplace_back(policy, std::move(sizes));
  }
  std::vector<std::size_t> counts(vertex_caches_.size(), 0);
  for (const VertexCacheSpec& spec : config_.vertex) {
    VertexCacheSlot slot;
    if (spec.batched()) {
      slot.batched = true;
      slot.bank = vertex_models_.size();
      vertex_models_.emplace_back(spec);
    } else {
      while (vertex_caches_[slot.bank].policy() != spec.policy) ++slot.bank;
      slot.size = counts[slot.bank]++;
    }
    vertex_cache_of_.push_back(slot);
  }

  // Finds or creates the stream, then the line-size group, of one byte cache.
  const auto attach = [&](const CacheConfig& cache, AddressStream::Kind kind, const LayoutSpec* layout,
                          std::uint32_t stride, std::vector<std::size_t>& stream_list) {
    validate(cache);
    std::size_t s = 0;
    for (; s < streams_.size(); ++s) {
      const AddressStream& st = *streams_[s];
      if (st.kind != kind) continue;
      if (kind == AddressStream::Kind::Texture && !(st.layout_spec == *layout)) continue;
      if (kind == AddressStream::Kind::VertexBuffer && st.stride != stride) continue;
      break;
    }
    if (s == streams_.size()) {
      auto st = std::make_unique<AddressStream>();
      st->kind = kind;
      if (layout) {
        st->layout_spec = *layout;
        st->layout = std::make_unique<TextureLayout>(*layout, textures_);
      }
      st->stride = stride;
      streams_.push_back(std::move(st));
      stream_list.push_back(s);
    }
    AddressStream& st = *streams_[s];
    const std::uint32_t shift = static_cast<std::uint32_t>(std::countr_zero(cache.line_bytes));
    std::size_t g = 0;
    while (g < st.groups.size() && st.groups[g].line_shift != shift) ++g;
    if (g == st.groups.size()) {
      st.groups.emplace_back();
      st.groups.back().line_shift = shift;
      if (config_.three_c) st.groups.back().profile = std::make_unique<LruStackProfile>();
    }
    BankCache bc;
    bc.config = cache;
    if (cache.policy == ReplacementPolicy::Opt)
      st.groups[g].keep_for_opt = true;
    else
      bc.cache = std::make_unique<ByteCache>(cache);
    bc.stream = s;
    bc.group = g;
    st.groups[g].caches.push_back(caches_.size());
    caches_.push_back(std::move(bc));
  };
  for (const TextureCacheSpec& spec : config_.texture)
    attach(spec.cache, AddressStream::Kind::Texture, &spec.layout, 0, texture_streams_);
  for (const VertexBufferCacheSpec& spec : config_.vertex_buffer) {
    if (spec.stride == 0) throw InputError("vertex buffer stride 0: expected at least 1 byte per vertex");
    attach(spec.cache, AddressStream::Kind::VertexBuffer, nullptr, spec.stride, vertex_buffer_streams_);
  }
  for (const CacheConfig& cache : config_.address)
    attach(cache, AddressStream::Kind::Address, nullptr, 0, address_streams_);
}

LiveBankSink::~LiveBankSink() = default;

void LiveBankSink::feed_stream(AddressStream& stream) {
  for (LineGroup& group : stream.groups) {
    group.lines.resize(stream.addresses.size());
    for (std::size_t i = 0; i < stream.addresses.size(); ++i) group.lines[i] = stream.addresses[i] >> group.line_shift;
    if (group.profile) group.profile->access_lines(group.lines);
    if (group.keep_for_opt) {
      check_opt_capacity(group.opt_lines.size() + group.lines.size(), config_.opt_max_accesses);
      group.opt_lines.insert(group.opt_lines.end(), group.lines.begin(), group.lines.end());
    }
    for (const std::size_t c : group.caches)
      if (caches_[c].cache) caches_[c].cache->access_lines(group.lines);
  }
}

void LiveBankSink::begin_draw(const DrawInfo& draw) {
  draw_ = draw;
  ++draw_serial_;
  assembler_ = PrimitiveAssembler(draw.type);
  strips_in_draw_ = 0;
  if (config_.flush_vertex_cache_per_draw) {
    for (VertexCacheSlot& slot : vertex_cache_of_) {
      if (slot.batched) continue;
      const std::uint64_t misses = vertex_caches_[slot.bank].misses(slot.size);
      slot.closed_warps += misses > slot.misses_at_flush;
      slot.misses_at_flush = misses;
    }
    for (VertexCacheSizes& caches : vertex_caches_) caches.clear();
    for (VertexReuseModel& model : vertex_models_) model.flush();
  }
}

void LiveBankSink::on_vertex(std::uint32_t vertex, bool primitive_start) {
  ++shared_.lookups;
  ++shared_.indices_sent;
  if (primitive_start) primitive_size_ = 0;
  if (primitive_size_ < primitive_.size()) primitive_[primitive_size_++] = vertex;
  if (vertex >= seen_.size()) seen_.resize(std::max<std::size_t>(std::size_t{vertex} + 1, seen_.size() * 2), 0);
  if (seen_[vertex] != draw_serial_ + 1) {
    seen_[vertex] = draw_serial_ + 1;
    ++shared_.vertices;
  }
  // The restart index between two strips of a draw was sent, not fetched.
  if (primitive_start && draw_.type == PrimitiveType::TriangleStrip) {
    if (strips_in_draw_ > 0 && draw_.restart_index) ++shared_.indices_sent;
    ++strips_in_draw_;
  }
  if (assembler_.push(vertex, primitive_start)) {
    const bool degenerate = is_degenerate(assembler_.triangle());
    if (degenerate)
      ++shared_.degenerate;
    else
      ++shared_.triangles;
    // Warp and batch models take a list's primitives as sent, a strip's drawn triangles.
    const bool strip = draw_.type == PrimitiveType::TriangleStrip;
    for (VertexReuseModel& model : vertex_models_)
      if (!(strip && degenerate))
        model.primitive(strip ? assembler_.triangle().data() : primitive_.data(), strip ? 3 : primitive_size_);
  }
}

void LiveBankSink::vertex_fetches(std::span<const VertexFetch> fetches) {
  if (finished_) throw std::logic_error("LiveBankSink: events after finish");
  if (!vertex_caches_.empty()) {
    fetched_.resize(fetches.size());
    for (std::size_t i = 0; i < fetches.size(); ++i) fetched_[i] = fetches[i].vertex;
    for (VertexCacheSizes& caches : vertex_caches_) caches.access(fetched_);
  }
  for (const VertexFetch& f : fetches) on_vertex(f.vertex, f.primitive_start);
  for (const std::size_t s : vertex_buffer_streams_) {
    AddressStream& stream = *streams_[s];
    stream.addresses.resize(fetches.size());
    const std::uint64_t base = std::uint64_t{draw_.draw} << 40;
    for (std::size_t i = 0; i < fetches.size(); ++i)
      stream.addresses[i] = base + std::uint64_t{fetches[i].vertex} * stream.stride;
    feed_stream(stream);
  }
}

void LiveBankSink::texel_accesses(std::span<const TexelAccess> accesses) {
  if (finished_) throw std::logic_error("LiveBankSink: events after finish");
  for (const std::size_t s : texture_streams_) {
    AddressStream& stream = *streams_[s];
    const TextureLayout& layout = *stream.layout;
    stream.addresses.resize(accesses.size());
    for (std::size_t i = 0; i < accesses.size(); ++i) {
      const TexelAccess& t = accesses[i];
      if (!layout.contains(t.texture, t.level, t.x, t.y)) [[unlikely]]
        throw InputError("texel access (texture " + std::to_string(t.texture) + ", level " + std::to_string(t.level) +
                         ", x " + std::to_string(t.x) + ", y " + std::to_string(t.y) + ", triangle " +
                         std::to_string(t.triangle) + ") lies outside the " + std::to_string(textures_.size()) +
                         " texture(s) whose level sizes the trace metadata lists");
      stream.addresses[i] = layout.address(t.texture, t.level, t.x, t.y);
    }
    feed_stream(stream);
  }
}

void LiveBankSink::address_accesses(std::span<const AddressAccess> accesses) {
  if (finished_) throw std::logic_error("LiveBankSink: events after finish");
  for (const std::size_t s : address_streams_) {
    AddressStream& stream = *streams_[s];
    stream.addresses.resize(accesses.size());
    for (std::size_t i = 0; i < accesses.size(); ++i) stream.addresses[i] = accesses[i].address;
    feed_stream(stream);
  }
}

void LiveBankSink::framebuffer_accesses(std::span<const FramebufferAccess> accesses) {
  if (finished_) throw std::logic_error("LiveBankSink: events after finish");
  for (FramebufferCache& fc : framebuffer_caches_) {
    const bool depth = fc.spec.buffer == FramebufferBuffer::Depth;
    const std::uint32_t shift = fc.cache.line_shift();
    for (const FramebufferAccess& a : accesses) {
      if (depth == (a.op == FramebufferOp::ColourWrite)) continue;  // the other buffer's event
      const bool read = a.op == FramebufferOp::DepthRead;
      for (std::uint32_t i = 0; i < 4; ++i) {
        if (!(a.mask >> i & 1u)) continue;
        const std::uint32_t x = a.x + (i & 1u), y = a.y + (i >> 1);
        if (!fc.layout.contains(0, 0, x, y)) [[unlikely]]
          throw InputError("framebuffer access at pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                           "), triangle " + std::to_string(a.triangle) + ", lies outside the " +
                           std::to_string(frame_.width) + "x" + std::to_string(frame_.height) + " frame");
        const std::uint64_t line = fc.layout.address(0, 0, x, y) >> shift;
        if (read)
          fc.cache.read(line);
        else
          fc.cache.write(line);
      }
    }
  }
}

void LiveBankSink::end_draw() {}

void LiveBankSink::finish() {
  if (finished_) return;
  finished_ = true;
  vertex_results_.clear();
  for (const VertexCacheSlot& slot : vertex_cache_of_) {
    VertexStreamStats s = shared_;
    if (slot.batched) {
      const VertexReuseModel& model = vertex_models_[slot.bank];
      s.misses = model.misses();
      s.warps = model.warps();
      s.lane_slots = model.lane_slots();
    } else {
      s.misses = vertex_caches_[slot.bank].misses(slot.size);
      s.warps = slot.closed_warps + (s.misses > slot.misses_at_flush);
      s.lane_slots = 0;  // a plain cache has no SIMD lanes
    }
    vertex_results_.push_back(s);
  }
  std::vector<CacheStats> all;
  for (BankCache& bc : caches_) {
    LineGroup& group = streams_[bc.stream]->groups[bc.group];
    CacheStats s = bc.cache ? bc.cache->stats() : simulate_opt(bc.config, group.opt_lines);
    if (group.profile) {
      const std::uint64_t fully_associative = group.profile->misses(bc.config.lines());
      s.has_three_c = true;
      s.compulsory = group.profile->compulsory();
      s.capacity = static_cast<std::int64_t>(fully_associative) - static_cast<std::int64_t>(s.compulsory);
      s.conflict = static_cast<std::int64_t>(s.misses) - static_cast<std::int64_t>(fully_associative);
    }
    all.push_back(s);
  }
  for (auto& stream : streams_)
    for (LineGroup& group : stream->groups) std::vector<std::uint64_t>().swap(group.opt_lines);
  framebuffer_results_.clear();
  for (FramebufferCache& fc : framebuffer_caches_) {
    fc.cache.flush();  // the end of the frame writes every dirty line back
    framebuffer_results_.push_back(fc.cache.stats());
  }
  const std::size_t nt = config_.texture.size(), nv = config_.vertex_buffer.size();
  texture_results_.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(nt));
  vertex_buffer_results_.assign(all.begin() + static_cast<std::ptrdiff_t>(nt),
                                all.begin() + static_cast<std::ptrdiff_t>(nt + nv));
  address_results_.assign(all.begin() + static_cast<std::ptrdiff_t>(nt + nv), all.end());
}

void LiveBankSink::check_finished() const {
  if (!finished_) throw std::logic_error("LiveBankSink: statistics are ready after finish()");
}

const std::vector<VertexStreamStats>& LiveBankSink::vertex_stats() const {
  check_finished();
  return vertex_results_;
}
const std::vector<CacheStats>& LiveBankSink::texture_stats() const {
  check_finished();
  return texture_results_;
}
const std::vector<CacheStats>& LiveBankSink::vertex_buffer_stats() const {
  check_finished();
  return vertex_buffer_results_;
}
const std::vector<WriteBackStats>& LiveBankSink::framebuffer_stats() const {
  check_finished();
  return framebuffer_results_;
}
const std::vector<CacheStats>& LiveBankSink::address_stats() const {
  check_finished();
  return address_results_;
}

}  // namespace rastrace
