// Implicit bodies collide through their exact function (collision/body_solid.h, issue 36): the
// grid only finds candidates, depths and normals are phi's and grad phi's, and the body's samples
// keep its sharp edges and corners (geometry/feature_points.h). A box made as an implicit rests on
// its true corners at 16 cells as at 128, and a box resting across an implicit table's edge stays
// as it does on a convex table, where the grid's bevelled edge would have let it tip.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "rbsim/collision/body_solid.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"
#include "../../sanitized_build.h"

namespace rbsim {
namespace {

using nlohmann::json;

Scene parse(const json& doc) { return parseScene(doc, "test.json", RBSIM_TEST_DATA_DIR); }

json implicitBox(const Vec3& extents, int resolution) {
  return {{"type", "implicit"}, {"function", "box"}, {"extents", {extents.x(), extents.y(), extents.z()}}, {"resolution", resolution}};
}
json convexBox(const Vec3& extents) { return {{"type", "box"}, {"extents", {extents.x(), extents.y(), extents.z()}}}; }

TEST(ImplicitContact, DepthAndNormalAreTheFunctionsNotTheGrids) {
  const Vec3 half(0.5, 0.2, 0.3);
  const Scene scene = parse({{"bodies", {{{"name", "b"}, {"shape", implicitBox(2.0 * half, 16)}, {"mass", 1.0}}}}});
  const BodySolid solid = bodySolidOf(scene.bodies[0]);
  ASSERT_TRUE(solid.implicit && solid.sdf);
  // The body frame may permute the file's axes (principal axes): points are written in the file
  // frame and carried over, p_body = axes^T (p_file - centre).
  const FileFrame& frame = scene.bodies[0].fileFrame;
  const auto query = [&](const Vec3& file) {
    const SurfaceQuery q = querySurface(solid, frame.axes.transpose() * (file - frame.centre));
    return std::make_pair(q.distance, Vec3(frame.axes * q.normal));
  };
  // Near an edge, outside and inside, and near a corner: the box's exact distance.
  struct Case { Vec3 p; double distance; Vec3 normal; };
  const double s = std::sqrt(0.5);
  const Case cases[] = {{Vec3(0.51, 0.21, 0.0), 0.01 * std::sqrt(2.0), Vec3(s, s, 0.0)},
                        {Vec3(0.49, 0.195, 0.1), -0.005, Vec3::UnitY()},
                        {Vec3(0.503, 0.204, 0.2), 0.005, Vec3(0.6, 0.8, 0.0)},
                        {Vec3(-0.2, -0.23, 0.34), 0.05, Vec3(0.0, -0.6, 0.8)}};
  for (const Case& c : cases) {
    const auto [distance, normal] = query(c.p);
    EXPECT_NEAR(distance, c.distance, 1e-9) << c.p.transpose();
    EXPECT_LT((normal - c.normal).norm(), 1e-5) << c.p.transpose() << ": " << normal.transpose();
  }
}

struct Rest {
  Vec3 position;
  Vec3 footprint = Vec3::Zero();  // extent of the ground contact's points along the box's x, y, z [m]
};

Rest restOnGround(const json& shape, double dt) {
  const Scene scene = parse({{"world", {{"dt", dt}, {"sleep", false}}},
                             {"bodies", {{{"name", "b"}, {"shape", shape}, {"density", 500.0}, {"position", {0.0, 0.25, 0.0}}}}},
                             {"planes", {{{"normal", {0, 1, 0}}}}}});
  World world = buildWorld(scene);
  for (int s = 0; s < static_cast<int>(std::lround(1.5 / dt)); ++s) world.step();
  // In the file's frame, p_file = axes R^T (p - x) + centre, so that a slight turn does not count.
  const RigidBody& body = world.bodies()[0];
  const FileFrame& frame = scene.bodies[0].fileFrame;
  Vec3 lo = Vec3::Constant(1e9), hi = Vec3::Constant(-1e9);
  for (const Contact& c : world.contacts()) {
    if (c.kind != Contact::Kind::PlaneBody) continue;
    for (int k = 0; k < c.manifold.count; ++k) {
      const Vec3 p = frame.axes * (body.rotation().transpose() * (c.manifold.points[k].position - body.position())) + frame.centre;
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  return {world.bodies()[0].position(), hi - lo};
}

TEST(ImplicitContact, AnImplicitBoxRestsOnItsTrueCornersAtAnyResolution) {
  const Vec3 extents(1.0, 0.4, 0.6);
  for (double dt : {1.0 / 60.0, 1.0 / 240.0}) {
    const Rest convex = restOnGround(convexBox(extents), dt);
    // Under the sanitizers the coarse grid alone: the fine one is the same code on 500 times the cells.
    for (int resolution : test::kSanitizedBuild ? std::vector<int>{16} : std::vector<int>{16, 128}) {
      const Rest implicit = restOnGround(implicitBox(extents, resolution), dt);
      // The four corners: the footprint is the box's, not the bevelled mesh's (a cell smaller).
      EXPECT_NEAR(implicit.footprint.x(), extents.x(), 1e-6) << resolution << " cells, dt " << dt;
      EXPECT_NEAR(implicit.footprint.z(), extents.z(), 1e-6) << resolution << " cells, dt " << dt;
      EXPECT_NEAR(implicit.position.y(), convex.position.y(), 1e-4) << resolution << " cells, dt " << dt;
    }
  }
}

// A 0.2 m cube whose centre is 0.03 m in from the edge of a 1 m table: over the table, so it
// stays. A grid of 16 cells bevels the table's edge over up to a cell (0.07 m), and a cube held
// by the bevelled mesh's samples finds no support under its centre and tips over the edge.
Quat cubeOnTableEdge(const json& table, double dt) {
  const Scene scene = parse({{"world", {{"dt", dt}, {"sleep", false}}},
                             {"bodies",
                              {{{"name", "table"}, {"shape", table}, {"mass", 1.0}, {"static", true}, {"position", {0.0, 0.1, 0.0}}},
                               {{"name", "cube"}, {"shape", convexBox(Vec3::Constant(0.2))}, {"density", 500.0},
                                {"position", {0.47, 0.3005, 0.0}}}}}});
  World world = buildWorld(scene);
  for (int s = 0; s < static_cast<int>(std::lround(2.0 / dt)); ++s) world.step();
  EXPECT_GT(world.bodies()[1].position().y(), 0.25);
  return world.bodies()[1].orientation();
}

TEST(ImplicitContact, ACubeOverAnImplicitTablesEdgeStaysAsOnAConvexTable) {
  // 1.13 m deep, so the grid's cells (1.13 / 16 m) do not meet the table's edges at x = +-0.5 m.
  const Vec3 table(1.0, 0.2, 1.13);
  for (double dt : {1.0 / 60.0, 1.0 / 240.0}) {
    const Quat convex = cubeOnTableEdge(convexBox(table), dt);
    const Quat implicit = cubeOnTableEdge(implicitBox(table, 16), dt);
    EXPECT_LT(convex.angularDistance(Quat::Identity()), 1e-3) << dt;
    EXPECT_LT(implicit.angularDistance(Quat::Identity()), 1e-3) << dt;
  }
}

// Continuous collision sweeps an implicit body as the hull of its mesh: an implicit torus thrown
// at 40 m/s onto a 1 cm plate at 1/60 s (0.67 m a step, against a 0.16 m thick ring) stops on it.
TEST(ImplicitContact, AFastImplicitTorusDoesNotTunnelThroughAThinPlate) {
  for (const char* solver : {"soft-step", "pgs"}) {
    const Scene scene = parse({{"world", {{"dt", 1.0 / 60.0}, {"solver", solver}, {"ccd", true}}},
                               {"bodies",
                                {{{"name", "plate"}, {"shape", convexBox(Vec3(2.0, 0.01, 2.0))}, {"mass", 1.0}, {"static", true}},
                                 {{"name", "ring"},
                                  {"shape", {{"type", "implicit"}, {"function", "torus"}, {"major_radius", 0.3}, {"minor_radius", 0.08}, {"resolution", 32}}},
                                  {"density", 500.0}, {"position", {0.0, 1.0, 0.0}}, {"velocity", {0.0, -40.0, 0.0}}}}}});
    ASSERT_TRUE(scene.bodies[1].implicit);
    World world = buildWorld(scene);
    for (int s = 0; s < 60; ++s) world.step();
    EXPECT_GT(world.bodies()[1].position().y(), 0.0) << solver << ": it went through the plate";
  }
}

}  // namespace
}  // namespace rbsim
