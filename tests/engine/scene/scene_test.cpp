// scene/: parseScene on documents built in the test, loadScene on files written to a temporary
// directory, and --set overrides. Every error must name the JSON path (or line and column).
#include "rbsim/scene/scene.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "rbsim/io/input_error.h"
#include "rbsim/math/rotation.h"
#include "rbsim/world/queries.h"
#include "test_util.h"

namespace rbsim {
namespace {

using nlohmann::json;
using test::allNear;

json boxBody(const std::string& name = "box") {
  return {{"name", name}, {"shape", {{"type", "box"}, {"extents", {1.0, 2.0, 3.0}}}}, {"mass", 2.0}};
}

json minimalScene() { return {{"world", {{"dt", 0.01}}}, {"bodies", json::array({boxBody()})}}; }

InputError parseError(const json& doc) {
  try {
    parseScene(doc, "test.json", RBSIM_TEST_DATA_DIR);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "parseScene did not throw InputError for " << doc.dump();
  return InputError("", "", "");
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A fresh directory per test, removed afterwards.
class SceneFiles : public testing::Test {
 protected:
  void SetUp() override {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() / test::uniqueTempName(info->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::filesystem::path path = dir_ / name;
    std::ofstream(path) << text;
    return path.string();
  }
  std::filesystem::path dir_;
};

// Euler angles as scene input (issue 55): yaw about z, pitch about y', roll about x'', degrees,
// the convention math/rotation.h states; the same pose as the axis-angle product it names.
TEST(ParseScene, TakesEulerAnglesYawPitchRoll) {
  const json doc = json::parse(R"({
    "world": {"dt": 0.01, "duration": 0.1},
    "bodies": [{"name": "box", "shape": {"type": "box", "extents": [1, 2, 3]}, "mass": 1,
                "orientation": {"euler_zyx_deg": [30, -20, 75]}}]})");
  const Scene scene = parseScene(doc, "test.json", RBSIM_TEST_DATA_DIR);
  const Mat3 expected = rotationFromAxisAngle(Vec3(0, 0, M_PI / 6)) * rotationFromAxisAngle(Vec3(0, -M_PI / 9, 0)) *
                        rotationFromAxisAngle(Vec3(5 * M_PI / 12, 0, 0));
  EXPECT_TRUE(allNear(scene.bodies[0].orientation.toRotationMatrix(), expected, 1e-14));
  json bad = doc;
  bad["bodies"][0]["orientation"] = {{"euler_zyx_deg", {30, 20}}};
  try {
    parseScene(bad, "test.json", RBSIM_TEST_DATA_DIR);
    FAIL() << "two angles accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bodies[0].orientation.euler_zyx_deg"), std::string::npos) << e.what();
  }
}

TEST(ParseScene, BuildsTheExpectedBodies) {
  const json doc = json::parse(R"({
    "title": "two bodies",
    "world": {"gravity": [0, 0, -1], "dt": 0.005, "integrator": "euler-quat", "duration": 2.0},
    "bodies": [
      {"name": "box", "shape": {"type": "box", "extents": [1, 2, 3]}, "density": 7,
       "position": [1, 2, 3], "velocity": [0, 1, 0], "angular_velocity": [0, 0, 1],
       "orientation": {"axis_angle_deg": [0, 0, 1, 90]},
       "forces": [{"force": [1, 0, 0], "point": [0, 0.5, 0], "start": 0.5, "end": 1.0}],
       "set_pose": [{"time": 1.5, "position": [0, 0, 0]}]},
      {"name": "tet", "shape": {"type": "mesh", "file": "tetrahedron.obj", "scale": 2},
       "mass": 3, "inertia": "exact"}
    ]})");
  const Scene scene = parseScene(doc, "test.json", RBSIM_TEST_DATA_DIR);
  EXPECT_EQ(scene.title, "two bodies");
  EXPECT_TRUE(allNear(scene.settings.gravity, Vec3(0, 0, -1), 0.0));
  EXPECT_EQ(scene.settings.timeStep, 0.005);
  EXPECT_EQ(scene.settings.integrator, Integrator::EulerQuat);
  EXPECT_EQ(scene.stepCount(), 400u);
  ASSERT_EQ(scene.bodies.size(), 2u);

  const BodyDef& box = scene.bodies[0];
  EXPECT_EQ(box.name, "box");
  EXPECT_NEAR(box.mass, 42.0, 1e-13) << "density 7 x 6 m^3";
  EXPECT_TRUE(allNear(box.inertiaBody, cuboidInertia(42.0, Vec3(1, 2, 3)), 1e-13));
  EXPECT_TRUE(allNear(box.position, Vec3(1, 2, 3), 0.0));
  EXPECT_TRUE(allNear(box.orientation.toRotationMatrix(), rotationFromAxisAngle(Vec3(0, 0, M_PI / 2)), 1e-15));
  EXPECT_TRUE(allNear(box.velocity, Vec3(0, 1, 0), 0.0));
  EXPECT_TRUE(allNear(box.angularVelocity, Vec3(0, 0, 1), 0.0));

