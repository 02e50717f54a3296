// Box3D's own benchmark scenes (assets/scenes/box3d/: large_pyramid, many_pyramids, joint_grid,
// convex_pile) in Bullet 3.24 (Debian's libbullet-dev, its default float build), beside
// box3d_scenes for rbsim: the same scene files, read here with nlohmann-json, the same step
// counts, the same printed lines. Bullet is a reference for the comparison, not a dependency of
// rbsim: this program is built only where Bullet is installed.
// Prints per scene: the setup time (scene file to a Bullet world with every body and joint
// added), wall and CPU ms per step (mean and median; CPU from getrusage), the share of the step
// of each of Bullet's BT_PROFILE zones (its own time, its children's excluded), and the end state:
// the fastest body, the top body's (highest start, dynamic) horizontal drift and sink, the
// deepest penetration (max -getDistance() over the dispatcher's manifolds the last step solved),
// the bodies awake, and the contacts (manifolds with a point; "points" counts their points).
//   usage: bullet_box3d_scenes [--scenes a,b] [--steps N] [--seconds S] [--stages on|off]
//   --steps overrides every scene's step count; --seconds runs S simulated seconds instead;
//   --stages off leaves Bullet's profile hooks uninstalled (they cost a clock read per zone).
// The world is Bullet's as the other Bullet benchmarks build it (bullet_world.h: default collision
// configuration, DBVT broad phase, sequential impulses with its default 10 iterations and warm
// starting), stepped by stepSimulation(dt, 0): one step of dt, no substeps, no interpolation.
// How the scene files are put into Bullet, and what it cannot say the same way:
//  - Mass is density x volume (cube 100 kg; sphere 268.1 kg; hull from its triangles by the
//    divergence theorem). Boxes and spheres take Bullet's own inertia (exact for them); the hull's
//    is computed from its triangles too, as Bullet's btConvexHullShape would give the inertia of its
//    bounding box: the hull's points go into Bullet in its principal frame about the centre of
//    mass, and the body starts rotated by that frame, so its points land where Box3D puts them.
//  - Friction: one coefficient per body (the file's friction_static; the four scenes have
//    friction_kinetic equal to it). Bullet combines a pair's coefficients as their product; here
//    the combining callback is the geometric mean, rbsim's and Box3D's rule, so 0.6 meets 0.6 as 0.6.
//  - The hull has Bullet's default collision margin of 0.04 m around it (a box's margin lies inside
//    its extents, a sphere's is its radius): hulls touch 0.04 m out of their surface, and their
//    penetration is counted against that rounded surface.
//  - "collisions": false (joint_grid): the bodies are added with collision mask 0, so no pair
//    passes the broad phase's filter, but Bullet still updates every AABB in its DBVT each step.
//  - Sleep off: every dynamic body is DISABLE_DEACTIVATION. Sleep on: the file's
//    sleep_linear_speed and sleep_angular_speed are each body's sleeping thresholds (Bullet tests
//    |v| and |omega| apart, as rbsim does) and time_to_sleep is gDeactivationTime; Bullet puts an
//    island to sleep when all its bodies are slow.
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <map>
#include <memory>
#include <numeric>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "box3d_cases.h"
#include "bullet_world.h"

using rbsim::bench::BulletWorld;
using Json = nlohmann::json;

