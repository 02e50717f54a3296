#include "scene/body_parser.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "rbsim/body/shape_body.h"
#include "rbsim/io/input_error.h"
#include "io/obj_loader.h"
#include "fracture/pieces.h"
#include "rbsim/geometry/mesh_generators.h"
#include "rbsim/geometry/signed_distance_grid.h"
#include "geometry/surface_samples.h"
#include "rbsim/mass/mass_model.h"
#include "scene/compound_parser.h"
#include "scene/fracture_parser.h"
#include "scene/implicit_parser.h"
#include "scene/mesh_ground_parser.h"
#include "scene/input_ranges.h"

namespace rbsim::scene_detail {

namespace {

// Why a coordinate may not exceed kMaxCoordinate, for messages.

Frame parseFrame(const JsonObject& o, const char* key, Frame fallback) {
  const std::string name = o.string(key, fallback == Frame::Body ? "body" : "world");
  if (name == "body") return Frame::Body;
  if (name == "world") return Frame::World;
  o.fail(key, "expected \"body\" or \"world\", got \"" + name + "\"");
}

// Round shapes are tessellated as body/shape_body.h's display meshes (a bowl with half the rings).
constexpr int kRoundSegments = kDisplaySegments;  // around the axis [1]
// A rounded box without a "radius" rounds its edges by this share of its smallest extent.
constexpr double kDefaultRoundingShare = 0.1;  // [1]
constexpr int kRoundRings = kDisplayRings;        // from pole to pole [1]

Mesh parseShape(const JsonObject& body, const std::string& baseDir, BodyDef& def,
                std::shared_ptr<const ImplicitShape>& implicit) {
  const JsonObject shape = body.object("shape", kShapeKeys);
  const std::string type = shape.requiredString("type");
  if (type == "implicit" || type == "csg") {
    auto parsed = std::make_shared<const ImplicitShape>(parseImplicitShape(shape));
    implicit = parsed;
    return meshImplicitShapeOrFail(shape, *parsed).mesh;
  }
  try {
    if (type == "box") {
      shape.allowOnly(kBoxKeys, "a \"box\" shape");
      const Vec3 extents = shape.positiveVec3("extents");
      def.shape = Shape::box(0.5 * extents);
      return makeBox(extents);
    }
    if (type == "sphere") {
      shape.allowOnly(kSphereKeys, "a \"sphere\" shape");
      const double radius = shape.positiveNumber("radius", 0.5);
      def.shape = Shape::sphere(radius);
      return makeUvSphere(radius, kRoundSegments, kRoundRings);
    }
    if (type == "capsule") {
      shape.allowOnly(kCapsuleKeys, "a \"capsule\" shape");
      const double radius = shape.positiveNumber("radius", 0.25), length = shape.number("length", 1.0);
      if (!(length >= 0.0)) shape.fail("length", "expected the distance between the caps' centres, >= 0 m");
      def.shape = Shape::capsule(radius, 0.5 * length);
      return makeCapsule(radius, length, kRoundSegments, kRoundRings);
    }
    if (type == "rounded_box") {
      shape.allowOnly(kRoundedBoxKeys, "a \"rounded_box\" shape");
      const Vec3 extents = shape.positiveVec3("extents");  // the outer box [m]
      const double radius = shape.positiveNumber("radius", kDefaultRoundingShare * extents.minCoeff());
      if (!(2.0 * radius <= extents.minCoeff())) {
        shape.fail("radius", "expected at most half the smallest extent (" + std::to_string(0.5 * extents.minCoeff()) + " m)");
      }
      const Vec3 core = 0.5 * extents - Vec3::Constant(radius);
      def.shape = Shape::roundedBox(core, radius);
      return makeRoundedBox(core, radius, kDisplayBandSegments);
    }
    if (type == "torus") {
      shape.allowOnly(kTorusKeys, "a \"torus\" shape");
      const double major = shape.positiveNumber("major_radius", 0.5), minor = shape.positiveNumber("minor_radius", 0.15);
      if (!(minor < major)) shape.fail("minor_radius", "expected less than major_radius");
      return makeTorus(major, minor, kRoundSegments, kRoundRings);
    }
    if (type == "bowl") {
      shape.allowOnly(kBowlKeys, "a \"bowl\" shape");
      const double radius = shape.positiveNumber("radius", 1.0), thickness = shape.positiveNumber("thickness", 0.1);
      if (!(thickness < radius)) shape.fail("thickness", "expected less than radius");
      return makeBowl(radius, thickness, kRoundSegments, kRoundRings / 2);
    }
    if (type == "letter_u") {
      shape.allowOnly(kLetterUKeys, "a \"letter_u\" shape");
      const Vec3 extents = shape.positiveVec3("extents");  // width, height, depth
      const double stroke = shape.positiveNumber("stroke", 0.25 * extents.x());
      if (!(2.0 * stroke < extents.x() && stroke < extents.y())) {
        shape.fail("stroke", "expected less than half the width and less than the height");
      }
      return makeLetterU(extents.x(), extents.y(), stroke, extents.z());
    }
  } catch (const std::invalid_argument& e) {  // the generators' own range checks
    shape.fail("type", e.what());
  }
  if (type == "mesh") {
    shape.allowOnly(kMeshKeys, "a \"mesh\" shape");
    const std::string file = shape.requiredString("file");
    // The name is handed to the C library, which would stop at a NUL ("a.obj\u0000x" opens a.obj)
    // and takes other control bytes literally: neither belongs in a file name written in JSON.
    for (const char c : file) {
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
        shape.fail("file", "contains a control character (byte " + std::to_string(static_cast<int>(c)) +
                               "); expected a plain file name");
      }
    }
    const std::filesystem::path full = std::filesystem::path(baseDir) / file;
    Mesh mesh;
    try {
      mesh = loadObj(full.lexically_normal().string());
    } catch (const InputError& e) {
      throw InputError(shape.file(), shape.pathOf("file"), e.what());
    }
    const double scale = shape.positiveNumber("scale", 1.0);
    for (Vec3& p : mesh.vertices) p *= scale;
    return mesh;
  }
  shape.fail("type", "expected \"box\", \"sphere\", \"capsule\", \"rounded_box\", \"torus\", \"bowl\", \"letter_u\", \"mesh\", "
                    "\"implicit\" or \"csg\", got \"" + type + "\"");
}

// A body of any shape gets a signed distance grid (seed 000 "Constructing Signed Distance
// Functions") and surface samples: asked for with "sdf": {"resolution", "sample_spacing"}, and
// always for a closed non-convex mesh, which the convex narrow phase would treat as its hull. An
// implicit shape's grid holds its exact function's values, at the shape's own resolution. Here the
// request is checked against the budgets and returned; cookScene (scene/cook.cpp) builds it.
std::optional<CookRequest> parseCollisionShape(const JsonObject& b, const BodyDef& def,
                                               const std::shared_ptr<const ImplicitShape>& implicit) {
  const Mesh& mesh = *def.mesh;
  if (implicit && b.has("sdf")) {
    const JsonObject sdf = b.object("sdf", kSdfKeys);
    if (sdf.has("resolution")) sdf.fail("resolution", "an implicit shape's grid has the shape's \"resolution\"; expected it there");
  }
  if (!b.has("sdf") && !implicit) {
    // Spheres, capsules and boxes are convex by construction: no grid, and no mesh to check.
    if (def.shape && (def.shape->isRound() || def.shape->type == ShapeType::Box)) return std::nullopt;
    // An open mesh (accepted with the cube inertia) has no inside to grid: it stays convex.
    const MeshCheck check = checkMesh(mesh);
    const bool solid = check.closed && check.consistentlyOriented && check.degenerateTriangles == 0;
    // Judged with the tolerance of the coordinates as the file gave them (geometry/mesh.h): their
    // float rounding grows with their distance from the file's origin, not the centre of mass.
    const Mesh& given = def.fileFrame.mesh ? *def.fileFrame.mesh : mesh;
    if (!solid || isConvexSurface(mesh, convexityTolerance(given))) return std::nullopt;
  }
  const JsonObject o = b.has("sdf") ? b.object("sdf", kSdfKeys) : b;
  SdfGridOptions options;
  options.resolution = implicit ? implicit->resolution
                      : b.has("sdf") ? o.positiveInt("resolution", options.resolution) : options.resolution;
  if (options.resolution < kMinSdfResolution || options.resolution > kMaxSdfResolution) {
    o.fail("resolution", "expected " + std::to_string(kMinSdfResolution) + " to " + std::to_string(kMaxSdfResolution) +
                             " cells along the longest side");
  }
  // Budgets first, against the fields that set them (build() and surfaceSamples() check again);
  // a grid the scene did not ask for is the shape's.
  const auto overBudget = [&](const char* key, const std::string& problem) {
    if (b.has("sdf") && o.has(key)) o.fail(key, problem);
    b.fail("shape", "its signed distance grid: " + problem);
  };
  const std::string gridTooBig = sdfBudgetProblem(mesh, options);
  if (!gridTooBig.empty()) overBudget("resolution", gridTooBig + "; use a lower resolution");
  const double spacingGiven = b.has("sdf") && o.has("sample_spacing") ? o.number("sample_spacing", 0.0) : 0.0;
  if (spacingGiven < 0.0) o.fail("sample_spacing", "expected a spacing >= 0 m (0: the vertices only)");
  // By default the samples are as dense as the grid (its cell, as build() lays it): finer would
  // test points the grid cannot tell apart, coarser would let an edge sink between samples.
  const double cellSize = sdfGridLattice(mesh, options).cellSize;
  const double spacing = b.has("sdf") && o.has("sample_spacing") ? spacingGiven : cellSize;
  const std::string samplesTooMany = surfaceSampleBudgetProblem(mesh, spacing);
  if (!samplesTooMany.empty()) {
    overBudget(o.has("sample_spacing") ? "sample_spacing" : "resolution", samplesTooMany + "; use a larger sample_spacing");
  }
  CookRequest request;
  request.mesh = def.mesh;
  request.resolution = options.resolution;
  request.file = b.file();
  request.shapeField = b.pathOf("shape");
  request.resolutionField = b.pathOf("shape.resolution");
  if (!implicit) {
    request.kind = CookRequest::Kind::Grid;
    request.sampleSpacing = spacing;
    return request;
  }
  // An implicit body collides through its exact function: one sharp sample per surface cell of
  // its grid, and, when the scene asks for a finer spacing, the mesh's samples moved onto the
  // exact surface.
  request.kind = CookRequest::Kind::Implicit;
  request.sampleSpacing = spacingGiven > 0.0 ? spacing : 0.0;
  request.implicit = implicit;
  request.axes = def.fileFrame.axes;
  request.centre = def.fileFrame.centre;
  request.shapeJson = b.raw("shape").dump();
  return request;
}

// The keys a body's shape is built from, as one string (ShapeCache): the "shape" object with a
// mesh file's name replaced by its resolved path, "mass", "density", "sdf" and the inertia method.
// Empty when there is no "shape" object (parseShape reports it).
std::string shapeKey(const JsonObject& b, const std::string& baseDir, InertiaMethod method) {
  if (!b.has("shape") || !b.raw("shape").is_object()) return "";
  nlohmann::json shape = b.raw("shape");
  const auto type = shape.find("type"), file = shape.find("file");
  if (type != shape.end() && *type == "mesh" && file != shape.end() && file->is_string()) {
    *file = (std::filesystem::path(baseDir) / file->get<std::string>()).lexically_normal().string();
  }
  const auto dumpOf = [&](const char* key) { return b.has(key) ? b.raw(key).dump() : std::string("-"); };
  return std::string(inertiaMethodName(method)) + "\n" + shape.dump() + "\n" + dumpOf("mass") + "\n" +
         dumpOf("density") + "\n" + dumpOf("sdf") + "\n" + dumpOf("collide_as");
}

double nonNegative(const JsonObject& o, const char* key, double fallback, const char* unit) {
  const double value = o.number(key, fallback);
  if (value < 0.0) o.fail(key, std::string("expected a value >= 0 ") + unit);
  return value;
}

// The body's size is bounded like a coordinate, its mass and principal moments (and their
// inverses) by kMaxMassScale: with speeds below light's, m v, I omega and the kinetic energy then
// stay finite too. Reported against the key that set the mass, with the size the moments come from.
void checkMassScale(const JsonObject& b, const BodyDef& def) {
  double reach = 0.0;
  for (const Vec3& p : def.mesh->vertices) reach = std::max(reach, p.stableNorm());
  if (!(reach <= kMaxCoordinate)) {
    b.fail("shape", "the body reaches " + formatNumber(reach) + " m from its centre of mass; expected at most " +
                        formatNumber(kMaxCoordinate) + " m (" + kFarFromOrigin + ")");
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(def.inertiaBody, Eigen::EigenvaluesOnly);
  const double least = eig.eigenvalues().minCoeff(), most = eig.eigenvalues().maxCoeff();
  if (withinMassScale(def.mass) && withinMassScale(least) && withinMassScale(most)) return;
  const Vec3 size = def.mesh->boundsMax() - def.mesh->boundsMin();
  // Each printed apart from the bound it is nearer, so a value just past it does not read as it.
  const auto shown = [](double x) { return formatPastLimit(x, x >= 1.0 ? kMaxMassScale : 1.0 / kMaxMassScale); };
  b.fail(b.has("density") ? "density" : "mass",
         "a mass of " + shown(def.mass) + " kg for a body of size " + formatNumber(size.x()) + " x " +
             formatNumber(size.y()) + " x " + formatNumber(size.z()) + " m gives principal moments of inertia from " +
             shown(least) + " to " + shown(most) + " kg m^2; " + kMassScaleExpectation + ": a mass (or density) nearer the "
             "body's size");
}

}  // namespace

ShapeCache::Entry* ShapeCache::find(const std::string& key) {
  const auto it = built_.find(key);
  return it == built_.end() ? nullptr : &it->second;
}

void ShapeCache::add(const std::string& key, Entry entry) { built_.emplace(key, std::move(entry)); }

Quat toBodyOrientation(const BodyDef& def, const Quat& fileOrientation) {
  if (def.fileFrame.axes == Mat3::Identity()) return fileOrientation;  // exactly as typed
  return (fileOrientation * Quat(def.fileFrame.axes)).normalized();
}

Material parseMaterial(const JsonObject& o, const Material& base) {
  Material m = base;
  const auto check = [&o](const char* key, const std::string& problem) {
    if (!problem.empty()) o.fail(key, problem);
  };
  m.restitution = o.number("restitution", m.restitution);
  check("restitution", restitutionProblem(m.restitution));
  m.staticFriction = o.number("friction_static", m.staticFriction);
  check("friction_static", frictionProblem(m.staticFriction, "(mu_s)"));
  // Without its own value, mu_k follows a lowered mu_s, so "friction_static": 0 means frictionless.
  m.kineticFriction = o.number("friction_kinetic", std::min(m.kineticFriction, m.staticFriction));
  check("friction_kinetic", frictionProblem(m.kineticFriction, "(mu_k)"));
  check("friction_kinetic", frictionOrderProblem(m));
  return m;
}

std::size_t findBody(const std::vector<BodyDef>& bodies, const JsonObject& o, const char* key) {
  const std::string name = o.requiredString(key);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].name == name) return i;
  }
  o.fail(key, "no body is named \"" + name + "\"");
}