  // The tetrahedron scaled by 2 has m = 8/6 at unit density and I = 2^5 I_unit about its
  // centroid (I_unit: 1/80 on, 1/480 off the diagonal); 3 kg scales that by 3 / (8/6).
  const BodyDef& tet = scene.bodies[1];
  EXPECT_EQ(tet.mass, 3.0);
  // In the file's axes that is 72/80 on and 72/480 off the diagonal; the body frame is the
  // principal frame (seed 000), where it is diag(72/80 - 72/480, same, 72/80 + 2 x 72/480).
  const Mat3 inFile = tet.fileFrame.axes * tet.inertiaBody * tet.fileFrame.axes.transpose();
  EXPECT_NEAR(inFile(0, 0), 72.0 / 80.0, 1e-14);
  EXPECT_NEAR(inFile(0, 1), 72.0 / 480.0, 1e-14);
  EXPECT_TRUE(allNear(tet.inertiaBody, Mat3(Vec3(0.75, 0.75, 1.2).asDiagonal()), 1e-14));
  EXPECT_TRUE(allNear(tet.fileFrame.axes * tet.mesh->vertices[0], Vec3::Constant(-0.5), 1e-15))
      << "re-centred on the centroid";
  EXPECT_EQ(scene.inertiaMethods, (std::vector<std::string>{"exact", "exact"}));

  ASSERT_EQ(scene.forces.size(), 1u);
  EXPECT_EQ(scene.forces[0].body, sceneBodyId(0));
  EXPECT_EQ(scene.forces[0].forceFrame, Frame::World);
  EXPECT_EQ(scene.forces[0].pointFrame, Frame::Body);
  EXPECT_EQ(scene.forces[0].start, 0.5);
  EXPECT_EQ(scene.forces[0].end, 1.0);
  ASSERT_EQ(scene.poseEvents.size(), 1u);
  EXPECT_EQ(scene.poseEvents[0].time, 1.5);
  EXPECT_FALSE(scene.poseEvents[0].orientation.has_value());

  World world = buildWorld(scene);
  ASSERT_EQ(world.bodies().size(), 2u);
  EXPECT_EQ(scriptedForces(world).size(), 1u);
  EXPECT_EQ(world.bodies()[1].name(), "tet");
  EXPECT_TRUE(allNear(world.bodies()[0].velocity(), Vec3(0, 1, 0), 1e-15));
}

TEST(ParseScene, UnknownKeySuggestsTheNearest) {
  json doc = minimalScene();
  doc["bodies"][0]["positon"] = {0, 0, 0};
  const InputError e = parseError(doc);
  EXPECT_EQ(e.file(), "test.json");
  EXPECT_EQ(e.field(), "bodies[0].positon");
  EXPECT_TRUE(contains(e.problem(), "did you mean \"position\"")) << e.what();
}

TEST(ParseScene, WrongTypeNamesThePath) {
  json doc = minimalScene();
  doc["bodies"][0]["mass"] = "heavy";
  const InputError e = parseError(doc);
  EXPECT_EQ(e.field(), "bodies[0].mass");
  EXPECT_TRUE(contains(e.problem(), "expected a number")) << e.what();

  json vec = minimalScene();
  vec["bodies"][0]["velocity"] = {1, 2};
  EXPECT_EQ(parseError(vec).field(), "bodies[0].velocity");
}

TEST(ParseScene, MissingShapeType) {
  json doc = minimalScene();
  doc["bodies"][0]["shape"].erase("type");
  const InputError e = parseError(doc);
  EXPECT_EQ(e.field(), "bodies[0].shape.type");
  EXPECT_TRUE(contains(e.problem(), "missing")) << e.what();
}

TEST(ParseScene, NegativeMass) {
  json doc = minimalScene();
  doc["bodies"][0]["mass"] = -1.0;
  const InputError e = parseError(doc);
  EXPECT_EQ(e.field(), "bodies[0].mass");
  EXPECT_TRUE(contains(e.problem(), "positive")) << e.what();
}

TEST(ParseScene, MassAndDensityTogether) {
  json doc = minimalScene();
  doc["bodies"][0]["density"] = 1000.0;
  const InputError e = parseError(doc);
  EXPECT_EQ(e.field(), "bodies[0].mass");
  EXPECT_TRUE(contains(e.problem(), "exactly one")) << e.what();
}

TEST(ParseScene, HugeTimeStep) {
  json doc = minimalScene();
  doc["world"]["dt"] = 1.0;  // NaN cannot be written in JSON; an absurd step can
  const InputError e = parseError(doc);
  EXPECT_EQ(e.field(), "world.dt");
  EXPECT_TRUE(contains(e.what(), "dt")) << e.what();
}

TEST(ParseScene, NonUnitQuaternion) {
  json doc = minimalScene();
  doc["bodies"][0]["orientation"] = {{"quaternion", {1.0, 0.1, 0.0, 0.0}}};
  const InputError e = parseError(doc);
  EXPECT_EQ(e.field(), "bodies[0].orientation.quaternion");
  EXPECT_TRUE(contains(e.problem(), "unit quaternion")) << e.what();
}

TEST(ParseScene, NonOrthonormalMatrix) {
  json doc = minimalScene();
  doc["bodies"][0]["orientation"] = {{"matrix", {{1, 0, 0}, {0, 1, 0.2}, {0, 0, 1}}}};
  const InputError e = parseError(doc);
  EXPECT_EQ(e.field(), "bodies[0].orientation.matrix");
  EXPECT_TRUE(contains(e.problem(), "rotation matrix")) << e.what();

  json reflection = minimalScene();
  reflection["bodies"][0]["orientation"] = {{"matrix", {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}}}};
  EXPECT_EQ(parseError(reflection).field(), "bodies[0].orientation.matrix") << "det -1";
}