namespace {

// ---------------------------------------------------------------------------------------------
// Bullet's stages: its BT_PROFILE zones call btEnterProfileZone / btLeaveProfileZone even in
// Debian's build (which has no CProfileManager); these hooks time each zone, its own time apart
// from its children's.
using Clock = std::chrono::steady_clock;
struct Zone {
  const char* name;
  double total = 0.0;  // s, children included
  double self = 0.0;   // s, children excluded
};
struct OpenZone {
  std::size_t zone;
  Clock::time_point start;
  double children;  // s
};
std::vector<Zone> gZones;
std::vector<OpenZone> gOpen;

void enterZone(const char* name) {
  std::size_t i = 0;
  while (i < gZones.size() && gZones[i].name != name && std::strcmp(gZones[i].name, name) != 0) ++i;
  if (i == gZones.size()) gZones.push_back({name});
  gOpen.push_back({i, Clock::now(), 0.0});
}

void leaveZone() {
  if (gOpen.empty()) return;
  const OpenZone open = gOpen.back();
  gOpen.pop_back();
  const double seconds = std::chrono::duration<double>(Clock::now() - open.start).count();
  gZones[open.zone].total += seconds;
  gZones[open.zone].self += seconds - open.children;
  if (!gOpen.empty()) gOpen.back().children += seconds;
}

// A pair's friction: the geometric mean of the bodies' coefficients (Bullet's default is the product).
btScalar geometricMeanFriction(const btCollisionObject* a, const btCollisionObject* b) {
  return btSqrt(a->getFriction() * b->getFriction());
}

// ---------------------------------------------------------------------------------------------
// A convex hull from an OBJ file: its "v" points and "f" triangles (wound outward).
struct Hull {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<int, 3>> triangles;
};

Hull readObj(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  Hull hull;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") {
      std::array<double, 3> p{};
      if (!(words >> p[0] >> p[1] >> p[2])) throw std::runtime_error(path + ": bad line: " + line);
      hull.points.push_back(p);
    } else if (tag == "f") {
      std::vector<int> face;
      for (std::string corner; words >> corner;) face.push_back(std::atoi(corner.c_str()));  // "i", "i/t", "i/t/n"
      for (std::size_t k = 1; k + 1 < face.size(); ++k) hull.triangles.push_back({face[0] - 1, face[k] - 1, face[k + 1] - 1});
    }
  }
  for (const auto& t : hull.triangles)
    for (int i : t)
      if (i < 0 || i >= static_cast<int>(hull.points.size())) throw std::runtime_error(path + ": face index out of range");
  if (hull.points.size() < 4 || hull.triangles.empty()) throw std::runtime_error(path + ": no closed surface");
  return hull;
}

// A shape of the scene file as Bullet takes it: the shape in its principal frame, the volume, the
// inertia per kg about the centre of mass in that frame, and the frame's rotation from the body's.
struct ShapeInfo {
  std::unique_ptr<btCollisionShape> shape;
  double volume = 0.0;      // m^3
  bool ownInertia = false;  // true: unitInertia below; false: Bullet's calculateLocalInertia (exact for boxes and spheres)
  btVector3 unitInertia{0, 0, 0};  // m^2 (per kg)
  btMatrix3x3 principal = btMatrix3x3::getIdentity();  // body frame from the shape's
};

ShapeInfo hullShape(const std::string& path) {
  const Hull hull = readObj(path);
  // Volume and centre of mass, as sums of the tetrahedra (origin, a, b, c).
  double volume = 0.0, moment[3] = {0, 0, 0};
  for (const auto& t : hull.triangles) {
    const auto &a = hull.points[t[0]], &b = hull.points[t[1]], &c = hull.points[t[2]];
    const double v = (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0;
    volume += v;
    for (int k = 0; k < 3; ++k) moment[k] += v * (a[k] + b[k] + c[k]) / 4.0;
  }
  if (!(volume > 0.0)) throw std::runtime_error(path + ": the triangles enclose no volume (wound inward?)");
  const double centroid[3] = {moment[0] / volume, moment[1] / volume, moment[2] / volume};
  // Second moment about the centre of mass: for each tetrahedron (c, a, b, c') with a, b, c' taken
  // from the centroid, det / 120 * (aa' + bb' + cc' + ss'), s = a + b + c.
  double second[3][3] = {};
  for (const auto& t : hull.triangles) {
    double p[3][3];
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k) p[v][k] = hull.points[t[v]][k] - centroid[k];
    const double det = p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                       p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
    const double s[3] = {p[0][0] + p[1][0] + p[2][0], p[0][1] + p[1][1] + p[2][1], p[0][2] + p[1][2] + p[2][2]};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        second[i][j] += det / 120.0 * (p[0][i] * p[0][j] + p[1][i] * p[1][j] + p[2][i] * p[2][j] + s[i] * s[j]);
  }
  const double trace = second[0][0] + second[1][1] + second[2][2];
  btMatrix3x3 inertia;  // per kg: (tr(C) I - C) / V
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) inertia[i][j] = btScalar(((i == j ? trace : 0.0) - second[i][j]) / volume);
  btMatrix3x3 rotation;  // inertia = rotation * diag * rotation^T
  inertia.diagonalize(rotation, btScalar(1e-9), 50);

  ShapeInfo info;
  info.volume = volume;
  info.ownInertia = true;
  info.unitInertia = btVector3(inertia[0][0], inertia[1][1], inertia[2][2]);
  info.principal = rotation;
  auto shape = std::make_unique<btConvexHullShape>();
  for (const auto& p : hull.points) {
    const btVector3 local(btScalar(p[0] - centroid[0]), btScalar(p[1] - centroid[1]), btScalar(p[2] - centroid[2]));
    shape->addPoint(rotation.transpose() * local, false);
  }
  shape->recalcLocalAabb();
  info.shape = std::move(shape);
  return info;
}

