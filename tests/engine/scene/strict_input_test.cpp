// Strict scene input (issue 19): duplicate keys, keys of another shape type, derived quantities
// that overflow, counts beyond a budget and files that never end are errors naming the field,
// never a silent choice or an internal error.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"
#include "rbsim/scene/strict_json.h"
#include "test_util.h"

namespace rbsim {
namespace {

const char* const kBox = R"({"name": "a", "shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1})";

std::string sceneWith(const std::string& world, const std::string& body = kBox, const std::string& extra = "") {
  return R"({"world": {"dt": 0.01)" + world + R"(}, "bodies": [)" + body + "]" + extra + "}";
}

// The error parseSceneText throws for `text`, with "--set" `overrides`; fails the test if none.
InputError errorOf(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parseSceneText(text, "strict.json", RBSIM_TEST_DATA_DIR, overrides);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for " << text;
  return InputError("", "", "");
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(StrictJson, DuplicateKeyIsAnErrorNamingItsPath) {
  const InputError top = errorOf(R"({"bodies": [], "bodies": []})");
  EXPECT_EQ(top.field(), "bodies");
  EXPECT_TRUE(has(top.problem(), "duplicate key")) << top.what();

  const InputError nested = errorOf(sceneWith(
      "", std::string(kBox) + R"(, {"name": "b", "shape": {"type": "box", "extents": [1, 1, 1], "extents": [2, 2, 2]}, "mass": 1})"));
  EXPECT_EQ(nested.field(), "bodies[1].shape.extents") << nested.what();
}

TEST(StrictJson, SameKeyInSiblingObjectsIsFine) {
  const nlohmann::json doc = parseStrictJson(R"({"a": [{"k": 1}, {"k": 2}], "b": {"k": 3}})", "f.json");
  EXPECT_EQ(doc["a"][1]["k"], 2);
  EXPECT_EQ(doc["b"]["k"], 3);
}

TEST(StrictJson, NestingIsBounded) {
  std::string deep(100000, '[');
  const InputError e = errorOf(deep);
  EXPECT_TRUE(has(e.problem(), "nested deeper than 64")) << e.what();
  EXPECT_NO_THROW(parseStrictJson(std::string(kMaxJsonDepth - 1, '[') + std::string(kMaxJsonDepth - 1, ']'), "f.json"));
}

TEST(StrictJson, DuplicateKeyInASetValueIsAnError) {
  const InputError e = errorOf(sceneWith(""), {R"(bodies[0].shape={"type": "box", "type": "sphere"})"});
  EXPECT_TRUE(has(e.what(), "--set")) << e.what();
  EXPECT_TRUE(has(e.what(), "type: duplicate key")) << e.what();
}

TEST(StrictShape, KeysOfAnotherShapeTypeAreErrors) {
  const InputError e = errorOf(sceneWith("", R"({"shape": {"type": "sphere", "radius": 1, "extents": [1, 1, 1]}, "mass": 1})"));
  EXPECT_EQ(e.field(), "bodies[0].shape.extents");
  EXPECT_TRUE(has(e.problem(), "does not apply to a \"sphere\" shape")) << e.what();
  EXPECT_TRUE(has(e.problem(), "radius")) << e.what();
  const InputError box = errorOf(sceneWith("", R"({"shape": {"type": "box", "extents": [1, 1, 1], "radius": 2}, "mass": 1})"));
  EXPECT_EQ(box.field(), "bodies[0].shape.radius");
}

TEST(StrictCounts, UnsignedStepCountIsReportedAsWritten) {
  const InputError e = errorOf(sceneWith(R"(, "steps": 18446744073709551615)"));
  EXPECT_EQ(e.field(), "world.steps");
  EXPECT_TRUE(has(e.problem(), "18446744073709551615")) << e.what();
  EXPECT_FALSE(has(e.problem(), "-1")) << e.what();
}

TEST(StrictCounts, SolverSweepsHaveABudget) {
  const InputError e = errorOf(sceneWith(R"(, "velocity_iterations": 1000000000)"));
  EXPECT_EQ(e.field(), "world.velocity_iterations");
  EXPECT_TRUE(has(e.problem(), "at most 1000")) << e.what();
  EXPECT_NO_THROW(parseSceneText(sceneWith(R"(, "velocity_iterations": 1000)"), "s.json", RBSIM_TEST_DATA_DIR));
}

TEST(StrictCounts, BodiesTimesStepsHaveABudget) {
  const std::string crowd = R"(, "spawn": [{"count": 100, "region": {"min": [0, 0, 0], "max": [50, 50, 50]},
                                          "body": {"shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1}}])";
  const InputError e = errorOf(sceneWith(R"(, "steps": 1000000000)", kBox, crowd));
  EXPECT_EQ(e.field(), "world.steps");
  EXPECT_TRUE(has(e.problem(), "101 bodies x 1000000000 steps")) << e.what();
  EXPECT_TRUE(has(e.problem(), "hours")) << e.what();
  const InputError byDuration = errorOf(sceneWith(R"(, "duration": 1e7)", kBox, crowd));
  EXPECT_EQ(byDuration.field(), "world.duration");
  // One body may run the full 1e9 steps: 1e9 body-steps is inside the budget.
  EXPECT_EQ(parseSceneText(sceneWith(R"(, "steps": 1000000000)"), "s.json", RBSIM_TEST_DATA_DIR).stepCount(), 1000000000u);
}

TEST(StrictCounts, DurationThatRunsNoStepIsAnError) {
  const InputError e = errorOf(sceneWith(R"(, "duration": 1e-300)"));
  EXPECT_EQ(e.field(), "world.duration");
  EXPECT_TRUE(has(e.problem(), "no step")) << e.what();
  // Half a step or more rounds to one step, as every other duration rounds to the nearest step.
  EXPECT_EQ(parseSceneText(sceneWith(R"(, "duration": 0.006)"), "s.json", RBSIM_TEST_DATA_DIR).stepCount(), 1u);
}

TEST(StrictOrientation, HugeMatrixIsNotARotation) {
  // R^T R overflows to inf, its error is NaN: the test must still refuse the matrix.
  const InputError e = errorOf(sceneWith(
      "", R"({"shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1,
              "orientation": {"matrix": [[1e200, 0, 0], [0, 1e200, 0], [0, 0, 1e200]]}})"));
  EXPECT_EQ(e.field(), "bodies[0].orientation.matrix");
  EXPECT_TRUE(has(e.problem(), "rotation matrix")) << e.what();
}

TEST(StrictOrientation, HugeEntriesAreNormalisedWhenAskedTo) {
  const Scene scene = parseSceneText(
      sceneWith("", R"({"shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1,
                       "orientation": {"quaternion": [1e200, 1e200, 0, 0], "normalize": true}},
                      {"name": "m", "shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1,
                       "orientation": {"matrix": [[0, -1e200, 0], [1e200, 0, 0], [0, 0, 1e200]], "normalize": true}})"),
      "s.json", RBSIM_TEST_DATA_DIR);
  const Quat q = scene.bodies[0].orientation;
  EXPECT_NEAR(q.w(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(q.x(), std::sqrt(0.5), 1e-15);
  const Mat3 R = scene.bodies[1].orientation.toRotationMatrix();
  EXPECT_NEAR(R(1, 0), 1.0, 1e-15) << "a quarter turn about z";
  EXPECT_NEAR(R(0, 1), -1.0, 1e-15);
  const InputError zero = errorOf(sceneWith(
      "", R"({"shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1,
              "orientation": {"quaternion": [0, 0, 0, 0], "normalize": true}})"));
  EXPECT_EQ(zero.field(), "bodies[0].orientation.quaternion");
}

TEST(StrictRanges, CoordinatesSpeedsAndGravityHavePhysicalBounds) {
  // Each is finite, and each would overflow a bounding box or an offset within a step.
  const InputError plane = errorOf(sceneWith("", kBox, R"(, "planes": [{"normal": [1, 1, 0], "point": [1e308, 1e308, 0]}])"));
  EXPECT_EQ(plane.field(), "planes[0].point");
  EXPECT_TRUE(has(plane.problem(), "exceeds 1e+06 m")) << plane.what();
  const InputError fast = errorOf(sceneWith("", R"({"shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1, "velocity": [0, 3e8, 0]})"));
  EXPECT_EQ(fast.field(), "bodies[0].velocity");
  EXPECT_TRUE(has(fast.problem(), "speed of light")) << fast.what();
  const InputError spin = errorOf(sceneWith("", R"({"shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1, "angular_velocity": [0, 1e9, 0]})"));
  EXPECT_EQ(spin.field(), "bodies[0].angular_velocity");
  EXPECT_TRUE(has(spin.problem(), "faster than light")) << spin.what();
  const InputError size = errorOf(sceneWith("", R"({"shape": {"type": "box", "extents": [4e6, 1, 1]}, "mass": 1})"));
  EXPECT_EQ(size.field(), "bodies[0].shape");
  EXPECT_TRUE(has(size.problem(), "reaches 2e+06 m")) << size.what();
  const InputError gravity = errorOf(sceneWith(R"(, "gravity": [0, -1e300, 0])"));
  EXPECT_EQ(gravity.field(), "world.gravity");
  const InputError pose = errorOf(sceneWith("", R"({"shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1,
                                                  "set_pose": [{"time": 1, "position": [0, 2e6, 0]}]})"));
  EXPECT_EQ(pose.field(), "bodies[0].set_pose[0].position");
  // Just inside every bound: a scene that runs.
  EXPECT_NO_THROW(parseSceneText(sceneWith(R"(, "gravity": [0, -9.99e12, 0])",
                                           R"({"shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1,
                                               "position": [0, 9.99e5, 0], "velocity": [2.99e8, 0, 0]})"),
                                 "s.json", RBSIM_TEST_DATA_DIR));
}

TEST(StrictDerived, SpringForceThatOverflowsNamesTheStiffness) {
  const InputError e = errorOf(sceneWith(
      "", R"({"shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1,
              "springs": [{"anchor": [0, 10, 0], "stiffness": 1e308, "rest_length": 1e308}]})"));
  EXPECT_EQ(e.field(), "bodies[0].springs[0].stiffness");
  EXPECT_TRUE(has(e.problem(), "overflows")) << e.what();
}

TEST(StrictFiles, DeviceIsNotReadAsAScene) {
  try {
    readSceneFile("/dev/zero");
    FAIL() << "/dev/zero was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "/dev/zero");
    EXPECT_TRUE(has(e.problem(), "not a regular file")) << e.what();
  }
}

TEST(StrictFiles, SceneLargerThanTheLimitIsRefusedBeforeReading) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / test::uniqueTempName("huge_scene.json");
  std::ofstream(path) << "{}";
  std::filesystem::resize_file(path, std::uintmax_t{1} << 32);  // sparse: 4 GiB of nothing on disk
  try {
    readSceneFile(path.string());
    ADD_FAILURE() << "a 4 GiB scene was read";
  } catch (const InputError& e) {
    EXPECT_TRUE(has(e.problem(), "4294967296 bytes")) << e.what();
    EXPECT_TRUE(has(e.problem(), "the limit for a scene file (JSON) is 67108864 bytes")) << e.what();
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace rbsim