std::optional<Vec3> parseBody(const JsonObject& b, const std::string& baseDir, Scene& scene, ShapeCache* shapes) {
  BodyDef def;
  def.name = b.string("name", "body" + std::to_string(scene.bodies.size()));
  InertiaMethod method = scene.settings.inertia;
  if (b.has("inertia") && !parseInertiaMethod(b.string("inertia", ""), method)) {
    b.fail("inertia", "expected \"cube\" or \"exact\"");
  }
  const std::string key = shapes != nullptr ? shapeKey(b, baseDir, method) : std::string();
  if (b.has("shape") && b.raw("shape").is_object()) {
    const nlohmann::json& shape = b.raw("shape");
    const auto type = shape.find("type"), file = shape.find("file");
    if (type != shape.end() && *type == "mesh" && file != shape.end() && file->is_string()) {
      scene.files.push_back((std::filesystem::path(baseDir) / file->get<std::string>()).lexically_normal().string());
    }
  }
  if (b.has("shapes")) {
    parseCompoundShapes(b, def);
    checkMassScale(b, def);
  } else if (ShapeCache::Entry* entry = key.empty() ? nullptr : shapes->find(key)) {
    // The same keys were built and checked before: share what they made (pointers, not copies),
    // and list the shape's request once in this scene.
    if (entry->request && entry->listedIn != shapes->scene()) {
      scene.cooking.push_back(*entry->request);
      entry->listedIn = shapes->scene();
    }
    const BodyDef* built = &entry->built;
    def.mesh = built->mesh;
    def.fileFrame = built->fileFrame;
    def.mass = built->mass;
    def.inertiaBody = built->inertiaBody;
    def.shape = built->shape;
  } else {
    std::shared_ptr<const ImplicitShape> implicit;
    Mesh mesh = parseShape(b, baseDir, def, implicit);
    if (b.has("mass")) b.positiveNumber("mass", 1.0);  // type and sign errors name the field
    if (b.has("density")) b.positiveNumber("density", 1.0);
    try {
      const MassModel model = buildMassModel(std::move(mesh), b.optionalPositive("mass"),
                                             b.optionalPositive("density"), method, def.shape ? &*def.shape : nullptr);
      def.mesh = model.mesh;
      def.mass = model.mass;
      def.inertiaBody = model.inertiaBody;
      def.fileFrame = {model.principalAxes, model.centerOffset, model.fileMesh};
    } catch (const InputError& e) {
      throw InputError(b.file(), b.pathOf(e.field().c_str()), e.problem());
    }
    checkMassScale(b, def);
    const std::optional<CookRequest> request = collidesAsTriangles(b) ? triangleGround(b, def) : parseCollisionShape(b, def, implicit);
    // The collision shape RigidBody would derive from the mesh (shapeOfMesh), made here once so
    // that every body of this shape holds the same hull rather than building its own.
    if (!def.shape) def.shape = shapeOfMesh(*def.mesh, request.has_value());
    if (request) scene.cooking.push_back(*request);
    if (!key.empty()) shapes->add(key, {def, request, shapes->scene()});
  }
  def.position = b.boundedVec3("position", Vec3::Zero(), kMaxCoordinate, "m", kFarFromOrigin);
  // The file gives the orientation of the file's axes; the body's are its principal axes.
  def.orientation = toBodyOrientation(def, b.optionalOrientation("orientation").value_or(Quat::Identity()));
  def.velocity = b.boundedVec3("velocity", Vec3::Zero(), kMaxSpeed, "m/s", "the speed of light");
  def.angularVelocity = b.vec3("angular_velocity", Vec3::Zero());
  const double radius = 0.5 * (def.mesh->boundsMax() - def.mesh->boundsMin()).norm();
  if (!(def.angularVelocity.stableNorm() * radius <= kMaxSpeed)) {
    b.fail("angular_velocity", "its surface moves at |omega| r = " + formatNumber(def.angularVelocity.stableNorm()) +
                                   " rad/s x " + formatNumber(radius) + " m, faster than light; expected a smaller spin");
  }
  std::optional<Vec3> color;
  if (b.has("color")) {
    color = b.vec3("color", kDefaultBodyColor);
    if (color->minCoeff() < 0.0 || color->maxCoeff() > 1.0) b.fail("color", "components must lie in [0, 1]");
  }
  def.isStatic = b.boolean("static", false);
  def.isKinematic = b.boolean("kinematic", false);
  if (def.isStatic && def.isKinematic) b.fail("kinematic", "a body is static or kinematic, not both");
  checkTriangleGroundIsStatic(b, def);
  def.material = parseMaterial(b);
  if (b.has("filter")) {
    if (!def.children.empty()) b.fail("filter", "a compound body's filters are its shapes'; expected \"filter\" in each");
    def.filter = parseFilter(b);
  }
  if (!def.children.empty() && (b.has("restitution") || b.has("friction_static") || b.has("friction_kinetic"))) {
    b.fail(b.has("restitution") ? "restitution" : b.has("friction_static") ? "friction_static" : "friction_kinetic",
           "a compound body's materials are its shapes'; expected the key in each");
  }
  if (def.isStatic && (def.velocity != Vec3::Zero() || def.angularVelocity != Vec3::Zero())) {
    b.fail(def.velocity != Vec3::Zero() ? "velocity" : "angular_velocity", "a static body cannot move; expected zero");
  }
  if (b.has("fracture") && !def.children.empty()) b.fail("fracture", "a compound body does not break; expected one \"shape\"");
  if (b.has("fracture")) def.fracture = parseFracture(b, def);
  scene.bodies.push_back(def);
  scene.inertiaMethods.emplace_back(inertiaMethodName(method));
  return color;
}

