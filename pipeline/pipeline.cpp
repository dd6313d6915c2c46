#include "pipeline/pipeline.h"

#include <algorithm>
#include <string>

#include "core/enum_names.h"
#include "core/error.h"

namespace rastrace {

namespace {
constexpr EnumName<CullMode> kCullModes[] = {
    {CullMode::None, "none"}, {CullMode::Back, "back"}, {CullMode::Front, "front"}};
}  // namespace

CullMode parse_cull_mode(const std::string& text) { return parse_enum(text, kCullModes, "cull mode"); }

Pipeline::Pipeline(Framebuffer& framebuffer, const PipelineOptions& options, EventSink* sink)
    : framebuffer_(framebuffer),
      options_(options),
      sink_(sink),
      rasterizer_(framebuffer, options.raster, sink),
      clipper_(framebuffer.width(), framebuffer.height(), options.guard_band),
      cache_(options.cache_policy, options.cache_entries) {
  // With several raster threads, the pipeline's own events wait in the rasterizer's ordered sink
  // until the triangles before them are drawn.
  sink_ = rasterizer_.event_sink();
  fetches_.emplace(sink_);
}

void Pipeline::set_camera(const glm::mat4& view, const glm::mat4& projection) {
  view_ = view;
  projection_ = projection;
}

void Pipeline::flush_fetches() { fetches_->flush(); }

void Pipeline::draw(const Mesh& mesh, const glm::mat4& model, const DrawCall& call, std::span<const Texture> textures) {
  const std::uint32_t draw = draw_number_++;
  ++stats_.draws;
  shader_ = VertexShader(view_ * model, projection_, options_.lighting);
  cache_.clear();
  const std::size_t vertex_count = mesh.vertex_count();
  if (shaded_.size() < vertex_count) shaded_.resize(vertex_count);
  const bool has_normals = mesh.normals.size() == vertex_count;
  const bool has_uvs = mesh.uvs.size() == vertex_count;
  static const Material kWhite;

  // Per-material state resolved once per draw, not per triangle.
  const std::size_t material_count = std::max<std::size_t>(mesh.materials.size(), 1);
  std::vector<TriangleState> states(material_count);
  for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
    const int texture = mesh.materials[m].texture;
    if (texture < 0) continue;
    if (static_cast<std::size_t>(texture) >= textures.size() ||
        textures[static_cast<std::size_t>(texture)].levels.empty())
      throw InputError(mesh.name + ": material " + std::to_string(m) + " uses texture " + std::to_string(texture) +
                       " but " + std::to_string(textures.size()) + " textures are loaded");
    const Texture& bound = textures[static_cast<std::size_t>(texture)];
    if (static_cast<std::uint32_t>(texture) >= kMaxTracedTextures)
      throw InputError(mesh.name + ": material " + std::to_string(m) + " uses texture " + std::to_string(texture) +
                       ": expected at most " + std::to_string(kMaxTracedTextures) +
                       " textures (texel events number them in 16 bits)");
    if (static_cast<std::uint32_t>(bound.levels[0].width) > kMaxTextureSide ||
        static_cast<std::uint32_t>(bound.levels[0].height) > kMaxTextureSide)
      throw InputError(mesh.name + ": material " + std::to_string(m) + " uses texture '" + bound.name + "' of " +
                       std::to_string(bound.levels[0].width) + "x" + std::to_string(bound.levels[0].height) +
                       " texels: expected at most " + std::to_string(kMaxTextureSide) +
                       " a side (texel events hold 16-bit coordinates)");
    if (has_uvs) {
      states[m].texture = &bound;
      states[m].texture_id = static_cast<std::uint32_t>(texture);
    }
  }
  auto material_of = [&](std::uint32_t primitive) -> std::uint32_t {
    const std::uint32_t m =
        call.primitive_materials.empty()
            ? call.material
            : (primitive < call.primitive_materials.size() ? call.primitive_materials[primitive] : 0u);
    if (m >= material_count)
      throw InputError(mesh.name + ": primitive " + std::to_string(primitive) + " uses material " + std::to_string(m) +
                       " but the mesh has " + std::to_string(mesh.materials.size()));
    return m;
  };

  if (sink_) {
    DrawInfo info;
    info.draw = draw;
    info.type = call.type;
    if (call.type == PrimitiveType::TriangleStrip) info.restart_index = call.restart_index;
    sink_->begin_draw(info);
  }

  auto fetch = [&](std::size_t position, bool primitive_start) {
    const std::uint32_t v = call.indices[position];
    if (v >= vertex_count)
      throw InputError(mesh.name + ": draw " + std::to_string(draw) + ", index " + std::to_string(position) +
                       ": vertex " + std::to_string(v) + " >= vertex count " + std::to_string(vertex_count));
    ++stats_.lookups;
    if (sink_) {
      *fetches_->reserve(1) = VertexFetch{v, primitive_start};
      fetches_->stored();
    }
    if (!cache_.access(v)) {
      ++stats_.vertices_shaded;
      shader_.shade_into(shaded_[v], mesh.positions[v], has_normals ? &mesh.normals[v] : nullptr,
                         has_uvs ? &mesh.uvs[v] : nullptr);
    }
  };

