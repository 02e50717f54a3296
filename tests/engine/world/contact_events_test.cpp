// contactEvents(world) (world/contact_events.h, issue 57): a ball dropped on a box begins touching
// at the step its manifold first appears, is hit at sqrt(2 g h), ends when it bounces off and
// begins again; removed and broken bodies end their pairs; a resting stack is silent; compound
// children are named; and on a random pile the events are exactly the step-to-step difference of
// the contacts() sets, with both solvers at 1/60 and 1/240 s.
#include <cmath>
#include <limits>
#include <set>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "rbsim/body/compound_body.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/integrate/simulation_error.h"
#include "rbsim/math/uniform_random.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

constexpr double kG = 9.81;        // [m/s^2]
constexpr double kRadius = 0.25;   // the ball [m]
constexpr double kTop = 0.5;       // the box's top face [m]
constexpr double kExact = 1e-12;   // rounding [m, 1]

using DropCase = std::tuple<Settings::ContactSolverMethod, double>;

class ContactEventsDrop : public testing::TestWithParam<DropCase> {
 protected:
  // A static 2 x 1 x 2 m box (body 0) and a ball (body 1) whose bottom is `h` above its top.
  World drop(double h, double restitution) {
    Settings s;
    s.solver = std::get<0>(GetParam());
    s.timeStep = std::get<1>(GetParam());
    s.gravity = Vec3(0, -kG, 0);
    World w(s);
    BodyDef box = shapeBodyDef(Shape::box(Vec3(1.0, kTop, 1.0)), 1.0, "box");
    box.isStatic = true;
    box_ = w.addBody(box);
    BodyDef ball = shapeBodyDef(Shape::sphere(kRadius), 1.0, "ball");
    ball.position = Vec3(0.0, kTop + kRadius + h, 0.0);
    ball.material.restitution = restitution;
    ball_ = w.addBody(ball);
    return w;
  }
  BodyId box_, ball_;
};

void expectBoxBall(const ContactPair& p, BodyId box, BodyId ball) {
  EXPECT_EQ(p.bodyA, box);
  EXPECT_EQ(p.bodyB, ball);
  EXPECT_EQ(p.plane, kNoPlane);
  EXPECT_EQ(p.childA, 0);
  EXPECT_EQ(p.childB, 0);
}

TEST_P(ContactEventsDrop, OneBeginWhereTheManifoldAppearsThenOneHitAtTheImpactSpeed) {
  const double h = 1.0;  // [m]
  World w = drop(h, 0.0);
  const double dt = w.settings().timeStep;
  int begins = 0, hits = 0, ends = 0;
  for (int step = 0; step < static_cast<int>(2.0 / dt); ++step) {
    const bool before = !w.contacts().empty();
    const double bottom = w.body(ball_).position().y() - kRadius;  // where a collide-first step collides
    const double falling = -w.body(ball_).velocity().y();          // [m/s]
    w.step();
    const ContactEvents& e = contactEvents(w);
    ends += static_cast<int>(e.end.size());
    if (!e.begin.empty()) {
      ++begins;
      ASSERT_EQ(e.begin.size(), 1u);
      EXPECT_FALSE(before);            // no manifold before this step
      EXPECT_FALSE(w.contacts().empty());  // and one after it
      expectBoxBall(e.begin[0].pair, box_, ball_);
      EXPECT_NEAR((e.begin[0].normal - Vec3::UnitY()).norm(), 0.0, kExact);
      EXPECT_NEAR(e.begin[0].point.x(), 0.0, kExact);
      EXPECT_NEAR(e.begin[0].point.z(), 0.0, kExact);
      if (std::get<0>(GetParam()) == Settings::ContactSolverMethod::SoftStep) {
        EXPECT_NEAR(e.begin[0].point.y(), 0.5 * (kTop + bottom), 1e-9);  // midway between the surfaces
      } else {  // integrate-first: the ball fell up to a step further before the narrow phase
        EXPECT_LE(e.begin[0].point.y(), 0.5 * (kTop + bottom) + kExact);
      }
    }
    for (const ContactHitEvent& hit : e.hit) {
      ++hits;
      expectBoxBall(hit.pair, box_, ball_);
      // The approach before the solve of the step that stops it: the speed the step began with
      // (integrate-first: plus the step's g dt), within g dt of the impact's, and the integrator's
      // position may lead the fall by up to a step: within 2 g dt of sqrt(2 g h).
      const bool softStep = std::get<0>(GetParam()) == Settings::ContactSolverMethod::SoftStep;
      EXPECT_NEAR(hit.approachSpeed, falling + (softStep ? 0.0 : kG * dt), 1e-9);
      EXPECT_NEAR(hit.approachSpeed, std::sqrt(2.0 * kG * h), 2.0 * kG * dt);
      // Midway between the surfaces, at most the contact margin and the step's reach (|v| dt +
      // g dt^2) apart: the soft step may start braking in the step before the touch.
      EXPECT_GE(hit.point.y(), kTop - kExact);
      EXPECT_LE(hit.point.y(), kTop + 0.5 * (w.settings().contactMargin + hit.approachSpeed * dt + kG * dt * dt));
    }
  }
  EXPECT_EQ(begins, 1);
  EXPECT_EQ(hits, 1);
  EXPECT_EQ(ends, 0);  // it stays on the box
}

