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

}  // namespace rastrace
