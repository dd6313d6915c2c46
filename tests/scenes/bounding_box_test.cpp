#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/ext/matrix_transform.hpp>

#include "scenes/bounding_box.h"

namespace rastrace {
namespace {

const std::vector<glm::vec3> kPoints = {{1, 2, 3}, {-1, 5, 0}, {4, -2, 1}, {100, 100, 100}};

TEST(BoundingBox, CornersOfAllPositions) {
  const BoundingBox box = bounding_box(kPoints);
  EXPECT_EQ(box.lo, glm::vec3(-1, -2, 0));
  EXPECT_EQ(box.hi, glm::vec3(100, 100, 100));
  EXPECT_EQ(box.extent(), glm::vec3(101, 102, 100));
  EXPECT_EQ(box.centre(), glm::vec3(49.5f, 49, 50));
}

TEST(BoundingBox, IndexedPositionsLeaveUnreferencedOnesOut) {
  const std::vector<std::uint32_t> indices = {0, 1, 2, 2, 1, 0};
  const BoundingBox box = bounding_box(kPoints, indices);
  EXPECT_EQ(box.lo, glm::vec3(-1, -2, 0));
  EXPECT_EQ(box.hi, glm::vec3(4, 5, 3));
}

TEST(BoundingBox, TransformedPositionsAndScenes) {
  const glm::mat4 move = glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, -10));
  const std::vector<glm::vec3> two = {{0, 0, 0}, {1, 1, 1}};
  const BoundingBox box = bounding_box(two, move);
  EXPECT_EQ(box.lo, glm::vec3(10, 0, -10));
  EXPECT_EQ(box.hi, glm::vec3(11, 1, -9));

  Scene scene;
  scene.objects.resize(2);
  scene.objects[0].mesh.positions = two;
  scene.objects[1].mesh.positions = two;
  scene.objects[1].transform = move;
  const BoundingBox world = bounding_box(scene);
  EXPECT_EQ(world.lo, glm::vec3(0, 0, -10));
  EXPECT_EQ(world.hi, glm::vec3(11, 1, 1));
}

TEST(BoundingBox, EmptyIsTheOriginAndNaNIsIgnored) {
  const BoundingBox empty = bounding_box(std::vector<glm::vec3>{});
  EXPECT_EQ(empty.lo, glm::vec3(0.0f));
  EXPECT_EQ(empty.hi, glm::vec3(0.0f));
  EXPECT_EQ(bounding_box(Scene{}).hi, glm::vec3(0.0f));

  const float nan = std::nanf("");
  const BoundingBox box = bounding_box(std::vector<glm::vec3>{{nan, 1, 2}, {3, nan, 4}, {5, 6, nan}});
  EXPECT_EQ(box.lo, glm::vec3(3, 1, 2));
  EXPECT_EQ(box.hi, glm::vec3(5, 6, 4));
  const BoundingBox all_nan = bounding_box(std::vector<glm::vec3>{{nan, 0, nan}});
  EXPECT_EQ(all_nan.lo, glm::vec3(0.0f));
  EXPECT_EQ(all_nan.hi, glm::vec3(0.0f));
}

}  // namespace
}  // namespace rastrace
