#include "raster/anisotropic_probes.h"

#include <algorithm>
#include <cmath>

namespace rastrace {

ProbeFootprint probe_footprint(const Texture& texture, const SamplerState& state, float dsdx, float dtdx, float dsdy,
                               float dtdy) {
  ProbeFootprint f;
  const float w = static_cast<float>(texture.levels[0].width), h = static_cast<float>(texture.levels[0].height);
  const float px = std::hypot(dsdx * w, dtdx * h), py = std::hypot(dsdy * w, dtdy * h);
  if (!std::isfinite(px) || !std::isfinite(py)) {
    // No footprint to follow: one probe, the isotropic sampler's own handling of the derivatives.
    f.lambda = compute_lod(state, texture.levels[0].width, texture.levels[0].height, dsdx, dtdx, dsdy, dtdy);
    f.plan = plan_levels(texture, state, f.lambda);
    return f;
  }
  const bool x_major = px >= py;
  const float major = x_major ? px : py, minor = x_major ? py : px;
  // A line (minor 0) takes the maximum; a point (both 0: constant coordinates) one probe.
  const float ratio = major == 0.0f  ? 1.0f
                      : minor > 0.0f ? std::ceil(major / minor)
                                     : static_cast<float>(state.max_anisotropy);
  f.probes = static_cast<int>(std::clamp(ratio, 1.0f, static_cast<float>(state.max_anisotropy)));
  const float rho = major / static_cast<float>(f.probes);
  f.lambda = rho > 0.0f ? std::log2(rho) : -128.0f;
  f.plan = plan_levels(texture, state, f.lambda);
  f.step_s = x_major ? dsdx : dsdy;
  f.step_t = x_major ? dtdx : dtdy;
  return f;
}

glm::vec4 sample_probes(const Texture& texture, const SamplerState& state, const ProbeFootprint& footprint, float s,
                        float t, TexelRecorder& recorder, const TexelSite& site) {
  if (footprint.probes == 1) return sample_planned(texture, state, footprint.plan, s, t, recorder, site);
  glm::vec4 sum(0.0f);
  const float n = static_cast<float>(footprint.probes);
  for (int i = 0; i < footprint.probes; ++i) {
    const float offset = (static_cast<float>(i) + 0.5f) / n - 0.5f;
    sum += sample_planned(texture, state, footprint.plan, s + footprint.step_s * offset, t + footprint.step_t * offset,
                          recorder, site);
  }
  return sum / n;
}

}  // namespace rastrace
