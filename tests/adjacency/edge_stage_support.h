// A camera that frames a mesh, and the draw of adjacency primitives through rastrace's pipeline
// with the edge stage attached: shared by the edge-stage tests and the OSMesa cross-check.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/edge_stage.h"
#include "pipeline/pipeline.h"
#include "scenes/bounding_box.h"

namespace rastrace::testing {

struct Camera {
  glm::mat4 view{1.0f}, projection{1.0f};
};

// Looks at the mesh's bounding-box centre from `direction`, far enough to see all of it.
inline Camera frame_mesh(const Mesh& mesh, glm::vec3 direction, float aspect) {
  const BoundingBox box = bounding_box(mesh.positions);
  const glm::vec3 centre = box.centre();
  const float radius = 0.5f * glm::length(box.extent());
  Camera camera;
  const glm::vec3 eye = centre + glm::normalize(direction) * radius * 2.6f;
  camera.view = glm::lookAt(eye, centre, glm::vec3(0, 1, 0));
  camera.projection = glm::perspective(glm::radians(45.0f), aspect, radius * 0.5f, radius * 6.0f);
  return camera;
}

struct EdgeDraw {
  PipelineStats pipeline;
  EdgeStageStats edges;
  std::vector<ProcessedEdge> processed;
  std::vector<std::array<std::uint32_t, 3>> faces;
};

inline EdgeDraw draw_edges(const Mesh& mesh, const std::vector<std::uint32_t>& indices, const Camera& camera,
                           Framebuffer* lines, unsigned cache = 24, bool record = false) {
  Framebuffer scratch(lines ? lines->width() : 64, lines ? lines->height() : 64);
  PipelineOptions options;
  options.cache_entries = cache;
  Pipeline pipeline(scratch, options, nullptr);
  pipeline.set_camera(camera.view, camera.projection);
  EdgeStageOptions stage_options;
  stage_options.record = record;
  EdgeStage stage(mesh, stage_options, lines);
  pipeline.set_primitive_hook(&stage);
  DrawCall call;
  call.indices = indices;
  call.type = PrimitiveType::TriangleListAdjacency;
  pipeline.draw(mesh, glm::mat4(1.0f), call, {});
  pipeline.finish();
  return {pipeline.stats(), stage.stats(), stage.edges(), stage.faces()};
}

}  // namespace rastrace::testing
