// The engine from C++: a ball dropped onto the ground, a box on a kinematic conveyor, a World
// snapshot read back and stepped on bit for bit, a body destroyed by its id. Prints what happened
// and exits 1 if the physics is not what it should be.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <rbsim/body/shape_body.h>
#include <rbsim/world/world.h>
#include <rbsim/world/world_snapshot.h>

namespace {

// The ground, a ball 2 m up, a kinematic belt carrying a parcel: ids slot 0, 1, 2.
rbsim::World build() {
  rbsim::Settings settings;
  settings.timeStep = 1.0 / 60.0;  // [s]
  settings.integrator = rbsim::Integrator::Dlm;  // its half kicks are exact for constant gravity
  rbsim::World world(settings);
  world.addPlane(rbsim::Plane{});  // the ground, y = 0

  rbsim::BodyDef ballDef = rbsim::shapeBodyDef(rbsim::Shape::sphere(0.25), 1.0, "ball");
  ballDef.position = rbsim::Vec3(0.0, 2.0, 0.0);
  const rbsim::BodyId ball = world.addBody(ballDef);

  rbsim::BodyDef beltDef = rbsim::shapeBodyDef(rbsim::Shape::box(rbsim::Vec3(2.0, 0.05, 0.5)), 10.0, "belt");
  beltDef.isKinematic = true;
  beltDef.position = rbsim::Vec3(0.0, 0.5, 3.0);
  beltDef.velocity = rbsim::Vec3(0.5, 0.0, 0.0);
  world.addBody(beltDef);
  rbsim::BodyDef parcelDef = rbsim::shapeBodyDef(rbsim::Shape::box(rbsim::Vec3(0.2, 0.2, 0.2)), 2.0, "parcel");
  parcelDef.position = rbsim::Vec3(0.0, 0.75, 3.0);
  world.addBody(parcelDef);
  return world;
}

}  // namespace

int main() {
  rbsim::World world = build();
  const rbsim::BodyId ball = world.idAt(0), parcel = world.idAt(2);

  // Free fall for 0.5 s: y = 2 - g t^2 / 2 = 0.7737 m.
  for (int i = 0; i < 30; ++i) world.step();
  const double fallen = world.body(ball).position().y();
  for (int i = 0; i < 150; ++i) world.step();  // 3 s in all
  const double resting = world.body(ball).position().y();
  const double carried = world.body(parcel).velocity().x();
  std::printf("ball after 0.5 s: y = %.4f m (free fall: %.4f m)\n", fallen, 2.0 - 0.5 * 9.81 * 0.25);
  std::printf("ball after 3 s: y = %.4f m (radius 0.25 m)\n", resting);
  std::printf("parcel on the belt: v = %.4f m/s (belt 0.5 m/s)\n", carried);

  // A snapshot: bytes that a World built the same way (here, or in another process) reads back,
  // taking the shapes from it; both then step on bit for bit.
  const std::vector<std::uint8_t> snapshot = rbsim::saveWorldSnapshot(world);
  rbsim::World read = rbsim::loadWorldSnapshot(snapshot, build());
  for (int i = 0; i < 60; ++i) {
    world.step();
    read.step();
  }
  const bool same = read.stateHash() == world.stateHash();
  std::printf("snapshot: %zu bytes; 60 steps on, the World read from it is %s\n", snapshot.size(),
              same ? "the same, bit for bit" : "DIFFERENT");

  world.destroyBody(ball);
  std::printf("after destroying the ball: %zu bodies, ball id valid: %s\n", world.bodies().size(),
              world.isValid(ball) ? "yes" : "no");

  const bool ok = same && std::abs(fallen - (2.0 - 0.5 * 9.81 * 0.25)) < 1e-9 && std::abs(resting - 0.25) < 0.006 &&
                  std::abs(carried - 0.5) < 0.01 && !world.isValid(ball) && world.bodies().size() == 2;
  std::printf("%s\n", ok ? "ok" : "UNEXPECTED");
  return ok ? 0 : 1;
}
