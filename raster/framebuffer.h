// The render target: 8-bit RGBA colour and a float depth buffer (window depth in [0, 1], cleared
// to 1, test GL_LESS), in image order (row 0 at the top). Optional debug planes record how many
// times each pixel was written and whether a drawn triangle's edge passed exactly through its
// centre; the cross-check uses them to prove the fill rule (no crack, no double write) and to
// explain coverage differences against OSMesa.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

namespace rastrace {

class Framebuffer {
 public:
  // width, height in 1..16384; throws InputError otherwise.
  Framebuffer(int width, int height, bool debug_planes = false);

  // Writes `colour` and `depth` to every pixel (and zeroes the debug planes).
  void clear(const glm::vec4& colour, float depth = 1.0f);
  // The same in parts, for a renderer that shares the clear out between threads: set_clear()
  // only keeps the values, clear_rows() writes them to rows y0 <= y < y1 (within the image).
  void set_clear(const glm::vec4& colour, float depth = 1.0f);
  void clear_rows(int y0, int y1);

  int width() const { return width_; }
  int height() const { return height_; }
  std::uint8_t* colour() { return colour_.data(); }
  const std::uint8_t* colour() const { return colour_.data(); }
  float* depth() { return depth_.data(); }
  const float* depth() const { return depth_.data(); }
  bool has_debug_planes() const { return !write_count_.empty(); }
  // Pixels written since the last clear: those nearer than the cleared depth (a fragment passes
  // GL_LESS only if nearer, and depths only decrease).
  std::uint64_t covered_pixels() const;
  // Times a fragment passed the depth test and was written (debug planes only).
  std::uint16_t* write_count() { return write_count_.data(); }
  const std::uint16_t* write_count() const { return write_count_.data(); }
  // 1 where the centre lies exactly on an edge of a rasterized (snapped) triangle, 2 where it lies
  // within 1/256 pixel of one (the snapping distance), 0 elsewhere (debug planes only).
  std::uint8_t* centre_on_edge() { return centre_on_edge_.data(); }
  const std::uint8_t* centre_on_edge() const { return centre_on_edge_.data(); }

  // PNG (or any format OpenImageIO knows by the extension), written atomically. RGB unless
  // `alpha` is set.
  void write_colour(const std::string& path, bool alpha = false) const;
  // Single-channel float EXR of the depth buffer, written atomically.
  void write_depth(const std::string& path) const;

 private:
  int width_;
  int height_;
  float clear_depth_ = 1.0f;
  std::uint32_t clear_colour_ = 0;  // RGBA8 as stored
  std::vector<std::uint8_t> colour_;
  std::vector<float> depth_;
  std::vector<std::uint16_t> write_count_;
  std::vector<std::uint8_t> centre_on_edge_;
};

// Writes an RGBA8 image (row 0 at the top) atomically with OpenImageIO; `channels` 3 drops alpha.
void write_rgba8_image(const std::string& path, int width, int height, const std::uint8_t* rgba, int channels);

}  // namespace rastrace