btVector3 vec3(const Json& v) {
  if (!v.is_array() || v.size() != 3) throw std::runtime_error("expected [x, y, z], got " + v.dump());
  return btVector3(btScalar(v[0].get<double>()), btScalar(v[1].get<double>()), btScalar(v[2].get<double>()));
}

// The scene in Bullet. Members go in this order so that the world goes before the shapes and the
// joints go first (~BulletScene takes them out of the world).
struct BulletScene {
  std::map<std::string, ShapeInfo> shapes;  // one per distinct shape: every cube shares one btBoxShape
  std::vector<std::unique_ptr<btCollisionShape>> planeShapes;
  BulletWorld bw{1.0, 0.6};  // its box and ground shapes go unused: the file says the shapes and planes
  std::vector<std::unique_ptr<btTypedConstraint>> joints;
  std::vector<btRigidBody*> bodies;  // the file's bodies, in its order
  double dt = 0.0;

  ~BulletScene() {
    for (auto& joint : joints) bw.world.removeConstraint(joint.get());
  }

  const ShapeInfo& shapeFor(const Json& shape, const std::string& dir) {
    const std::string type = shape.at("type").get<std::string>();
    const std::string key = type + " " + shape.dump();
    auto found = shapes.find(key);
    if (found != shapes.end()) return found->second;
    ShapeInfo info;
    if (type == "box") {
      const btVector3 extents = vec3(shape.at("extents"));  // full extents
      info.shape = std::make_unique<btBoxShape>(extents * btScalar(0.5));
      info.volume = double(extents.x()) * double(extents.y()) * double(extents.z());
    } else if (type == "sphere") {
      const double r = shape.at("radius").get<double>();
      info.shape = std::make_unique<btSphereShape>(btScalar(r));
      info.volume = 4.0 / 3.0 * M_PI * r * r * r;
    } else if (type == "mesh") {
      info = hullShape(dir + "/" + shape.at("file").get<std::string>());  // convex: the four scenes' mesh is a hull
    } else {
      throw std::runtime_error("shape type '" + type + "' is not put into Bullet here");
    }
    return shapes.emplace(key, std::move(info)).first->second;
  }

  btRigidBody* add(btCollisionShape* shape, btScalar mass, const btVector3& inertia, const btTransform& transform,
                   double friction, double restitution, int group, int mask) {
    bw.motionStates.push_back(std::make_unique<btDefaultMotionState>(transform));
    btRigidBody::btRigidBodyConstructionInfo info(mass, bw.motionStates.back().get(), shape, inertia);
    info.m_friction = btScalar(friction);
    info.m_restitution = btScalar(restitution);
    bw.bodies.push_back(std::make_unique<btRigidBody>(info));
    bw.world.addRigidBody(bw.bodies.back().get(), group, mask);
    return bw.bodies.back().get();
  }

