// io/obj_loader: the hand-written OBJ files in tests/engine/data and the loader's input errors.
#include "io/obj_loader.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "io/input_error.h"
#include "mass/mass_properties.h"
#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;
using test::dataPath;

// The InputError loadObj throws for `path`, or a failure when it throws nothing.
InputError loadError(const std::string& path) {
  try {
    loadObj(path);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "loadObj(" << path << ") did not throw InputError";
  return InputError("", "", "");
}

TEST(LoadObj, ReadsTheTetrahedron) {
  const Mesh mesh = loadObj(dataPath("tetrahedron.obj"));
  EXPECT_EQ(mesh.name, dataPath("tetrahedron.obj"));
  ASSERT_EQ(mesh.vertices.size(), 4u);
  EXPECT_TRUE(allNear(mesh.vertices[0], Vec3(0, 0, 0), 0.0));
  EXPECT_TRUE(allNear(mesh.vertices[1], Vec3(1, 0, 0), 0.0));
  EXPECT_TRUE(allNear(mesh.vertices[2], Vec3(0, 1, 0), 0.0));
  EXPECT_TRUE(allNear(mesh.vertices[3], Vec3(0, 0, 1), 0.0));
  ASSERT_EQ(mesh.triangles.size(), 4u);
  EXPECT_EQ(mesh.triangles[0], (Triangle{0, 2, 1})) << "OBJ indices are 1-based, ours 0-based";
  const MeshCheck check = checkMesh(mesh);
  EXPECT_TRUE(check.closed && check.consistentlyOriented && check.degenerateTriangles == 0) << check.problem;
}

TEST(LoadObj, TriangulatesQuadsKeepingTheWinding) {
  const Mesh mesh = loadObj(dataPath("quad_cube.obj"));
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u) << "six quads, two triangles each";
  const MeshCheck check = checkMesh(mesh);
  EXPECT_TRUE(check.closed && check.consistentlyOriented && check.degenerateTriangles == 0) << check.problem;
  // Winding kept outward: the unit cube's volume is +1 and its centre is (1/2, 1/2, 1/2).
  const MassProperties props = polyhedralMassProperties(mesh, 1.0);
  EXPECT_NEAR(props.volume, 1.0, 1e-15);
  EXPECT_TRUE(allNear(props.centerOfMass, Vec3::Constant(0.5), 1e-15));
}

TEST(LoadObj, EarClipsConcavePentagonsAndResolvesRelativeIndices) {
  // An arrow-head prism: concave pentagon caps (area 10 m^2, one given by negative indices), unit
  // height, quad sides. A fan from a cap's first corner would cover the notch and overlap.
  const Mesh mesh = loadObj(dataPath("concave_prism.obj"));
  EXPECT_EQ(mesh.triangles.size(), 2u * 3u + 5u * 2u);
  const MeshCheck check = checkMesh(mesh);
  EXPECT_TRUE(check.closed && check.consistentlyOriented && check.degenerateTriangles == 0) << check.problem;
  EXPECT_NEAR(polyhedralMassProperties(mesh, 1.0).volume, 10.0, 1e-12);
}

TEST(LoadObj, LoadsAnOpenMeshThatCheckMeshRejects) {
  const Mesh mesh = loadObj(dataPath("open_tetrahedron.obj"));
  EXPECT_EQ(mesh.triangles.size(), 3u);
  EXPECT_FALSE(checkMesh(mesh).closed);
}

TEST(LoadObj, InvertedCubeIsClosedButEnclosesNegativeVolume) {
  const Mesh mesh = loadObj(dataPath("inverted_cube.obj"));
  const MeshCheck check = checkMesh(mesh);
  EXPECT_TRUE(check.closed);
  EXPECT_TRUE(check.consistentlyOriented) << "wound inward, but consistently";
  EXPECT_NEAR(polyhedralMassProperties(mesh, 1.0).volume, -1.0, 1e-15);
}

TEST(LoadObj, EmptyFileIsAnInputError) {
  const InputError e = loadError(dataPath("empty.obj"));
  EXPECT_EQ(e.file(), dataPath("empty.obj"));
  EXPECT_EQ(e.field(), "mesh");
  EXPECT_NE(e.problem().find("no faces"), std::string::npos) << e.what();
}

TEST(LoadObj, MissingFileIsAnInputErrorNamingIt) {
  const std::string path = dataPath("no_such_mesh.obj");
  const InputError e = loadError(path);
  EXPECT_EQ(e.file(), path);
  EXPECT_NE(std::string(e.what()).find("no_such_mesh.obj"), std::string::npos) << e.what();
  EXPECT_NE(e.problem().find("cannot open"), std::string::npos) << e.what();
}

TEST(LoadObj, OverflowingCoordinateIsAnInputError) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / (test::uniqueTempName("overflow") + ".obj");
  {
    std::ofstream out(path);
    out << "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n";
  }
  const InputError e = loadError(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(e.field(), "vertex 2");
  EXPECT_NE(e.problem().find("finite"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace rbsim
