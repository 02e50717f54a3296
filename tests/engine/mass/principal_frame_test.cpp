// Seed 000's diagonalisation: "rotating the object space rest state by U^-1 gives a diagonal
// inertia tensor". The L-bracket (assets/meshes/l_bracket.obj), whose inertia in its file's axes
// has an off-diagonal term of 0.02 kg m^2, becomes a body with a diagonal I_body; its vertices
// in the file's coordinates come back exactly as written; and what the file says in those
// coordinates (its orientation, a force's body-frame point) lands where the file meant.
#include <cmath>

#include <gtest/gtest.h>

#include "io/obj_loader.h"
#include "rbsim/math/rotation.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"
#include "rbsim/world/queries.h"
#include "test_util.h"

namespace rbsim {
namespace {

const std::string kBracket = std::string(RBSIM_ASSET_DIR) + "/meshes/l_bracket.obj";

Scene bracketScene() {
  const nlohmann::json doc = {
      {"bodies",
       {{{"name", "bracket"},
         {"shape", {{"type", "mesh"}, {"file", kBracket}}},
         {"mass", 2.0},
         {"position", {1.0, 2.0, 3.0}},
         {"orientation", {{"axis_angle_deg", {0.0, 0.0, 1.0, 30.0}}}},
         {"forces", {{{"force", {0.0, 10.0, 0.0}}, {"point", {0.1, 0.2, 0.3}}}}}}}}};
  return parseScene(doc, "bracket.json", "/");
}

TEST(PrincipalFrame, TheLBracketsBodyInertiaIsDiagonal) {
  const Scene scene = bracketScene();
  const BodyDef& def = scene.bodies[0];
  const Mat3& I = def.inertiaBody;
  const Mat3 inFile = def.fileFrame.axes * I * def.fileFrame.axes.transpose();
  // What the file's axes give: the 0.02 kg m^2 product of inertia the issue measured.
  EXPECT_GT(std::abs(inFile(0, 1)) + std::abs(inFile(0, 2)) + std::abs(inFile(1, 2)), 0.015);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (i != j) {
        EXPECT_LE(std::abs(I(i, j)), 1e-12 * I.trace()) << i << j;
      }
    }
  }
  EXPECT_NEAR(def.fileFrame.axes.determinant(), 1.0, 1e-14);
}

TEST(PrincipalFrame, FileVerticesComeBackExactlyAndTheWorldPoseIsTheFilesOne) {
  const Scene scene = bracketScene();
  const Mesh file = loadObj(kBracket);
  World world = buildWorld(scene);
  const RigidBody& body = world.bodies()[0];
  ASSERT_EQ(body.vertexCount(), file.vertices.size());
  // The file said: its axes turned 30 degrees about z, its centre of mass at (1, 2, 3).
  const Mat3 fileToWorld = rotationFromAxisAngle(Vec3(0.0, 0.0, M_PI / 6.0));
  const Vec3& c = body.fileFrame().centre;
  for (std::size_t i = 0; i < file.vertices.size(); ++i) {
    EXPECT_EQ(body.fileVertex(i), file.vertices[i]) << i;
    EXPECT_TRUE(test::allNear(body.worldVertex(i), fileToWorld * (file.vertices[i] - c) + Vec3(1.0, 2.0, 3.0), 1e-14)) << i;
  }
  // The force's body-frame point (0.1, 0.2, 0.3) is in the file's axes about the centre of mass.
  const auto forces = activeForces(world, world.idAt(0), 0.0);
  ASSERT_EQ(forces.size(), 1u);
  EXPECT_TRUE(test::allNear(forces[0].first, fileToWorld * Vec3(0.1, 0.2, 0.3) + Vec3(1.0, 2.0, 3.0), 1e-14));
}

}  // namespace
}  // namespace rbsim