  void load(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    const Json file = Json::parse(in);
    const std::string dir = path.substr(0, path.find_last_of('/'));

    const Json& world = file.at("world");
    bw.world.setGravity(vec3(world.value("gravity", Json::array({0, -9.81, 0}))));
    dt = world.value("dt", 1.0 / 60.0);
    const bool sleep = world.value("sleep", true);
    const bool collisions = world.value("collisions", true);
    const int group = collisions ? int(btBroadphaseProxy::DefaultFilter) : 1;
    const int mask = collisions ? int(btBroadphaseProxy::AllFilter) : 0;
    // Bullet's own sleep defaults where the file says nothing: 0.8 m/s, 1 rad/s, 2 s.
    const double sleepLinear = world.value("sleep_linear_speed", 0.8);
    const double sleepAngular = world.value("sleep_angular_speed", 1.0);
    gDeactivationTime = btScalar(world.value("time_to_sleep", 2.0));
    gCalculateCombinedFrictionCallback = &geometricMeanFriction;

    btTransform identity;
    identity.setIdentity();
    for (const Json& plane : file.value("planes", Json::array())) {
      const btVector3 normal = vec3(plane.at("normal")).normalized();
      const btScalar offset = normal.dot(vec3(plane.value("point", Json::array({0, 0, 0}))));
      planeShapes.push_back(std::make_unique<btStaticPlaneShape>(normal, offset));
      add(planeShapes.back().get(), 0, btVector3(0, 0, 0), identity, plane.value("friction_static", 0.5),
          plane.value("restitution", 0.0), group, mask);
    }

    std::map<std::string, btRigidBody*> named;
    for (const Json& body : file.at("bodies")) {
      for (const char* key : {"orientation", "velocity", "angular_velocity", "kinematic", "inertia", "scale"})
        if (body.contains(key)) throw std::runtime_error(std::string("body key '") + key + "' is not put into Bullet here");
      const ShapeInfo& shape = shapeFor(body.at("shape"), dir);
      const bool isStatic = body.value("static", false);
      const double mass = isStatic ? 0.0 : body.contains("mass") ? body.at("mass").get<double>() : body.value("density", 1000.0) * shape.volume;
      btVector3 inertia(0, 0, 0);
      if (mass > 0.0) {
        if (shape.ownInertia) inertia = shape.unitInertia * btScalar(mass);
        else shape.shape->calculateLocalInertia(btScalar(mass), inertia);
      }
      btTransform transform(shape.principal, vec3(body.at("position")));  // "position": the centre of mass
      btRigidBody* rb = add(shape.shape.get(), btScalar(mass), inertia, transform, body.value("friction_static", 0.5),
                            body.value("restitution", 0.0), group, mask);
      if (!isStatic) {
        if (sleep) rb->setSleepingThresholds(btScalar(sleepLinear), btScalar(sleepAngular));
        else rb->setActivationState(DISABLE_DEACTIVATION);
      }
      bodies.push_back(rb);
      if (body.contains("name")) named[body.at("name").get<std::string>()] = rb;
    }

    for (const Json& joint : file.value("joints", Json::array())) {
      const std::string type = joint.at("type").get<std::string>();
      if (type != "ball") throw std::runtime_error("joint type '" + type + "' is not put into Bullet here");
      btRigidBody* a = named.at(joint.at("body_a").get<std::string>());
      btRigidBody* b = named.at(joint.at("body_b").get<std::string>());
      const btVector3 anchor = vec3(joint.at("anchor"));  // world point at the start
      const btVector3 pivotA = a->getCenterOfMassTransform().inverse() * anchor;
      const btVector3 pivotB = b->getCenterOfMassTransform().inverse() * anchor;
      joints.push_back(std::make_unique<btPoint2PointConstraint>(*a, *b, pivotA, pivotB));
      bw.world.addConstraint(joints.back().get());
    }
  }
};

