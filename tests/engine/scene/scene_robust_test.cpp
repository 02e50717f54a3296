// Hostile but well-formed inputs to the particle, soft, planar, fracture and spawn blocks: every
// quantity derived from the numbers (volumes, areas, moduli, offsets, momenta) is checked where it
// is computed and reported against its field; everything that scales work has a budget whose
// limit and estimate the message gives; a divergence while running is a SimulationError.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "rbsim/world/systems.h"
#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"
#include "rbsim/integrate/simulation_error.h"

namespace rbsim {
namespace {

using nlohmann::json;

// The InputError of parsing `doc`, or a failure when it parses.
InputError robustParseError(const json& doc) {
  try {
    parseScene(doc, "test.json", ".");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError for " << doc.dump();
  return InputError("", "", "");
}

void expectError(const json& doc, const std::string& field, std::initializer_list<const char*> fragments) {
  const InputError e = robustParseError(doc);
  EXPECT_EQ(e.field(), field) << e.what();
  for (const char* f : fragments) EXPECT_NE(e.problem().find(f), std::string::npos) << "missing \"" << f << "\" in: " << e.what();
}

json softScene(const json& block = json::object()) {
  json soft = {{"shape", {{"type", "box"}, {"extents", {1, 1, 1}}}}};
  soft.update(block);
  return {{"world", {{"dt", 0.005}}}, {"soft_bodies", json::array({soft})}};
}

TEST(SceneRobust, ASoftBlockWhoseTetrahedraUnderflowIsRefused) {
  expectError(softScene({{"shape", {{"type", "box"}, {"extents", {1e-300, 1e-300, 1e-300}}}}}),
              "soft_bodies[0].shape.extents", {"tetrahedron's volume is 0 m^3", "underflow"});
  // Extents of 1e300 m, whose volume would overflow, are refused by the range of lengths first.
  expectError(softScene({{"shape", {{"type", "box"}, {"extents", {1e300, 1e300, 1e300}}}}}),
              "soft_bodies[0].shape.extents", {"at most 1e6 m"});
}

TEST(SceneRobust, ASoftBlockWhoseLameConstantsOverflowIsRefused) {
  // E = 1e308 Pa (lambda = inf) is refused by the range of moduli before Lame's constants.
  expectError(softScene({{"youngs_modulus", 1e308}, {"poisson_ratio", 0.45}}), "soft_bodies[0].youngs_modulus",
              {"at most 1e13 Pa"});
  expectError(softScene({{"density", 1e-320}}), "soft_bodies[0].density", {"kg", "inverses are finite"});
}

TEST(SceneRobust, SoftMeshResolutionHasAWorkBudget) {
  expectError(softScene({{"shape", {{"type", "box"}, {"extents", {1, 1, 1}}, {"cells", {40, 40, 40}}}}}),
              "soft_bodies[0].shape.cells", {"384000 tetrahedra", "1.92768e+08 element evaluations per step", "backward-euler",
                                            "the limit is 2.5e+07 per step"});
  // The explicit step evaluates each element once: the documented 60 cells per axis run.
  const Scene scene = parseScene(softScene({{"shape", {{"type", "box"}, {"extents", {1, 1, 1}}, {"cells", {60, 60, 60}}}},
                                            {"integrator", "symplectic-euler"}}),
                                 "test.json", ".");
  EXPECT_EQ(scene.softBodies[0].mesh.tets.size(), 6u * 60 * 60 * 60);
}

TEST(SceneRobust, ATinySoftBlockPinsOneFaceOnly) {
  const Scene scene = parseScene(softScene({{"shape", {{"type", "box"}, {"extents", {1e-13, 1e-13, 1e-13}}}}, {"pin", "-x"}}),
                                 "test.json", ".");
  EXPECT_EQ(scene.softBodies[0].pinned.size(), 9u) << "the 3 x 3 nodes of the -x face of 2 x 2 x 2 cells";
}

TEST(SceneRobust, ASoftBodyWhoseForcesStopBeingFiniteStopsTheRun) {
  Scene scene = parseScene(softScene(), "test.json", ".");
  World world = buildWorld(scene);
  softBodies(world)[0].positions()[3].x() = std::nan("");
  try {
    world.step();
    FAIL() << "expected a SimulationError";
  } catch (const SimulationError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("step 0"), std::string::npos) << what;
    EXPECT_NE(what.find("soft body 'soft0'"), std::string::npos) << what;
    EXPECT_NE(what.find("internal forces (elastic and damping) stopped being finite"), std::string::npos) << what;
  }
}

json planarScene(const json& shape, const json& extra = json::object()) {
  json body = {{"name", "p"}, {"shape", shape}, {"position", {0, 2}}};
  body.update(extra);
  return {{"world", {{"dt", 0.01}}}, {"planar", {{"lines", json::array({{{"normal", {0, 1}}}})}, {"bodies", json::array({body})}}}};
}

TEST(SceneRobust, ASelfIntersectingPolygonIsNotConvex) {
  const json star = {{"type", "polygon"},
                     {"corners", {{1, 0}, {-0.809, 0.588}, {0.309, -0.951}, {0.309, 0.951}, {-0.809, -0.588}}}};
  expectError(planarScene(star), "planar.bodies[0].shape.corners", {"wound once counter-clockwise", "add up to 2 revolutions"});
}

TEST(SceneRobust, APolygonWhoseAreaOverflowsOrUnderflowsIsRefused) {
  const json huge = {{"type", "polygon"}, {"corners", {{-1e200, -1e200}, {1e200, -1e200}, {0, 1e200}}}};
  expectError(planarScene(huge), "planar.bodies[0].shape.corners", {"turn at corner 1 is inf m^2"});
  const json box = {{"type", "box"}, {"extents", {1e300, 1e300}}};
  expectError(planarScene(box), "planar.bodies[0].shape", {"area is inf m^2"});
  const json tiny = {{"type", "polygon"}, {"corners", {{0, 0}, {1e-200, 0}, {0, 1e-200}}}};
  expectError(planarScene(tiny), "planar.bodies[0].shape.corners", {"turn at corner 1 is 0 m^2"});
  expectError(planarScene({{"type", "box"}, {"extents", {1, 1}}}, {{"velocity", {1e308, 0}}, {"mass", 10}}),
              "planar.bodies[0].velocity", {"m v = 10 kg x 1e+308 m/s overflows"});
}

TEST(SceneRobust, PlanarBodyCountHasAWorkBudget) {
  json doc = planarScene({{"type", "box"}, {"extents", {0.1, 0.1}}});
  json& bodies = doc["planar"]["bodies"];
  for (int i = 1; i < 3000; ++i) bodies.push_back({{"name", "b" + std::to_string(i)}, {"shape", bodies[0]["shape"]}});
  expectError(doc, "planar.bodies", {"contact detection tests", "the limit is 5e+07 per step"});
}

TEST(SceneRobust, APlanarBodyThatDivergesStopsTheRunNamingIt) {
  json doc = planarScene({{"type", "box"}, {"extents", {1, 1}}}, {{"velocity", {1.7e308, 0}}});
  doc["world"]["dt"] = 0.1;  // x gains 1.7e307 m a step: it overflows within a dozen
  doc["world"]["gravity"] = {0, 0, 0};  // no fall onto the line first
  const Scene scene = parseScene(doc, "test.json", ".");
  World world = buildWorld(scene);
  try {
    for (int s = 0; s < 100; ++s) world.step();
    FAIL() << "expected a SimulationError";
  } catch (const SimulationError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("planar body 'p': position stopped being finite at step"), std::string::npos) << what;
    EXPECT_NE(what.find("|v| = 1.7e+308 m/s"), std::string::npos) << what;
  }
}

json wallWithPlanes(const json& planes) {
  return {{"world", {{"dt", 0.01}, {"inertia", "exact"}}},
          {"bodies", json::array({{{"name", "wall"},
                                   {"shape", {{"type", "box"}, {"extents", {2, 1, 0.2}}}},
                                   {"mass", 40},
                                   {"fracture", {{"threshold", 5}, {"planes", planes}}}}})}};
}

TEST(SceneRobust, ACutPlaneWhoseOffsetOverflowsIsRefused) {
  expectError(wallWithPlanes(json::array({{{"normal", {1e308, 1e308, 0}}, {"point", {1.7e308, 1.7e308, 0}}}})),
              "bodies[0].fracture.planes[0].point", {"offset n . p overflows (inf m)"});
}

TEST(SceneRobust, FractureByPlanesHasAPieceBudget) {
  json planes = json::array();
  for (int i = 0; i < 40; ++i) planes.push_back({{"normal", {1, 0, 0}}, {"point", {-0.99 + 0.02 * i, 0, 0}}});
  for (int i = 0; i < 10; ++i) planes.push_back({{"normal", {0, 1, 0}}, {"point", {0, -0.45 + 0.1 * i, 0}}});
  expectError(wallWithPlanes(planes), "bodies[0].fracture.planes", {"brings the body to at least 257 pieces", "the limit is 256 pieces"});
  json many = json::array();
  for (int i = 0; i < 300; ++i) many.push_back({{"normal", {1, 0, 0}}, {"point", {0, 0, 0}}});
  expectError(wallWithPlanes(many), "bodies[0].fracture.planes", {"at most 255 planes", "got 300"});
}

json spawnScene(const json& block) {
  json spawn = {{"count", 3}, {"region", {{"min", {0, 0, 0}}, {"max", {1, 1, 1}}}},
                {"body", {{"shape", {{"type", "box"}, {"extents", {1, 1, 1}}}}, {"mass", 10}}}};
  spawn.update(block);
  return {{"world", {{"dt", 0.01}}}, {"spawn", json::array({spawn})}};
}

TEST(SceneRobust, SpawnRegionsAndMomentaMustBeFinite) {
  // Corners and speeds whose extent or momentum would overflow are refused by the ranges first.
  expectError(spawnScene({{"region", {{"min", {-1e308, 0, 0}}, {"max", {1e308, 1, 1}}}}}), "spawn[0].region.min",
              {"exceeds 1e+06 m"});
  expectError(spawnScene({{"speed", {0, 1e308}}}), "spawn[0].speed", {"speed of light"});
}

TEST(SceneRobust, SpawnCountHasAVertexBudget) {
  expectError(spawnScene({{"count", 100000}, {"body", {{"shape", {{"type", "sphere"}, {"radius", 0.1}}}, {"mass", 1}}}}),
              "spawn[0].count", {"100000 bodies of", "the limit is 2e+07 vertices"});
}

json particleScene(const json& system = json::object()) {
  json p = {{"emitters", json::array({{{"type", "point"}}})}};
  p.update(system);
  return {{"world", {{"dt", 0.01}}}, {"particles", json::array({p})}};
}

TEST(SceneRobust, AFlockOfAHundredThousandIsRefusedWithItsEstimate) {
  expectError(particleScene({{"capacity", 100000}, {"flock", {{"radius", 1}}}}), "particles[0].flock",
              {"capacity 100000 x 1 substeps", "1e+10 flock neighbour tests (100000 boids alive at most",
               "the limit is 4e+08 per step"});
  // A flock that its emitters cannot fill is judged by what can be alive: 100 boids.
  EXPECT_NO_THROW(parseScene(particleScene({{"capacity", 100000}, {"flock", {{"radius", 1}}},
                                            {"emitters", json::array({{{"type", "point"}, {"rate", 0}, {"burst", 100}}})}}),
                             "test.json", "."));
  expectError(particleScene({{"capacity", 10000000}, {"substeps", 10}}), "particles[0].capacity", {"1e+08 particle updates"});
  // The largest store runs with one substep.
  EXPECT_NO_THROW(parseScene(particleScene({{"capacity", 10000000}}), "test.json", "."));
}

TEST(SceneRobust, ParticleQuantitiesDerivedFromFiniteNumbersMustBeFinite) {
  const auto emitter = [](const json& e) {
    json def = {{"type", "point"}};
    def.update(e);
    return particleScene({{"emitters", json::array({def})}});
  };
  expectError(emitter({{"rate", 1e12}}), "particles[0].emitters[0].rate", {"at most 1e+09 particles/s"});
  expectError(emitter({{"mass", 1e-320}}), "particles[0].emitters[0].mass", {"inverse is finite"});
  expectError(emitter({{"type", "disc"}, {"position", {1e308, 0, 0}}, {"radius", 1e308}}), "particles[0].emitters[0].position",
              {"exceeds 1e+06 m"});
  expectError(particleScene({{"attractors", json::array({{{"strength", 1e300}, {"softening", 1e-10}}})}}),
              "particles[0].attractors[0].softening", {"strength / softening^2 = inf N"});
  expectError(particleScene({{"gravity_scale", 1e308}}), "particles[0].gravity_scale", {"overflows"});
  json clothScene = particleScene({{"cloth", {{"resolution", {100, 100}}, {"mass", 1e-320}}}});
  clothScene["particles"][0].erase("emitters");
  expectError(clothScene, "particles[0].cloth.mass", {"inverse is finite"});
}

TEST(SceneRobust, AParticleThatDivergesStopsTheRunInThatStep) {
  World world = buildWorld(parseScene(particleScene(), "test.json", "."));
  world.step();
  ASSERT_GT(particleSystems(world)[0].particles().count(), 0u);
  particleSystems(world)[0].particles().velocity[0].y() = INFINITY;
  try {
    world.step();  // step 1, long before the interval check of step 16
    FAIL() << "expected a SimulationError";
  } catch (const SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("particle system 'particles_0': particle 0 left the finite numbers"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rbsim
