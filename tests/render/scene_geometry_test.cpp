// The CPU geometry rules: flat normals point out of the body, a box has exactly its 12 edges
// outlined (not the face diagonals), and arrows have the direction and length of F * scale.
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "render/scene_geometry.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

TEST(SceneGeometry, BoxHasOutwardFlatNormalsAndTwelveOutlineEdges) {
  FrameData frame;
  const glm::mat3 rotation =
      glm::mat3(glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, 3))));
  frame.bodies.push_back(makeBox({1, 2, 3}, {0.5f, 0.25f, 1.0f}, rotation, {1, 0, 0}));
  frame.bodies[0].selected = true;
  SceneGeometry g;
  buildSceneGeometry(frame, g);
  ASSERT_EQ(g.bodies.size(), 36u);
  for (std::size_t i = 0; i < g.bodies.size(); i += 3) {
    const glm::vec3 n = g.bodies[i].normal;
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    EXPECT_EQ(n, g.bodies[i + 1].normal);
    EXPECT_EQ(n, g.bodies[i + 2].normal);
    const glm::vec3 faceCentre = (g.bodies[i].position + g.bodies[i + 1].position +
                                  g.bodies[i + 2].position) / 3.0f;
    EXPECT_GT(glm::dot(n, faceCentre - glm::vec3(1, 2, 3)), 0.0f) << "triangle " << i / 3;
  }
  EXPECT_EQ(g.edges.size(), 24u);      // 12 segments
  EXPECT_EQ(g.highlight.size(), 24u);  // selected: outlined again in the highlight colour
  EXPECT_EQ(g.axes.size(), 6u);
  EXPECT_EQ(g.axes[1].position, glm::vec3(1, 2, 3) + 0.5f * rotation[0]);  // x along R's column
}

TEST(SceneGeometry, ForceArrowHasScaledLengthAndDirection) {
  FrameData frame;
  frame.options.forceScale = 0.1f;
  frame.forces.push_back({{1, 0, 0}, {0, 20, 0}});  // 20 N up: 2 m arrow
  SceneGeometry g;
  buildSceneGeometry(frame, g);
  ASSERT_EQ(g.forceShafts.size(), 2u);
  EXPECT_EQ(g.forceShafts[0].position, glm::vec3(1, 0, 0));
  float tipY = 0.0f;
  for (const MeshVertex& v : g.arrowHeads) tipY = std::max(tipY, v.position.y);
  EXPECT_NEAR(tipY, 2.0f, 1e-5f);
  EXPECT_LT(g.forceShafts[1].position.y, 2.0f);  // the shaft stops where the cone begins
  frame.forces[0].force = glm::vec3(0.0f);        // a zero force draws nothing
  buildSceneGeometry(frame, g);
  EXPECT_TRUE(g.forceShafts.empty());
}

TEST(SceneGeometry, SmoothSurfaceAveragesNormalsAndOutlinesOnlyItsBorder) {
  // Two triangles folded 90 degrees along their shared edge (a cloth bent over a box's edge).
  static const std::vector<std::array<std::uint32_t, 3>> triangles = {{0, 1, 2}, {0, 2, 3}};
  FrameData frame;
  BodyView cloth;
  cloth.worldVertices = {{0, 0, 0}, {1, 0, 0}, {0, 0, -1}, {0, -1, 0}};
  cloth.triangles = &triangles;
  cloth.axisLength = 0.0f;
  frame.bodies.push_back(cloth);
  SceneGeometry flat;
  buildSceneGeometry(frame, flat);
  EXPECT_EQ(flat.edges.size(), 2u * 5u) << "4 border edges and the crease";
  frame.bodies[0].smooth = true;
  SceneGeometry smooth;
  buildSceneGeometry(frame, smooth);
  EXPECT_EQ(smooth.edges.size(), 2u * 4u) << "the border only";
  // Vertex 0 is shared: its normal is the normalised sum of +y and -x (equal areas 1/2).
  const glm::vec3 shared = smooth.bodies[0].normal;
  EXPECT_NEAR(shared.x, -std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(shared.y, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(smooth.bodies[1].normal.y, 1.0f, 1e-6f) << "vertex 1 is on the first triangle only";
}

}  // namespace
}  // namespace rbsim::render::test
