// mass/mass_model: from a shape and a mass or density to the re-centred mesh and I_body, and the
// input errors a scene can trigger.
#include "rbsim/mass/mass_model.h"

#include <cmath>
#include <limits>
#include <tuple>

#include <gtest/gtest.h>

#include "rbsim/io/input_error.h"
#include "io/obj_loader.h"
#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;
using test::dataPath;

InputError modelError(Mesh mesh, std::optional<double> mass, std::optional<double> density,
                      InertiaMethod method) {
  try {
    buildMassModel(std::move(mesh), mass, density, method);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "buildMassModel did not throw InputError";
  return InputError("", "", "");
}

Mesh offsetTetrahedron(const Vec3& offset) {
  Mesh m = loadObj(dataPath("tetrahedron.obj"));
  for (Vec3& v : m.vertices) v += offset;
  return m;
}

TEST(BuildMassModel, ExactRecentresOnTheCentroid) {
  const Vec3 offset(3.0, -1.0, 2.0);
  const Mesh original = offsetTetrahedron(offset);
  const MassModel model = buildMassModel(original, std::nullopt, 2.0, InertiaMethod::Exact);
  const Vec3 centroid = offset + Vec3::Constant(0.25);
  EXPECT_TRUE(allNear(model.centerOffset, centroid, 1e-14));
  EXPECT_NEAR(model.mass, 2.0 / 6.0, 1e-15);
  ASSERT_EQ(model.mesh->vertices.size(), original.vertices.size());
  // The body frame is the principal frame (seed 000): p_file = E p_body + c, the file's vertices
  // kept as they were, and the inertia diagonal.
  ASSERT_EQ(model.fileMesh->vertices.size(), original.vertices.size());
  for (std::size_t i = 0; i < original.vertices.size(); ++i) {
    EXPECT_TRUE(allNear(model.principalAxes * model.mesh->vertices[i] + centroid, original.vertices[i], 1e-14));
    EXPECT_EQ(model.fileMesh->vertices[i], original.vertices[i]);
  }
  EXPECT_NEAR(model.principalAxes.determinant(), 1.0, 1e-15);
  EXPECT_TRUE(allNear(model.inertiaBody, Mat3(model.inertiaBody.diagonal().asDiagonal()), 0.0));
  const MassProperties again = polyhedralMassProperties(*model.mesh, 2.0);
  EXPECT_TRUE(allNear(again.centerOfMass, Vec3::Zero(), 1e-15)) << "body origin = centre of mass";
  EXPECT_TRUE(allNear(again.inertia, model.inertiaBody, 1e-15));
}

TEST(BuildMassModel, CubeRecentresOnTheBoundsCentre) {
  const MassModel model = buildMassModel(offsetTetrahedron(Vec3(3.0, -1.0, 2.0)), 4.0, std::nullopt,
                                         InertiaMethod::Cube);
  EXPECT_TRUE(allNear(model.centerOffset, Vec3(3.5, -0.5, 2.5), 1e-15));
  EXPECT_TRUE(allNear(0.5 * (model.mesh->boundsMin() + model.mesh->boundsMax()), Vec3::Zero(), 1e-15));
  EXPECT_EQ(model.mass, 4.0);
  EXPECT_TRUE(allNear(model.inertiaBody, cuboidInertia(4.0, Vec3::Ones()), 1e-15));
}

TEST(BuildMassModel, ExactWithAMassScalesTheInertia) {
  // Unit density gives m = 1/6; asking for 3 kg scales every entry by 3 / (1/6) = 18.
  const Mesh tet = offsetTetrahedron(Vec3::Zero());
  const MassModel unit = buildMassModel(tet, std::nullopt, 1.0, InertiaMethod::Exact);
  const MassModel heavy = buildMassModel(tet, 3.0, std::nullopt, InertiaMethod::Exact);
  EXPECT_EQ(heavy.mass, 3.0);
  EXPECT_TRUE(allNear(heavy.inertiaBody, 18.0 * unit.inertiaBody, 1e-15));
  EXPECT_TRUE(allNear(heavy.centerOffset, unit.centerOffset, 0.0));
}

TEST(BuildMassModel, CubeWithADensityUsesTheMeshVolume) {
  const MassModel model = buildMassModel(offsetTetrahedron(Vec3::Zero()), std::nullopt, 6.0,
                                         InertiaMethod::Cube);
  EXPECT_NEAR(model.mass, 1.0, 1e-15) << "density 6 x volume 1/6, not x the bounding box's 1";
  EXPECT_TRUE(allNear(model.inertiaBody, cuboidInertia(1.0, Vec3::Ones()), 1e-15));
}

TEST(BuildMassModel, InwardWindingIsRejected) {
  const InputError e = modelError(loadObj(dataPath("inverted_cube.obj")), 1.0, std::nullopt,
                                  InertiaMethod::Exact);
  EXPECT_EQ(e.field(), "shape");
  EXPECT_NE(e.problem().find("inward"), std::string::npos) << e.what();
}

TEST(BuildMassModel, OpenMeshIsRejectedForExactInertia) {
  const Mesh open = loadObj(dataPath("open_tetrahedron.obj"));
  const InputError e = modelError(open, 1.0, std::nullopt, InertiaMethod::Exact);
  EXPECT_EQ(e.field(), "shape");
  EXPECT_NE(e.problem().find("closed"), std::string::npos) << e.what();
  // The cube proxy with a mass needs no volume, so the open mesh is fine there...
  EXPECT_NO_THROW(buildMassModel(open, 1.0, std::nullopt, InertiaMethod::Cube));
  // ...but a density does need the enclosed volume.
  EXPECT_THROW(buildMassModel(open, std::nullopt, 1.0, InertiaMethod::Cube), InputError);
}

TEST(BuildMassModel, BadMassesNameTheField) {
  const Mesh box = makeBox(Vec3::Ones());
  for (double bad : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    for (InertiaMethod method : {InertiaMethod::Exact, InertiaMethod::Cube}) {
      const InputError e = modelError(box, bad, std::nullopt, method);
      EXPECT_EQ(e.field(), "mass") << "mass " << bad;
      EXPECT_NE(std::string(e.what()).find("mass"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(modelError(box, std::nullopt, -2.0, InertiaMethod::Exact).field(), "density");
}

TEST(BuildMassModel, ExactlyOneOfMassAndDensity) {
  const Mesh box = makeBox(Vec3::Ones());
  const InputError both = modelError(box, 1.0, 1000.0, InertiaMethod::Exact);
  EXPECT_NE(both.problem().find("exactly one"), std::string::npos) << both.what();
  const InputError neither = modelError(box, std::nullopt, std::nullopt, InertiaMethod::Exact);
  EXPECT_NE(neither.problem().find("exactly one"), std::string::npos) << neither.what();
}

TEST(BuildMassModel, FlatMeshIsRejected) {
  Mesh flat;
  flat.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  flat.triangles = {{0, 1, 2}, {0, 2, 1}};
  const InputError e = modelError(flat, 1.0, std::nullopt, InertiaMethod::Cube);
  EXPECT_EQ(e.field(), "shape");
  EXPECT_NE(e.problem().find("flat"), std::string::npos) << e.what();
}


TEST(BuildMassModel, ASurfaceCrossingItselfHasNoVolume) {
  Mesh two = makeBox(Vec3::Ones());
  two.name = "two.obj";
  const auto shift = static_cast<std::uint32_t>(two.vertices.size());
  for (const Vec3& p : makeBox(Vec3::Ones()).vertices) two.vertices.push_back(p + Vec3(0.5, 0.5, 0.5));
  for (Triangle t : makeBox(Vec3::Ones()).triangles) two.triangles.push_back({t[0] + shift, t[1] + shift, t[2] + shift});
  for (const auto& [mass, density, method] :
       {std::tuple<std::optional<double>, std::optional<double>, InertiaMethod>{1.0, std::nullopt, InertiaMethod::Exact},
        {std::nullopt, 1.0, InertiaMethod::Cube}}) {
    const InputError e = modelError(two, mass, density, method);
    EXPECT_EQ(e.field(), "shape");
    EXPECT_NE(e.problem().find("mesh 'two.obj': the surface crosses itself (triangles "), std::string::npos) << e.what();
    EXPECT_NE(e.problem().find("its volume is not defined"), std::string::npos) << e.what();
  }
  // The cube approximation with a mass needs no volume: it still works.
  EXPECT_DOUBLE_EQ(buildMassModel(two, 2.0, std::nullopt, InertiaMethod::Cube).mass, 2.0);
}

}  // namespace
}  // namespace rbsim
