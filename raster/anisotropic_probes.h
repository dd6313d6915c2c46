// Anisotropic filtering by the rule of EXT_texture_filter_anisotropic (and of GPUs since): along
// the footprint's major axis, N = min(ceil(Pmax / Pmin), maxAniso) trilinear (or the minification
// filter's) probes, spaced evenly over the major derivative vector and averaged, at the level of
// detail lambda = log2(Pmax / N), which is the minor axis's whenever the maximum does not bind.
// Pmax and Pmin are the lengths of the two derivative vectors in level-0 texels (equation 8.6's).
//
// llvmpipe filters differently (raster/anisotropy.h: an elliptical average of one level); this
// rule is the model of hardware texture traffic: N x 8 texel reads per trilinear fragment, up to
// 128 at 16x. `render --aniso N --aniso-rule probes` selects it.
#pragma once

#include <glm/vec4.hpp>

#include "raster/sampler.h"
#include "raster/texel_recorder.h"
#include "scenes/texture.h"

namespace rastrace {

// One quad's probes (its derivatives are shared).
struct ProbeFootprint {
  int probes = 1;
  float lambda = 0.0f;
  LevelPlan plan;                      // plan_levels at lambda, shared by every probe of the quad
  float step_s = 0.0f, step_t = 0.0f;  // the major derivative vector, in (s, t)
};

ProbeFootprint probe_footprint(const Texture& texture, const SamplerState& state, float dsdx, float dtdx, float dsdy,
                               float dtdy);

// The mean of the footprint's probes at (s, t) + ((i + 0.5) / N - 0.5) * step, i = 0..N-1, each
// sampled at the footprint's planned levels (sample_planned), every texel read recorded in probe order.
glm::vec4 sample_probes(const Texture& texture, const SamplerState& state, const ProbeFootprint& footprint, float s,
                        float t, TexelRecorder& recorder, const TexelSite& site);

}  // namespace rastrace