void run(const rbsim::bench::Box3dScene& scene, int steps, double seconds, bool stages) {
  const std::string path = std::string(RBSIM_SOURCE_DIR) + "/assets/scenes/box3d/" + scene.name + ".json";
  const auto loadStart = Clock::now();
  BulletScene bs;
  bs.load(path);
  const double loadSeconds = std::chrono::duration<double>(Clock::now() - loadStart).count();
  if (seconds > 0.0) steps = static_cast<int>(std::lround(seconds / bs.dt));

  const std::vector<btRigidBody*>& bodies = bs.bodies;
  std::vector<btVector3> start;
  std::size_t top = 0;
  bool haveTop = false;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    start.push_back(bodies[i]->getCenterOfMassPosition());
    const bool dynamic = !bodies[i]->isStaticOrKinematicObject();
    if (dynamic && (!haveTop || start[i].y() > start[top].y())) top = i, haveTop = true;
  }

  gZones.clear();
  gOpen.clear();
  btEnterProfileZoneFunc* oldEnter = btGetCurrentEnterProfileZoneFunc();
  btLeaveProfileZoneFunc* oldLeave = btGetCurrentLeaveProfileZoneFunc();
  if (stages) {
    btSetCustomEnterProfileZoneFunc(&enterZone);
    btSetCustomLeaveProfileZoneFunc(&leaveZone);
  }
  std::vector<double> ms;
  ms.reserve(static_cast<std::size_t>(steps));
  const double cpu0 = rbsim::bench::processCpuSeconds();
  const auto wall0 = Clock::now();
  for (int s = 0; s < steps; ++s) {
    const auto t0 = Clock::now();
    bs.bw.world.stepSimulation(btScalar(bs.dt), 0);  // exactly one step of dt, no interpolation
    ms.push_back(1e3 * std::chrono::duration<double>(Clock::now() - t0).count());
  }
  const double wall = std::chrono::duration<double>(Clock::now() - wall0).count();
  const double cpu = rbsim::bench::processCpuSeconds() - cpu0;
  btSetCustomEnterProfileZoneFunc(oldEnter);
  btSetCustomLeaveProfileZoneFunc(oldLeave);

  double fastest = 0.0, deepest = 0.0;
  std::size_t awake = 0, dynamic = 0;
  for (const btRigidBody* b : bodies) {
    if (b->isStaticOrKinematicObject()) continue;
    ++dynamic;
    fastest = std::max(fastest, static_cast<double>(b->getLinearVelocity().length()));
    if (b->isActive()) ++awake;
  }
  std::size_t contacts = 0, points = 0;
  btCollisionDispatcher& dispatcher = bs.bw.dispatcher;
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    if (manifold->getNumContacts() > 0) ++contacts;
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      ++points;
      deepest = std::max(deepest, -static_cast<double>(manifold->getContactPoint(p).getDistance()));
    }
  }
  double drift = 0.0, sink = 0.0;
  if (haveTop) {
    const btVector3 topNow = bodies[top]->getCenterOfMassPosition();
    drift = std::hypot(double(topNow.x() - start[top].x()), double(topNow.z() - start[top].z()));
    sink = double(start[top].y() - topNow.y());
  }
  std::vector<double> sorted = ms;
  double median = 0.0;
  if (!sorted.empty()) {
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    median = sorted[sorted.size() / 2];
  }
  const int per = std::max(steps, 1);
  std::printf("%-14s %6zu bodies %5zu joints  load %7.3f s  %5d steps  wall %8.2f ms/step (median %8.2f)  cpu %8.2f "
              "ms/step  threads %d\n",
              scene.name, dynamic, bs.joints.size(), loadSeconds, steps, 1e3 * wall / per, median, 1e3 * cpu / per, 1);
  std::printf("%-14s end: fastest %.4f m/s  top drift %.4f m  top sink %.4f m  deepest %.4f m  awake %zu  contacts %zu"
              "  points %zu\n",
              scene.name, fastest, drift, sink, deepest, awake, contacts, points);
  if (stages) {
    // Shares of the timed steps' wall time; "other" is stepSimulation's own work outside every zone
    // (motion states, gravity, clearing forces).
    const double total = 1e-3 * std::accumulate(ms.begin(), ms.end(), 0.0);
    double zoned = 0.0;
    for (const Zone& z : gZones) zoned += z.self;
    std::vector<Zone> byShare = gZones;
    byShare.push_back({"other", total - zoned, total - zoned});
    std::sort(byShare.begin(), byShare.end(), [](const Zone& a, const Zone& b) { return a.self > b.self; });
    std::printf("%-14s stages:", scene.name);
    for (const Zone& z : byShare)
      if (total > 0.0 && z.self > 0.005 * total) std::printf("  %s %.0f%%", z.name, 100.0 * z.self / total);
    std::printf("\n");
  }
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> names;
  int steps = 0;
  double seconds = 0.0;
  bool stages = true;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) {
      std::fprintf(stderr, "bullet_box3d_scenes: %s needs a value\n", arg.c_str());
      return 2;
    }
    const std::string value = argv[++i];
    if (arg == "--scenes") names = rbsim::bench::splitCommas(value);
    else if (arg == "--steps") steps = std::atoi(value.c_str());
    else if (arg == "--seconds") seconds = std::atof(value.c_str());
    else if (arg == "--stages") stages = value != "off";
    else {
      std::fprintf(stderr, "bullet_box3d_scenes: unknown option %s\n", arg.c_str());
      return 2;
    }
  }
  for (const std::string& name : names)
    if (std::none_of(std::begin(rbsim::bench::kBox3dScenes), std::end(rbsim::bench::kBox3dScenes), [&](const rbsim::bench::Box3dScene& s) { return name == s.name; })) {
      std::fprintf(stderr, "bullet_box3d_scenes: unknown scene %s\n", name.c_str());
      return 2;
    }
  std::printf("Bullet %d, %s precision\n", btGetVersion(), sizeof(btScalar) == 8 ? "double" : "float");
  try {
    for (const rbsim::bench::Box3dScene& scene : rbsim::bench::kBox3dScenes) {
      if (!scene.inBullet) {
        if (!names.empty() && std::find(names.begin(), names.end(), scene.name) != names.end()) {
          std::fprintf(stderr, "bullet_box3d_scenes: %s needs what this loader does not build (compound bodies and a kinematic motion, or ragdolls, spawners and mesh grounds)\n", scene.name);
          return 2;
        }
        continue;
      }
      if (!names.empty() && std::find(names.begin(), names.end(), scene.name) == names.end()) continue;
      run(scene, steps > 0 ? steps : scene.steps, seconds, stages);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bullet_box3d_scenes: %s\n", e.what());
    return 2;
  }
  return 0;
}