TEST(ParseScene, NormalizeOnRequestGivesTheUnitQuaternionAndTheNearestRotation) {
  json doc = minimalScene();
  doc["bodies"][0]["orientation"] = {{"quaternion", {2.0, 0.0, 2.0, 0.0}}, {"normalize", true}};
  const Quat q = parseScene(doc, "test.json", RBSIM_TEST_DATA_DIR).bodies[0].orientation;
  EXPECT_NEAR(q.w(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(q.y(), std::sqrt(0.5), 1e-15);

  // R S with S symmetric positive definite: its polar factor, the nearest rotation, is R.
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Mat3 S = Vec3(1.1, 0.95, 1.0).asDiagonal();
  const Mat3 M = R * S;
  json rows = json::array();
  for (int r = 0; r < 3; ++r) rows.push_back({M(r, 0), M(r, 1), M(r, 2)});
  json matrix = minimalScene();
  matrix["bodies"][0]["orientation"] = {{"matrix", rows}, {"normalize", true}};
  const Quat fromMatrix = parseScene(matrix, "test.json", RBSIM_TEST_DATA_DIR).bodies[0].orientation;
  EXPECT_LT((fromMatrix.toRotationMatrix() - R).norm(), 1e-12);
  matrix["bodies"][0]["orientation"].erase("normalize");
  EXPECT_EQ(parseError(matrix).field(), "bodies[0].orientation.matrix") << "without the request: an error";
}

TEST(ParseScene, UnknownIntegratorListsTheValidNames) {
  json doc = minimalScene();
  doc["world"]["integrator"] = "verlet";
  const InputError e = parseError(doc);
  EXPECT_EQ(e.field(), "world.integrator");
  for (const std::string& name : integratorNames()) EXPECT_TRUE(contains(e.problem(), name)) << e.what();
}

TEST(ParseScene, InwardMeshNamesTheShape) {
  json doc = minimalScene();
  doc["bodies"][0]["shape"] = {{"type", "mesh"}, {"file", "inverted_cube.obj"}};
  const InputError e = parseError(doc);
  EXPECT_EQ(e.field(), "bodies[0].shape");
  EXPECT_TRUE(contains(e.problem(), "inward")) << e.what();
}

TEST(ParseScene, MissingMeshFileIsNamed) {
  json doc = minimalScene();
  doc["bodies"][0]["shape"] = {{"type", "mesh"}, {"file", "nope.obj"}};
  const InputError e = parseError(doc);
  EXPECT_EQ(e.field(), "bodies[0].shape.file");
  EXPECT_TRUE(contains(e.what(), "nope.obj")) << e.what();
}

TEST(ParseScene, NoBodiesAndDuplicateNames) {
  EXPECT_EQ(parseError(json{{"world", {{"dt", 0.01}}}}).field(), "bodies");
  json doc = minimalScene();
  doc["bodies"].push_back(boxBody());
  const InputError e = parseError(doc);
  EXPECT_EQ(e.field(), "bodies[1].name");
  EXPECT_TRUE(contains(e.problem(), "duplicate")) << e.what();
}

TEST_F(SceneFiles, LoadsAFileAndResolvesMeshesBesideIt) {
  std::filesystem::copy_file(test::dataPath("tetrahedron.obj"), dir_ / "tet.obj");
  const std::string path = write("scene.json", R"({"bodies": [
      {"name": "t", "shape": {"type": "mesh", "file": "tet.obj"}, "density": 6}]})");
  const Scene scene = loadScene(path);
  EXPECT_EQ(scene.file, path);
  EXPECT_EQ(scene.title, "scene") << "defaults to the file's stem";
  ASSERT_EQ(scene.bodies.size(), 1u);
  EXPECT_NEAR(scene.bodies[0].mass, 1.0, 1e-15);
}