ScriptedForce parseForce(const JsonObject& f, std::size_t index, const Mat3& fileAxes, double duration) {
  ScriptedForce force;
  force.body = sceneBodyId(index);
  force.force = f.vec3("force", Vec3::Zero());
  force.point = f.vec3("point", Vec3::Zero());
  force.forceFrame = parseFrame(f, "force_frame", Frame::World);
  force.pointFrame = parseFrame(f, "point_frame", Frame::Body);
  // Body-frame vectors are written in the file's axes (about the centre of mass).
  if (force.forceFrame == Frame::Body) force.force = fileAxes.transpose() * force.force;
  if (force.pointFrame == Frame::Body) force.point = fileAxes.transpose() * force.point;
  force.start = f.number("start", 0.0);
  force.end = f.number("end", duration);
  if (force.start < 0.0) f.fail("start", "expected a time >= 0 s");
  if (!(force.end > force.start)) f.fail("end", "expected a time after \"start\"");
  return force;
}

void parseScripts(const JsonObject& b, std::size_t index, Scene& scene) {
  const bool isStatic = scene.bodies[index].isStatic;
  // Forces and springs act on dynamic bodies only: a kinematic body moves as its velocities say.
  const bool forcesIgnored = isStatic || scene.bodies[index].isKinematic;
  const char* ignoredBecause = isStatic ? "a static body does not respond to forces"
                                        : "a kinematic body moves as prescribed; forces do not act on it";
  for (const JsonObject& f : b.objectArray("forces", kForceKeys)) {
    if (forcesIgnored) b.fail("forces", ignoredBecause);
    scene.forces.push_back(parseForce(f, index, scene.bodies[index].fileFrame.axes, scene.duration));
  }
  for (const JsonObject& p : b.objectArray("set_pose", kSetPoseKeys)) {
    PoseEvent event;
    event.body = sceneBodyId(index);
    event.time = p.requiredNumber("time");
    if (event.time < 0.0) p.fail("time", "expected a time >= 0 s");
    if (p.has("position")) event.position = p.boundedVec3("position", Vec3::Zero(), kMaxCoordinate, "m", kFarFromOrigin);
    event.orientation = p.optionalOrientation("orientation");
    if (event.orientation) event.orientation = toBodyOrientation(scene.bodies[index], *event.orientation);
    if (p.has("velocity")) event.velocity = p.boundedVec3("velocity", Vec3::Zero(), kMaxSpeed, "m/s", "the speed of light");
    event.angularVelocity = p.optionalVec3("angular_velocity");
    if (isStatic && (event.velocity || event.angularVelocity)) p.fail("velocity", "a static body cannot move");
    scene.poseEvents.push_back(event);
  }
  if (b.has("motion")) parseMotion(b, index, scene);
  for (const JsonObject& s : b.objectArray("springs", kSpringKeys)) {
    if (forcesIgnored) b.fail("springs", ignoredBecause);
    Spring spring;
    spring.body = sceneBodyId(index);
    spring.anchor = s.boundedVec3("anchor", Vec3::Zero(), kMaxCoordinate, "m", kFarFromOrigin);
    spring.point = scene.bodies[index].fileFrame.axes.transpose() * s.vec3("point", Vec3::Zero());
    spring.stiffness = s.positiveNumber("stiffness", 1.0);
    spring.restLength = nonNegative(s, "rest_length", 0.0, "m");
    spring.damping = nonNegative(s, "damping", 0.0, "N s/m");
    // The force k (l - l0) + c v at the scene's own lengths must be a number: k = 1e308 with a
    // rest length of 10 m asks for 1e309 N before the body has moved.
    const BodyDef& body = scene.bodies[index];
    const double reach = (spring.anchor - (body.position + body.orientation * spring.point)).norm() + spring.restLength;
    if (!std::isfinite(reach) || !std::isfinite(spring.stiffness * reach)) {
      s.fail("stiffness", "k times the spring's length (" + formatNumber(reach) + " m) overflows a double; "
                          "expected a force k (l - l0) below about 1e307 N");
    }
    scene.springs.push_back(spring);
  }
}

std::pair<Plane, Material> parsePlane(const JsonObject& p) {
  const Vec3 normal = p.vec3("normal", Vec3::UnitY());
  if (!(normal.stableNorm() > 0.0)) p.fail("normal", "expected a non-zero direction");
  Plane plane;
  plane.normal = normal.stableNormalized();  // a direction: its length carries no meaning
  plane.offset = plane.normal.dot(p.boundedVec3("point", Vec3::Zero(), kMaxCoordinate, "m", kFarFromOrigin));
  return {plane, parseMaterial(p)};
}

void parsePlanes(const JsonObject& root, Scene& scene) {
  for (const JsonObject& p : root.objectArray("planes", kPlaneKeys)) {
    const auto [plane, material] = parsePlane(p);
    scene.planes.push_back(plane);
    scene.planeMaterials.push_back(material);
  }
}

}  // namespace rbsim::scene_detail
