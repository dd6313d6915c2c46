// The vertex stage: model-view-projection, eye-space normals and optional Gouraud lighting with
// one directional light, as OpenGL's fixed-function pipeline computes it (GL_NORMALIZE on,
// GL_COLOR_MATERIAL for ambient and diffuse, no specular), so OSMesa can draw the same thing.
//
// The material colour is applied per primitive (a draw per material in GL terms): the shaded
// vertex carries the lighting factor, and colour = clamp(diffuse * light) at assembly, which is
// exactly GL's ambient * diffuse + max(0, n.l) * diffuse for a white light.
#pragma once

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace rastrace {

struct Lighting {
  bool enabled = false;
  glm::vec3 direction{0.0f, 0.0f, 1.0f};  // towards the light, eye space (GL_POSITION with w = 0)
  float ambient = 0.2f;                   // GL_LIGHT_MODEL_AMBIENT, grey
};

struct ShadedVertex {
  glm::vec4 clip{0.0f};
  glm::vec2 uv{0.0f};
  float light = 1.0f;  // multiplies the material's diffuse colour (1 when lighting is off)
};

class VertexShader {
 public:
  VertexShader() = default;
  VertexShader(const glm::mat4& model_view, const glm::mat4& projection, const Lighting& lighting);

  ShadedVertex shade(const glm::vec3& position, const glm::vec3* normal, const glm::vec2* uv) const {
    ShadedVertex out;
    shade_into(out, position, normal, uv);
    return out;
  }
  // The same, written field by field into `out`: the pipeline's vertex array. Returned from a
  // call and copied, the vertex went through the stack, and the copy's 16-byte loads waited on
  // the smaller stores that had built it (they cannot be forwarded).
  void shade_into(ShadedVertex& out, const glm::vec3& position, const glm::vec3* normal, const glm::vec2* uv) const {
    out.clip = mvp_ * glm::vec4(position, 1.0f);
    out.uv = uv ? *uv : glm::vec2(0.0f);
    out.light = 1.0f;
    if (lighting_.enabled) {
      // Without per-vertex normals GL uses the current normal, (0, 0, 1) by default.
      const glm::vec3 n = normal_matrix_ * (normal ? *normal : glm::vec3(0.0f, 0.0f, 1.0f));
      const float length = glm::length(n);
      const float diffuse = length > 0.0f ? std::max(0.0f, glm::dot(n / length, lighting_.direction)) : 0.0f;
      out.light = lighting_.ambient + diffuse;
    }
  }

  const glm::mat4& model_view() const { return model_view_; }
  const glm::mat4& projection() const { return projection_; }

 private:
  glm::mat4 model_view_{1.0f};
  glm::mat4 projection_{1.0f};
  glm::mat4 mvp_{1.0f};
  glm::mat3 normal_matrix_{1.0f};
  Lighting lighting_;
};

}  // namespace rastrace
