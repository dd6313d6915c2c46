#include "pipeline/vertex_shader.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace rastrace {

VertexShader::VertexShader(const glm::mat4& model_view, const glm::mat4& projection, const Lighting& lighting)
    : model_view_(model_view),
      projection_(projection),
      mvp_(projection * model_view),
      normal_matrix_(glm::transpose(glm::inverse(glm::mat3(model_view)))),
      lighting_(lighting) {
  if (lighting_.enabled) {
    const float length = glm::length(lighting_.direction);
    lighting_.direction = length > 0.0f ? lighting_.direction / length : glm::vec3(0.0f, 0.0f, 1.0f);
  }
}

ShadedVertex VertexShader::shade(const glm::vec3& position, const glm::vec3* normal, const glm::vec2* uv) const {
  ShadedVertex out;
  out.clip = mvp_ * glm::vec4(position, 1.0f);
  if (uv) out.uv = *uv;
  if (lighting_.enabled) {
    // Without per-vertex normals GL uses the current normal, (0, 0, 1) by default.
    const glm::vec3 n = normal_matrix_ * (normal ? *normal : glm::vec3(0.0f, 0.0f, 1.0f));
    const float length = glm::length(n);
    const float diffuse = length > 0.0f ? std::max(0.0f, glm::dot(n / length, lighting_.direction)) : 0.0f;
    out.light = lighting_.ambient + diffuse;
  }
  return out;
}

}  // namespace rastrace
