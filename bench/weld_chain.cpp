// Issue 55 item 3: what the weld's solve realises. A 1 m box of 1 kg welded by its end to the world
// (the cantilever of JointTypes.WeldHoldsACantileverWithinItsSoftness) and a chain of ten 0.1 m
// links of 0.1 kg (and one of five 0.2 m links of 1 kg) welded end to end from the world, all rigid (0 Hz) welds, at dt = 1/60 and 1/240 s: the
// tip's droop after 10 s against the ideal rigid weld's (0) and against the static droop the
// joints' softness predicts for the coupled 6x6 block and for the split 3 + 3 form; its drift
// over the last 5 s; and the wall time per step of 100 such chains (1000 welds), with gravity and
// without (no contacts, the solve's own cost), single-threaded.
// Run: build/bench/weld_chain
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "rbsim/dynamics/impulse.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/world/world.h"

namespace {

using namespace rbsim;

constexpr double kGravity = 9.81;           // [m/s^2]
constexpr double kLinkLength = 0.1;         // [m]
constexpr double kLinkWidth = 0.02;         // [m]
constexpr double kLinkMass = 0.1;           // [kg]
constexpr int kChainLinks = 10;             // [links]
// A chain the joints' softness holds to small angles: five 0.2 m links of 1 kg.
constexpr int kShortLinks = 5;              // [links]
constexpr double kShortLength = 0.2;        // [m]
constexpr double kShortWidth = 0.05;        // [m]
constexpr double kShortMass = 1.0;          // [kg]
constexpr int kTimedChains = 100;           // [chains]
constexpr double kChainSpacing = 0.5;       // between the timed chains, along z [m]
constexpr double kSettleTime = 10.0;        // [s]
constexpr double kDriftWindow = 5.0;        // the drift is the tip's change over the run's last [s]
constexpr double kTimedSeconds = 2.0;       // simulated for the timing, after 0.5 s of warm-up [s]
constexpr int kTimingRepeats = 3;           // the fastest of these is reported [runs]

Settings settingsFor(double dt) {
  Settings s;
  s.timeStep = dt;
  s.gravity = Vec3(0.0, -kGravity, 0.0);
  s.allowSleep = false;
  s.threads = 1;  // single-threaded, as the header says: the default is every core
  return s;
}

// A chain of `links` boxes of length `length` along +x from the world at (0, 0, z), each welded
// to the one before it (the first to the world) at their shared end. Returns the last link's index.
std::size_t addChain(World& world, int links, double length, double width, double mass, double z) {
  const Vec3 extents(length, width, width);
  const auto mesh = std::make_shared<const Mesh>(makeBox(extents));
  for (int i = 0; i < links; ++i) {
    BodyDef def;
    def.name = "link";
    def.mesh = mesh;
    def.mass = mass;
    def.inertiaBody = cuboidInertia(mass, extents);
    def.position = Vec3((i + 0.5) * length, 0.0, z);
    world.addBody(def);
    JointDef weld;
    weld.type = JointDef::Type::Weld;
    weld.bodyA = world.idAt(world.bodies().size() - 1);
    if (i > 0) weld.bodyB = world.idAt(world.bodies().size() - 2);
    weld.anchor = Vec3(i * length, 0.0, z);
    world.addJoint(weld);
  }
  return world.bodies().size() - 1;
}

// The tip's drop below the anchor's height [m]: the far end of the last link.
double tipDroop(const World& world, std::size_t last, double length) {
  return -world.bodies()[last].bodyToWorld(Vec3(0.5 * length, 0.0, 0.0)).y();
}

// The static droop of the tip the joints' softness predicts, to first order about the straight
// chain: each weld k holds the links beyond it with F_k = (W_k y, M_k z) (their weight at the
// anchor, their moment about it) and gives way by C_k = -K_k F_k / omega^2 (softness.h's steady
// state, omega the joints' 120 Hz capped at a quarter of the substep rate), K_k the coupled
// block (seed 002's K of both links at the anchor) or, split, its point block and (iA + iB) alone.
double predictedDroop(int links, double length, double width, double mass, double dt, bool coupled) {
  const double h = dt / Settings{}.substeps;
  const double omega = 2.0 * M_PI * std::min(120.0, 0.25 / h);  // soft_step_joints.cpp's kJointHertz, cap [rad/s]
  const Mat3 inverseInertia = cuboidInertia(mass, Vec3(length, width, width)).inverse();
  double droop = 0.0;
  for (int k = 0; k < links; ++k) {
    double moment = 0.0;  // [N m]
    for (int j = k; j < links; ++j) moment += mass * kGravity * (j - k + 0.5) * length;
    Vec6 load;
    load << 0.0, (links - k) * mass * kGravity, 0.0, 0.0, 0.0, moment;
    Mat6 K = coupledImpulseFactor(1.0 / mass, inverseInertia, Vec3(-0.5 * length, 0.0, 0.0));
    if (k > 0) K += coupledImpulseFactor(1.0 / mass, inverseInertia, Vec3(0.5 * length, 0.0, 0.0));
    if (!coupled) {
      K.topRightCorner<3, 3>().setZero();
      K.bottomLeftCorner<3, 3>().setZero();
    }
    const Vec6 C = -K * load / (omega * omega);
    droop += -C.y() - C(5) * (links - k) * length;
  }
  return droop;
}

void measureDroop(const char* name, int links, double length, double width, double mass, double dt) {
  World world(settingsFor(dt));
  const std::size_t last = addChain(world, links, length, width, mass, 0.0);
  const int steps = static_cast<int>(std::lround(kSettleTime / dt));
  const int windowStart = steps - static_cast<int>(std::lround(kDriftWindow / dt));
  double before = 0.0;
  for (int i = 0; i < steps; ++i) {
    if (i == windowStart) before = tipDroop(world, last, length);
    world.step();
  }
  const double droop = tipDroop(world, last, length);
  std::printf("%-22s dt 1/%.0f s: tip droop %.4e m (rigid weld: 0; softness predicts %.4e coupled, %.4e split), "
              "drift over the last %.0f s %.2e m\n",
              name, 1.0 / dt, droop, predictedDroop(links, length, width, mass, dt, true),
              predictedDroop(links, length, width, mass, dt, false), kDriftWindow, droop - before);
}

void measureTime(double dt, bool gravity) {
  double best = 1e300;
  for (int run = 0; run < kTimingRepeats; ++run) {
    Settings settings = settingsFor(dt);
    if (!gravity) settings.gravity = Vec3::Zero();
    World world(settings);
    for (int c = 0; c < kTimedChains; ++c) addChain(world, kChainLinks, kLinkLength, kLinkWidth, kLinkMass, c * kChainSpacing);
    for (int i = 0; i < static_cast<int>(std::lround(0.5 / dt)); ++i) world.step();
    const int steps = static_cast<int>(std::lround(kTimedSeconds / dt));
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) world.step();
    const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
    best = std::min(best, elapsed.count() / steps);
  }
  std::printf("%d chains of %d welded links, %s, dt 1/%.0f s: %.3f ms per step (best of %d)\n", kTimedChains, kChainLinks,
              gravity ? "gravity" : "no gravity", 1.0 / dt, best, kTimingRepeats);
}

}  // namespace

int main() {
  for (double dt : {1.0 / 60.0, 1.0 / 240.0}) {
    measureDroop("cantilever (1 m, 1 kg)", 1, 1.0, 0.1, 1.0, dt);
    measureDroop("chain of 5 links", kShortLinks, kShortLength, kShortWidth, kShortMass, dt);
    measureDroop("chain of 10 links", kChainLinks, kLinkLength, kLinkWidth, kLinkMass, dt);
    measureTime(dt, true);
    measureTime(dt, false);
  }
  return 0;
}
