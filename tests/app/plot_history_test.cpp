// The overlay's time plots (app/run/plot_history.h): each quantity against its definition, the
// window of the last seconds, and the legend of a comparison; view.plots as the scene reads it.
#include <cmath>

#include <gtest/gtest.h>

#include "rbsim/body/shape_body.h"
#include "rbsim/io/input_error.h"
#include "run/phase.h"
#include "run/plot_history.h"

namespace rbsim::app {
namespace {

World twoBodies() {
  Settings s;
  s.gravity = Vec3(0.0, -9.81, 0.0);
  s.detectCollisions = false;
  World world(s);
  BodyDef a = shapeBodyDef(Shape::box(Vec3(0.5, 0.25, 0.1)), 2.0, "a");
  a.position = Vec3(1.0, 2.0, 3.0);
  a.velocity = Vec3(0.5, -1.0, 0.0);
  a.angularVelocity = Vec3(0.0, 3.0, 1.0);
  BodyDef b = shapeBodyDef(Shape::sphere(0.3), 5.0, "b");
  b.position = Vec3(-2.0, 0.5, 0.0);
  b.velocity = Vec3(0.0, 0.0, 2.0);
  world.addBody(a);
  world.addBody(b);
  return world;
}

TEST(PlotQuantity, EachQuantityIsItsDefinition) {
  const World world = twoBodies();
  const RigidBody& a = world.bodies()[0];
  const RigidBody& b = world.bodies()[1];
  const double keA = a.kineticEnergy(), keB = b.kineticEnergy();
  const double peA = 2.0 * 9.81 * 2.0, peB = 5.0 * 9.81 * 0.5;  // m g y
  EXPECT_DOUBLE_EQ(plotQuantity("ke", world, false, 0, nullptr), keA + keB);
  EXPECT_DOUBLE_EQ(plotQuantity("pe", world, false, 0, nullptr), peA + peB);
  EXPECT_DOUBLE_EQ(plotQuantity("E", world, false, 0, nullptr), keA + peA + keB + peB);
  EXPECT_DOUBLE_EQ(plotQuantity("E", world, true, 1, nullptr), keB + peB);
  const Vec3 P = a.state().linearMomentum + b.state().linearMomentum;
  EXPECT_DOUBLE_EQ(plotQuantity("|P|", world, false, 0, nullptr), P.norm());
  EXPECT_DOUBLE_EQ(plotQuantity("|P|", world, true, 0, nullptr), std::sqrt(1.0 + 4.0));  // m |v| = 2 |(0.5, -1, 0)|
  const Vec3 L = a.position().cross(a.state().linearMomentum) + a.state().angularMomentum +
                 b.position().cross(b.state().linearMomentum) + b.state().angularMomentum;
  EXPECT_DOUBLE_EQ(plotQuantity("|L|", world, false, 0, nullptr), L.norm());
  EXPECT_DOUBLE_EQ(plotQuantity("|L|", world, true, 0, nullptr), a.state().angularMomentum.norm());
  EXPECT_EQ(plotQuantity("contacts", world, false, 0, nullptr), 0.0);
  EXPECT_TRUE(std::isnan(plotQuantity("error", world, true, 0, nullptr)));  // nothing compares it
  EXPECT_TRUE(std::isnan(plotQuantity("ke", world, true, 7, nullptr)));     // no such body
}

TEST(PlotQuantity, TheErrorIsTheFreeFlightComparison) {
  World world = twoBodies();
  FreeFlightError error(world.idAt(0));
  error.observe(world);
  for (int i = 0; i < 100; ++i) {
    world.step();
    error.observe(world);
  }
  const FreeFlightError::Reading reading = error.read(world);
  ASSERT_TRUE(reading.tracked);
  EXPECT_EQ(plotQuantity("error", world, true, 0, &error), reading.angle);
}

Phase phaseOf(const std::string& view, const std::string& compare = "") {
  const std::string text = R"({"world": {"gravity": [0, 0, 0], "dt": 0.01, "duration": 3},
    "view": )" + view + R"(, "bodies": [{"name": "box", "shape": {"type": "box", "extents": [1, 0.5, 0.2]}, "mass": 1,
    "angular_velocity": [0.1, 3, 0.1]}])" + compare + "}";
  return parsePhaseText(text, "plots.json", ".");
}

TEST(TimePlots, KeepsTheLastSecondsOfEveryWorldWithItsValueAsLegend) {
  const Phase phase = phaseOf(R"({"plots": ["ke", "|L|"], "plot_seconds": 1})",
                              R"(, "compare": {"key": "world.integrator", "values": ["euler-quat", "dlm"]})");
  std::vector<World> worlds;
  for (const PhaseWorld& w : phase.worlds) worlds.push_back(buildWorld(w.scene));
  TimePlots history(phase);
  ASSERT_FALSE(history.empty());
  for (int frame = 0; frame < 25; ++frame) {  // 2.5 s at 10 steps a frame
    for (World& w : worlds) {
      for (int i = 0; i < 10; ++i) w.step();
    }
    history.sample(worlds, nullptr);
  }
  const std::vector<render::OverlayPlot> plots = history.plots();
  ASSERT_EQ(plots.size(), 2u);
  EXPECT_EQ(plots[0].unit, "J");
  EXPECT_EQ(plots[1].unit, "kg m^2/s");
  EXPECT_EQ(plots[0].legend, (std::vector<std::string>{"euler-quat", "dlm"}));
  EXPECT_FLOAT_EQ(plots[0].tMax, 2.5f);
  EXPECT_FLOAT_EQ(plots[0].tMin, 1.5f);
  for (const render::OverlayPlot& plot : plots) {
    ASSERT_EQ(plot.values.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_EQ(plot.times[k].size(), 11u);  // 1.5, 1.6, ..., 2.5 s
      EXPECT_GE(plot.times[k].front(), 1.5f - 1e-6f);
      EXPECT_FLOAT_EQ(plot.times[k].back(), 2.5f);
    }
  }
  // dlm keeps the spin's energy; euler-quat gains it (docs/accuracy.md).
  EXPECT_GT(plots[0].values[0].back(), plots[0].values[0].front());
  EXPECT_NEAR(plots[0].values[1].back(), plots[0].values[1].front(), 1e-6f);
}

TEST(TimePlots, TheSceneChecksItsPlotKeys) {
  const auto fieldOf = [](const std::string& view) {
    try {
      phaseOf(view);
    } catch (const InputError& e) {
      return e.field() + ": " + e.problem();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(fieldOf(R"({"plots": ["ke", "E"], "plot_of": "selected", "plot_seconds": 5})"), "accepted");
  EXPECT_NE(fieldOf(R"({"plots": ["energy"]})").find("view.plots: unknown quantity energy"), std::string::npos);
  EXPECT_NE(fieldOf(R"({"plots": ["ke", "ke"]})").find("listed twice"), std::string::npos);
  EXPECT_NE(fieldOf(R"({"plots": []})").find("view.plots: expected an array of 1 to " + std::to_string(kPlotQuantities.size())), std::string::npos);
  EXPECT_NE(fieldOf(R"({"plots": ["ke"], "plot_of": "body"})").find("view.plot_of"), std::string::npos);
  EXPECT_NE(fieldOf(R"({"plots": ["ke"], "plot_seconds": 1e9})").find("view.plot_seconds: expected at most"), std::string::npos);
  EXPECT_NE(fieldOf(R"({"plots": ["ke"], "plot_seconds": -1})").find("view.plot_seconds"), std::string::npos);
}

}  // namespace
}  // namespace rbsim::app
