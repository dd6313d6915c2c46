// The small rasterizer behind the view-independent overdraw measure: orthographic views only,
// a square grid of R x R pixels, depth and a fragment count per pixel, nothing else. It is not
// the renderer (raster/): no attributes, no textures, no events, so it stays out of the
// renderer's hot path and can draw a mesh from hundreds of directions in well under a second.
//
// Coverage is the half-space rasterizer of Capens, "Advanced rasterization", 2004, as
// meshoptimizer's overdraw analyzer uses it: vertices snapped to 28.4 fixed point, pixel centres
// sampled, the top-left fill rule, so that two triangles sharing an edge never both cover a pixel.
// Each triangle goes to one of two layers by its screen winding: layer 0 keeps the nearest
// fragment with the larger depth, layer 1 (the faces turned the other way) with the smaller one,
// so one pass draws a view along an axis and the opposite view, back faces culled in each.
//
// OverdrawRules states exactly how depth is computed and tested; the presets reproduce
// meshoptimizer 0.18 (Debian) bit for bit, upstream meshoptimizer after its 2025 fix, and a
// rasterizer without either artefact (the default). docs/DESIGN.md, "View-independent overdraw",
// lists what each rule changes on real meshes.
#pragma once

#include <cstdint>
#include <vector>

namespace rastrace {

struct OverdrawRules {
  // meshoptimizer 0.18's depth gradient: dz/dx = (z2-z1)(y3-y1) - (y2-y1)(z3-z1) / det, the
  // division applied to the second product only (a pair of parentheses lost in 2018, restored
  // upstream in 2025). False: the plane's true gradient.
  bool meshopt_018_gradient = false;
  // meshoptimizer clears depth to 0 and passes a fragment when its depth >= the stored one, so
  // the first fragment of a pixel is lost if its interpolated depth is below 0 (a vertex on the
  // bounding box's face, rounding, or a wrong gradient). False: an empty pixel takes any fragment.
  bool zero_depth_clear = false;
  // Depth stepped in float from pixel to pixel and row to row, as meshoptimizer does. False: the
  // triangle's plane evaluated at each pixel centre in double precision.
  bool incremental_float_depth = false;

  static OverdrawRules exact() { return {}; }
  static OverdrawRules meshopt_fixed() { return {false, true, true}; }
  static OverdrawRules meshopt_018() { return {true, true, true}; }
  bool operator==(const OverdrawRules&) const = default;
};

// A vertex on the screen: x and y in pixels (0 to R), z the depth (larger is nearer in layer 0).
struct OverdrawVertex {
  float x, y, z;
};

struct OverdrawCounts {
  std::uint64_t shaded = 0;   // fragments that passed the depth test (pixel shader runs)
  std::uint64_t covered = 0;  // pixels with at least one such fragment
  double overdraw() const { return covered ? double(shaded) / double(covered) : 0.0; }
  OverdrawCounts& operator+=(const OverdrawCounts& other) {
    shaded += other.shaded;
    covered += other.covered;
    return *this;
  }
};

class OverdrawRasterizer {
 public:
  // resolution: pixels per side (at least 1, at most 4096 so the fixed-point products fit);
  // depth_range: the depth of the far side of the view volume, which layer 1 reverses about
  // (meshoptimizer: the resolution). Throws InputError otherwise.
  OverdrawRasterizer(int resolution, float depth_range, OverdrawRules rules);

  void clear();
  // Draws a triangle into the layer its winding selects: clockwise in (x, y) with y up (det <= 0)
  // to layer 0, counter-clockwise to layer 1. A triangle without area covers no pixel.
  void draw(OverdrawVertex v1, OverdrawVertex v2, OverdrawVertex v3);
  // Fragments shaded and pixels covered in both layers since the last clear().
  OverdrawCounts counts() const;

 private:
  int resolution_;
  float depth_range_;
  OverdrawRules rules_;
  // Per pixel and layer ([pixel * 2 + layer]): the nearest depth so far, as "larger wins" (layer 1
  // stores depth_range - z), and the fragments shaded. A float depth is held exactly in a double.
  std::vector<double> depth_;
  std::vector<std::uint32_t> count_;
};

}  // namespace rastrace
