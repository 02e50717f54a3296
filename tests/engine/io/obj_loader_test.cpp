// io/obj_loader: the hand-written OBJ files in tests/engine/data and the loader's input errors.
#include "io/obj_loader.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/stat.h>

#include <gtest/gtest.h>

#include "rbsim/io/input_error.h"
#include "rbsim/mass/mass_properties.h"
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

// The InputError parseObj throws for `text`, or a failure when it throws nothing.
InputError parseError(const std::string& text) {
  try {
    parseObj(text, "t.obj");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "parseObj did not throw InputError for:\n" << text.substr(0, 200);
  return InputError("", "", "");
}

void expectProblem(const InputError& e, const std::string& field, std::initializer_list<const char*> fragments) {
  EXPECT_EQ(e.field(), field) << e.what();
  for (const char* fragment : fragments) EXPECT_NE(e.problem().find(fragment), std::string::npos) << e.what();
}

// A convex polygon of n corners in the plane z = 0, as OBJ text: n 'v' lines and one 'f' line.
std::string polygonObj(int corners) {
  std::ostringstream text;
  for (int k = 0; k < corners; ++k) {
    const double angle = 2.0 * 3.141592653589793 * k / corners;
    text << "v " << std::cos(angle) << " " << std::sin(angle) << " 0\n";
  }
  text << "f";
  for (int k = 1; k <= corners; ++k) text << " " << k;
  return text.str() + "\n";
}

TEST(ParseObj, VertexLinesNeedThreeNumbers) {
  expectProblem(parseError("v 0 0 0\nv 1 2\nv 0 1 0\nf 1 2 3\n"), "line 2",
                {"'v' expects 3 coordinates", "got 2 fields"});
  expectProblem(parseError("v 0 0 0\nv 1 0 0\n\nv 1 abc 3\nf 1 2 3\n"), "line 4",
                {"'v' field 2 is 'abc'", "expected a decimal number"});
  expectProblem(parseError("v 0 0 0\nv 1 0 0\nv\nf 1 2 3\n"), "line 3", {"got 0 fields"});
  expectProblem(parseError("v 0 0 0\nv 1 0 0 1 1\nv 0 1 0\nf 1 2 3\n"), "line 2", {"got 5 fields"});
  expectProblem(parseError("v 0 0 0\nv 1 0 .\nv 0 1 0\nf 1 2 3\n"), "line 2", {"field 3 is '.'"});
  expectProblem(parseError("v 0 0 0\nv 1e 0 0\nv 0 1 0\nf 1 2 3\n"), "line 2", {"field 1 is '1e'"});
  expectProblem(parseError("v 0 0 0\nv 1 0 0 # note\nv 0 1 0\nf 1 2 3\n"), "line 2", {"got 5 fields"});
  // A weight or a colour after x y z, and the exponent forms tinyobjloader reads, are accepted.
  EXPECT_EQ(parseObj("v 0 0 0 1\nv 1e0 -0 +0 1 0 0\nv -.0 1.E+0 0\nf 1 2 3\n", "t.obj").vertices.size(), 3u);
}

TEST(ParseObj, TextureAndNormalLinesAreCheckedToo) {
  expectProblem(parseError("vt 0.5 x\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "line 1", {"'vt' field 2 is 'x'"});
  expectProblem(parseError("vt\nv 0 0 0\n"), "line 1", {"'vt' expects 1 to 3 texture coordinates"});
  expectProblem(parseError("vn 0 1\nv 0 0 0\n"), "line 1", {"'vn' expects 3 normal components", "got 2"});
}

TEST(ParseObj, FaceIndicesMustBeIntegersInRange) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expectProblem(parseError(v + "f 1 2 x\n"), "line 4", {"corner 3 'x'", "vertex index 'x' is not a non-zero integer"});
  expectProblem(parseError(v + "f 1 2 3.5\n"), "line 4", {"vertex index '3.5'"});
  expectProblem(parseError(v + "f 1 2 0\n"), "line 4", {"vertex index '0'", "counts from 1"});
  expectProblem(parseError(v + "f 1 2 99999999999\n"), "line 4", {"'99999999999' is not a non-zero integer"});
  expectProblem(parseError(v + "f 1 2 -4\n"), "line 4", {"index -4 counts back past the first", "only 3"});
  expectProblem(parseError(v + "f 1 2 9\n"), "line 4", {"face 1: vertex index out of range: 9, but the file has 3"});
  expectProblem(parseError(v + "f 1/1 2/1 3/1\n"), "line 4", {"texture coordinate index out of range: 1, but the file has 0"});
  expectProblem(parseError(v + "f 1//x 2//1 3//1\n"), "line 4", {"normal index 'x'"});
  expectProblem(parseError(v + "f 1/2/3/4 2 3\n"), "line 4", {"expected v, v/vt, v//vn or v/vt/vn"});
  expectProblem(parseError(v + "f 1 2\n"), "line 4", {"fewer than 3 vertices"});
  EXPECT_EQ(parseObj(v + "vt 0 0\nvn 0 0 1\nf 1/1/1 2//1 -1/-1/-1\n", "t.obj").triangles.size(), 1u);
}

TEST(ParseObj, FacesOfMoreThan255CornersAreRefusedNotMisread) {
  EXPECT_EQ(parseObj(polygonObj(255), "t.obj").triangles.size(), 253u);
  for (int corners : {256, 259, 1000}) {
    expectProblem(parseError(polygonObj(corners)), "line " + std::to_string(corners + 1),
                  {("a face of " + std::to_string(corners) + " corners").c_str(), "at most 255 corners"});
  }
}

TEST(ParseObj, ControlBytesAreRefusedWithTheirLine) {
  const std::string text = std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3") + '\0' + " 4\n";
  expectProblem(parseError(text), "line 4", {"control character (byte 0x00)"});
  expectProblem(parseError("v 0 0 0\r\nv 1 0 0\rv 0 1\x01 0\nf 1 2 3\n"), "line 3", {"byte 0x01"});
}

TEST(ParseObj, MeshesOverTheBudgetAreRefusedBeforeTheyAreRead) {
  std::string text;
  text.reserve(8 * (kMaxMeshVertices + 1));
  for (std::size_t i = 0; i <= kMaxMeshVertices; ++i) text += "v 0 0 0\n";
  expectProblem(parseError(text + "f 1 2 3\n"), "mesh",
                {"has 1000001 vertices and 1 triangles", "the limit is 1000000 vertices and 2000000 triangles"});
}

TEST(LoadObj, DevicesFifosAndHugeFilesAreRefusedBeforeReading) {
  expectProblem(loadError("/dev/zero"), "mesh", {"is a character device, not a regular file", "expected an OBJ file"});
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / test::uniqueTempName("objfiles");
  std::filesystem::create_directories(dir);
  const std::filesystem::path fifo = dir / "pipe.obj";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  expectProblem(loadError(fifo.string()), "mesh", {"is a FIFO (named pipe), not a regular file"});
  const std::filesystem::path huge = dir / "huge.obj";
  std::ofstream(huge).put('#');
  std::filesystem::resize_file(huge, kMaxObjFileBytes + 1);  // sparse: no disk space used
  expectProblem(loadError(huge.string()), "mesh",
                {"is 268435457 bytes (256 MB)", "the limit for an OBJ file is 268435456 bytes (256 MB)"});
  std::filesystem::remove_all(dir);
  expectProblem(loadError(dataPath("")), "mesh", {"is a folder"});
}

}  // namespace
}  // namespace rbsim