TEST_F(SceneFiles, SyntaxErrorReportsLineAndColumn) {
  const std::string path = write("broken.json", "{\n  \"world\": {\"dt\": 0.01},\n  \"bodies\": [ }\n");
  try {
    loadScene(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.field(), "line 3, column 15") << e.what();  // the '}' that cannot start a value
  }
}

TEST_F(SceneFiles, NaNIsAJsonSyntaxError) {
  const std::string path = write("nan.json", "{\"world\": {\"dt\": NaN}}");
  try {
    loadScene(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.field(), "line 1")) << e.what();
    EXPECT_TRUE(contains(e.problem(), "invalid JSON")) << e.what();
  }
}

// A --set key or bare value with a byte that is not UTF-8 was put into the document as it was, and
// writing the shape's cache key threw nlohmann's type_error 316 past every handler (the set
// fuzzer's crash, tests/fuzz/corpus/set): refused as bad input now, naming --set.
TEST(ParseScene, AnOverrideThatIsNotUtf8IsRefused) {
  for (const std::string& assignment : {std::string("bodies[0]shape.t\x87\x87=[1,2,3]"), std::string("bodies.box.name=\xff"),
                                       std::string("title=caf\xc3")}) {
    try {
      parseSceneText(minimalScene().dump(), "test.json", RBSIM_TEST_DATA_DIR, {assignment});
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "--set " + assignment);
      EXPECT_TRUE(contains(e.problem(), "UTF-8")) << e.what();
    }
  }
  // UTF-8 itself is fine.
  EXPECT_NO_THROW(parseSceneText(minimalScene().dump(), "test.json", RBSIM_TEST_DATA_DIR, {"title=caf\xc3\xa9"}));
}

TEST_F(SceneFiles, MissingSceneFile) {
  EXPECT_THROW(loadScene((dir_ / "absent.json").string()), InputError);
}

TEST_F(SceneFiles, OverridesApplyBeforeChecking) {
  const std::string path = write("scene.json", minimalScene().dump());
  const Scene scene = loadScene(path, {"world.dt=0.002", "bodies.box.mass=3", "bodies[0].velocity=[1,2,3]"});
  EXPECT_EQ(scene.settings.timeStep, 0.002);
  EXPECT_EQ(scene.bodies[0].mass, 3.0);
  EXPECT_TRUE(allNear(scene.bodies[0].velocity, Vec3(1, 2, 3), 0.0));
  try {
    loadScene(path, {"world.integrator=verlet"});
    FAIL() << "an override is validated like the file";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "world.integrator");
  }
  try {
    loadScene(path, {"bodies[4].mass=1"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.field(), "--set bodies[4].mass=1");
  }
}

TEST(ApplyOverride, SetsByPathIndexAndName) {
  json doc = minimalScene();
  applyOverride(doc, "world.dt=0.002");
  EXPECT_EQ(doc["world"]["dt"], 0.002);
  applyOverride(doc, "bodies.box.mass=3");
  EXPECT_EQ(doc["bodies"][0]["mass"], 3);
  applyOverride(doc, "bodies[0].velocity=[1,2,3]");
  EXPECT_EQ(doc["bodies"][0]["velocity"], json({1, 2, 3}));
  applyOverride(doc, "bodies.0.shape.type=mesh");
  EXPECT_EQ(doc["bodies"][0]["shape"]["type"], "mesh") << "a bare word is a string";
  applyOverride(doc, "view.fps=60");
  EXPECT_EQ(doc["view"]["fps"], 60) << "missing objects are created";
}

TEST(ApplyOverride, BadAssignmentsAreInputErrors) {
  json doc = minimalScene();
  for (const char* bad : {"bodies[1].mass=3", "bodies.ghost.mass=3", "world.dt", "=3", "world.dt.x=1"}) {
    EXPECT_THROW(applyOverride(doc, bad), InputError) << bad;
  }
  EXPECT_EQ(doc, minimalScene()) << "a failed override changes nothing it did not reach";
}

}  // namespace
}  // namespace rbsim