  std::uint32_t primitive = 0;
  auto assemble = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::span<const std::uint32_t> indices) {
    const bool degenerate = a == b || b == c || a == c;
    ++stats_.primitives;
    const std::uint32_t number = primitive++;
    const std::uint32_t material = material_of(number);
    if (hook_) {
      AssembledPrimitive p;
      p.draw = draw;
      p.primitive = number;
      p.triangle = triangle_number_;
      p.degenerate = degenerate;
      p.triangle_indices = {a, b, c};
      p.indices = indices;
      p.shaded = std::span<const ShadedVertex>(shaded_.data(), vertex_count);
      hook_->primitive(p);
    }
    if (degenerate) {
      ++stats_.degenerate;
      return;
    }
    ++stats_.triangles;
    TriangleState state = states[material];
    state.triangle = triangle_number_++;
    triangle(mesh, a, b, c, material < mesh.materials.size() ? mesh.materials[material] : kWhite, state);
  };

  // GL ignores a trailing incomplete list primitive; so do we (its indices are not fetched).
  walk_index_stream(call.indices, call.type, call.restart_index, fetch, [&](const AssembledTriangle& t) {
    assemble(t.vertices[0], t.vertices[1], t.vertices[2], call.indices.subspan(t.first, t.count));
  });

  flush_fetches();
  rasterizer_.flush();
  if (sink_) sink_->end_draw();
}

void Pipeline::triangle(const Mesh& /*mesh*/, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                        const Material& material, const TriangleState& state) {
  ClipVertex v[3];
  const std::uint32_t ids[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    const ShadedVertex& s = shaded_[ids[i]];
    v[i].position = s.clip;
    v[i].uv = s.uv;
    v[i].colour = glm::vec4(glm::clamp(glm::vec3(material.diffuse) * s.light, 0.0f, 1.0f),
                            glm::clamp(material.diffuse.a, 0.0f, 1.0f));
  }
  const std::uint32_t c0 = clipper_.outcode(v[0].position), c1 = clipper_.outcode(v[1].position),
                      c2 = clipper_.outcode(v[2].position);
  if (c0 & c1 & c2) {
    ++stats_.outside;
    return;
  }
  // The triangle itself, or the polygon the clipper left of it (a member: a ClipPolygon's nine
  // vertices are initialised when it is made, which per triangle cost more than drawing a small
  // one).
  const ClipVertex* vertices = v;
  int count = 3;
  if (c0 | c1 | c2) {
    ++stats_.clipped;
    clipper_.clip(v[0], v[1], v[2], c0 | c1 | c2, clipped_);
    vertices = clipped_.vertices.data();
    count = clipped_.count;
  }
  if (count < 3) return;

  const float half_w = 0.5f * static_cast<float>(framebuffer_.width());
  const float half_h = 0.5f * static_cast<float>(framebuffer_.height());
  RasterVertex* r = projected_.data();
  for (int i = 0; i < count; ++i) {
    const ClipVertex& p = vertices[i];
    if (!(p.position.w > 0.0f)) return;  // only a triangle through the eye itself; nothing visible
    const float inv_w = 1.0f / p.position.w;
    RasterVertex& out = r[i];
    out.x = (p.position.x * inv_w + 1.0f) * half_w;
    out.y = (1.0f - p.position.y * inv_w) * half_h;
    out.z = 0.5f * (p.position.z * inv_w + 1.0f);
    out.inv_w = inv_w;
    out.colour = p.colour;
    out.uv = p.uv;
  }
  // Facing from the whole polygon's signed area in image coordinates (y down): a negative area
  // is counter-clockwise as seen on screen, GL's default front face.
  float area = 0.0f;
  for (int i = 0; i < count; ++i) {
    const RasterVertex& p = r[i];
    const RasterVertex& q = r[(i + 1) % count];
    area += p.x * q.y - q.x * p.y;
  }
  const bool front = area < 0.0f;
  if ((options_.cull == CullMode::Back && !front) || (options_.cull == CullMode::Front && front)) {
    ++stats_.culled;
    return;
  }
  for (int i = 1; i + 1 < count; ++i) {
    ++stats_.rasterized;
    rasterizer_.draw(r[0], r[i], r[i + 1], state);
  }
}

void Pipeline::finish() {
  flush_fetches();
  rasterizer_.flush();
  rasterizer_.finish();
  if (sink_) sink_->finish();
}

}  // namespace rastrace