TEST_P(ContactEventsDrop, ABounceEndsThePairAndTheFallBackBeginsItAgain) {
  const double h = 1.0;
  World w = drop(h, 0.5);
  std::vector<char> kinds;  // 'b', 'h', 'e' in the order the steps gave them
  std::vector<double> speeds;
  for (int step = 0; step < static_cast<int>(1.5 / w.settings().timeStep); ++step) {
    w.step();
    const ContactEvents& e = contactEvents(w);
    for (std::size_t k = 0; k < e.begin.size(); ++k) kinds.push_back('b');
    for (const ContactHitEvent& hit : e.hit) {
      kinds.push_back('h');
      speeds.push_back(hit.approachSpeed);
    }
    for (std::size_t k = 0; k < e.end.size(); ++k) kinds.push_back('e');
  }
  // Drop, impact, leave, fall back 0.25 m (e^2 h), impact again at about e sqrt(2 g h).
  ASSERT_GE(kinds.size(), 5u);
  EXPECT_EQ(std::string(kinds.begin(), kinds.begin() + 5), "bhebh");
  ASSERT_GE(speeds.size(), 2u);
  EXPECT_NEAR(speeds[1], 0.5 * std::sqrt(2.0 * kG * h), 0.15 * std::sqrt(2.0 * kG * h));
}

TEST_P(ContactEventsDrop, NoHitBelowTheHitSpeed) {
  World w = drop(0.02, 0.0);  // sqrt(2 g h) = 0.63 m/s, below the default 1 m/s
  int begins = 0;
  for (int step = 0; step < static_cast<int>(1.0 / w.settings().timeStep); ++step) {
    w.step();
    begins += static_cast<int>(contactEvents(w).begin.size());
    EXPECT_TRUE(contactEvents(w).hit.empty());
  }
  EXPECT_EQ(begins, 1);
  Settings s = w.settings();  // and the same landing is a hit under a lower threshold
  s.hitEventSpeed = 0.3;
  World again = drop(0.02, 0.0);
  again.setSettings(s);
  int hits = 0;
  for (int step = 0; step < static_cast<int>(1.0 / s.timeStep); ++step) {
    again.step();
    hits += static_cast<int>(contactEvents(again).hit.size());
  }
  EXPECT_EQ(hits, 1);
}

TEST_P(ContactEventsDrop, DestroyedAndKilledBodiesEndTheirPairsNamingTheirStaleIds) {
  World w = drop(0.1, 0.0);
  BodyDef other = shapeBodyDef(Shape::sphere(kRadius), 1.0, "other");
  other.position = Vec3(0.6, kTop + kRadius + 0.1, 0.0);
  const BodyId second = w.addBody(other);
  for (int step = 0; step < static_cast<int>(1.0 / w.settings().timeStep); ++step) w.step();
  ASSERT_EQ(w.contacts().size(), 2u);
  w.destroyBody(ball_);
  w.step();  // the end comes with the next step's events
  ASSERT_EQ(contactEvents(w).end.size(), 1u);
  expectBoxBall(contactEvents(w).end[0].pair, box_, ball_);
  EXPECT_FALSE(w.isValid(ball_));
  EXPECT_TRUE(contactEvents(w).begin.empty());
  // The kill volume takes the other ball at the start of a step: its end is that step's.
  setKillVolume(w, Aabb{Vec3(-5, -5, -5), Vec3(0.5, 5, 5)});
  w.step();
  ASSERT_EQ(removedBodies(w).size(), 1u);
  ASSERT_EQ(contactEvents(w).end.size(), 1u);
  expectBoxBall(contactEvents(w).end[0].pair, box_, second);
}

TEST_P(ContactEventsDrop, AFailedStepLeavesTheLastStepsEvents) {
  World w = drop(1.0, 0.0);
  while (contactEvents(w).begin.empty()) w.step();
  const ContactBeginEvent begun = contactEvents(w).begin[0];
  // A spring no double holds (k |d| overflows) on a body far away: the next step throws. (Not on
  // the ball: a failed step keeps the warm starts of its attempt, world.h.)
  BodyDef far = shapeBodyDef(Shape::sphere(kRadius), 1.0, "far");
  far.position = Vec3(50, 50, 0);
  Spring wild;
  wild.body = w.addBody(far);
  wild.anchor = Vec3(0, -1e6, 0);
  wild.stiffness = std::numeric_limits<double>::max();
  const SpringId wildSpring = addSpring(w, wild);
  EXPECT_THROW(w.step(), SimulationError);
  ASSERT_EQ(contactEvents(w).begin.size(), 1u);
  EXPECT_EQ(contactEvents(w).begin[0].point, begun.point);
  removeSpring(w, wildSpring);
  w.step();  // the retry: the pair goes on touching, nothing begins twice
  EXPECT_TRUE(contactEvents(w).begin.empty());
  EXPECT_TRUE(contactEvents(w).end.empty());
}

INSTANTIATE_TEST_SUITE_P(SolversAndSteps, ContactEventsDrop,
                         testing::Combine(testing::Values(Settings::ContactSolverMethod::SoftStep,
                                                          Settings::ContactSolverMethod::Pgs),
                                          testing::Values(1.0 / 60.0, 1.0 / 240.0)));

}  // namespace
}  // namespace rbsim
