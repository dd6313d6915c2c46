// The index stream as a GPU reads it: the primitive type, the optional primitive-restart index,
// and the one triangle walk every module uses (reorder, pipeline, cache_sim, traces).
//
//   TriangleList           3 indices per triangle; a trailing incomplete triangle is not drawn
//   TriangleStrip          GL strip: triangle k of a strip is (v[k], v[k+1], v[k+2]) for even k
//                          and (v[k+1], v[k], v[k+2]) for odd k; the restart index, when the
//                          draw has one, ends a strip (it is sent, never fetched)
//   TriangleListAdjacency  6 indices per primitive, GL_TRIANGLES_ADJACENCY: 0, 2, 4 is the
//                          triangle, 1, 3, 5 the adjacent vertices
//
// "No restart" is std::nullopt, not a reserved value: a strip may restart at 0xFFFFFFFF (GL's
// fixed restart index for 32-bit indices) and a strip without restart has no index that ends it.
// Degenerate triangles (a repeated index) are walked like any other; callers decide what they cost.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace rastrace {

enum class PrimitiveType : std::uint8_t {
  TriangleList = 0,
  TriangleStrip = 1,
  TriangleListAdjacency = 2,
};

using RestartIndex = std::optional<std::uint32_t>;
inline constexpr RestartIndex kNoRestart = std::nullopt;
// GL's fixed restart index for 32-bit indices; rastrace's strips use it.
inline constexpr std::uint32_t kStripRestart = 0xFFFFFFFFu;

// Indices per primitive of a list type (3 or 6); 0 for a strip (its primitives overlap).
constexpr std::size_t list_primitive_size(PrimitiveType type) {
  return type == PrimitiveType::TriangleList ? 3 : type == PrimitiveType::TriangleListAdjacency ? 6 : 0;
}

// True if `index` is a restart marker in a stream of this type (only strips restart).
constexpr bool is_restart(PrimitiveType type, const RestartIndex& restart, std::uint32_t index) {
  return type == PrimitiveType::TriangleStrip && restart && *restart == index;
}

// A triangle with a repeated vertex: fetched, never drawn.
constexpr bool is_degenerate(const std::array<std::uint32_t, 3>& v) {
  return v[0] == v[1] || v[1] == v[2] || v[0] == v[2];
}

// A triangle as assembled: its vertices in GL winding, and the positions [first, first + count)
// of its primitive's indices in the stream (3 for lists and strips, 6 for adjacency).
struct AssembledTriangle {
  std::array<std::uint32_t, 3> vertices{};
  std::size_t first = 0;
  std::size_t count = 3;
  bool degenerate() const { return is_degenerate(vertices); }
};

// Primitive assembly one fetched index at a time, for consumers that see fetches rather than a
// whole stream (a trace replay). Restart markers are not pushed: the next index is pushed with
// primitive_start set, as are the first index of every list primitive and of every strip.
class PrimitiveAssembler {
 public:
  explicit PrimitiveAssembler(PrimitiveType type) : size_(list_primitive_size(type)) {}

  // Returns true when `vertex` completes a triangle; triangle() then holds its vertices.
  bool push(std::uint32_t vertex, bool primitive_start) {
    if (primitive_start) count_ = 0;
    if (size_ == 0) {  // strip: a sliding window of three
      window_[0] = window_[1];
      window_[1] = window_[2];
      window_[2] = vertex;
      if (++count_ < 3) return false;
      const bool odd = (count_ - 3) % 2 == 1;
      triangle_ = odd ? std::array{window_[1], window_[0], window_[2]} : window_;
      return true;
    }
    if (count_ < size_) list_[count_] = vertex;
    if (++count_ != size_) return false;
    triangle_ = size_ == 3 ? std::array{list_[0], list_[1], list_[2]} : std::array{list_[0], list_[2], list_[4]};
    return true;
  }
  const std::array<std::uint32_t, 3>& triangle() const { return triangle_; }

 private:
  std::size_t size_;  // 3 or 6 for lists, 0 for a strip
  std::size_t count_ = 0;
  std::array<std::uint32_t, 3> window_{};
  std::array<std::uint32_t, 6> list_{};
  std::array<std::uint32_t, 3> triangle_{};
};

// Walks a stream in draw order: on_index(position, primitive_start) for every index the GPU
// fetches (restart markers and a trailing incomplete list primitive are not fetched), then,
// once an index completes a triangle, on_triangle(const AssembledTriangle&).
template <typename OnIndex, typename OnTriangle>
void walk_index_stream(std::span<const std::uint32_t> indices, PrimitiveType type, const RestartIndex& restart,
                       OnIndex&& on_index, OnTriangle&& on_triangle) {
  PrimitiveAssembler assembler(type);
  const std::size_t size = list_primitive_size(type);
  const std::size_t end = size ? indices.size() - indices.size() % size : indices.size();
  const std::size_t span = size ? size : 3;
  bool strip_start = true;
  for (std::size_t i = 0; i < end; ++i) {
    const std::uint32_t v = indices[i];
    if (is_restart(type, restart, v)) {
      strip_start = true;
      continue;
    }
    const bool primitive_start = size ? i % size == 0 : strip_start;
    strip_start = false;
    on_index(i, primitive_start);
    if (assembler.push(v, primitive_start)) on_triangle(AssembledTriangle{assembler.triangle(), i + 1 - span, span});
  }
}

// Calls visit(a, b, c) for every triangle of the stream in draw order (degenerates included),
// with the winding GL gives it.
template <typename Visit>
void for_each_triangle(std::span<const std::uint32_t> indices, PrimitiveType type, const RestartIndex& restart,
                       Visit&& visit) {
  walk_index_stream(
      indices, type, restart, [](std::size_t, bool) {},
      [&](const AssembledTriangle& t) { visit(t.vertices[0], t.vertices[1], t.vertices[2]); });
}

}  // namespace rastrace
