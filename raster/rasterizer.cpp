#include "raster/rasterizer.h"

#include "core/enum_names.h"
#include "raster/parallel_rasterizer.h"
#include "raster/quad_loop.h"

namespace rastrace {

namespace {

constexpr EnumName<Traversal> kTraversals[] = {{Traversal::Scanline, "scanline"},
                                               {Traversal::Tiled8, "tiled8"},
                                               {Traversal::Tiled8, "tiled"},
                                               {Traversal::Hilbert8, "hilbert"}};

}  // namespace

Traversal parse_traversal(const std::string& text) { return parse_enum(text, kTraversals, "traversal order"); }

const char* to_string(Traversal traversal) { return enum_to_string(traversal, kTraversals); }

namespace {
constexpr EnumName<DepthTest> kDepthTests[] = {{DepthTest::Early, "early"}, {DepthTest::Late, "late"}};
}  // namespace

DepthTest parse_depth_test(const std::string& text) { return parse_enum(text, kDepthTests, "depth test"); }

const char* to_string(DepthTest test) { return enum_to_string(test, kDepthTests); }

Rasterizer::Rasterizer(Framebuffer& framebuffer, const RasterOptions& options, EventSink* sink)
    : framebuffer_(framebuffer),
      options_(options),
      recorder_(sink),
      framebuffer_recorder_(sink),
      hilbert_bits_(traversal_hilbert_bits(framebuffer.width(), framebuffer.height())) {
  if (options_.threads > 1) {
    parallel_ = std::make_unique<ParallelRasterizer>(framebuffer, options_, sink);
    return;
  }
  if (!options_.hierarchical_z) return;
  hiz_ = std::make_unique<HierarchicalZ>();
  hiz_->build(framebuffer_);
}

Rasterizer::~Rasterizer() = default;

EventSink* Rasterizer::event_sink() {
  if (parallel_) return parallel_->event_sink();
  return recorder_.sink();
}

void Rasterizer::clear(const glm::vec4& colour, float depth) {
  if (parallel_) {
    parallel_->clear(colour, depth);
    return;
  }
  framebuffer_.clear(colour, depth);
  if (hiz_) hiz_->reset(depth);
}

void Rasterizer::flush() {
  if (parallel_) {
    parallel_->flush();
    return;
  }
  recorder_.flush();
  framebuffer_recorder_.flush();
}

void Rasterizer::finish() {
  if (parallel_) parallel_->finish();
}

RasterStats Rasterizer::stats() const {
  if (parallel_) return parallel_->stats();
  RasterStats s = stats_;
  s.texel_reads = recorder_.reads();
  return s;
}

void Rasterizer::draw(const RasterVertex& va, const RasterVertex& vb, const RasterVertex& vc,
                      const TriangleState& state) {
  if (parallel_) {
    parallel_->draw(va, vb, vc, state);
    return;
  }
  TriangleSetup s;
  if (!setup_triangle(va, vb, vc, framebuffer_.width(), framebuffer_.height(), traversal_alignment(options_.traversal),
                      s))
    return;
  ++stats_.triangles;
  const bool textured = state.texture != nullptr && !state.texture->levels.empty();
  const bool debug = framebuffer_.has_debug_planes();
  if (textured) {
    if (debug)
      traverse<true, true>(s, state);
    else
      traverse<true, false>(s, state);
  } else {
    if (debug)
      traverse<false, true>(s, state);
    else
      traverse<false, false>(s, state);
  }
}

template <bool kTextured, bool kDebug>
void Rasterizer::traverse(const TriangleSetup& s, const TriangleState& state) {
  QuadStage stage{framebuffer_, options_, hiz_.get(), recorder_, framebuffer_recorder_, stats_};
  const PixelRect image{0, 0, framebuffer_.width() - 1, framebuffer_.height() - 1};
  visit_quads<kTextured, kDebug>(stage, s, state, options_.traversal, image, hilbert_bits_,
                                 [](int, int) __attribute__((always_inline)){});
}

}  // namespace rastrace
