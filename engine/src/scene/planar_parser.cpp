// "planar": {"depth": 0.4, "lines": [{"normal": [0, 1], "offset": 0}], "bodies": [{"name",
// "shape": {"type": "box", "extents": [w, h]} or {"type": "polygon", "corners": [[x, y], ...]},
// "mass", "position": [x, y], "angle_deg", "velocity": [vx, vy], "angular_velocity",
// "restitution", "friction_static", "friction_kinetic", "color"}]}
#include "scene/planar_parser.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "rbsim/math/types.h"
#include "rbsim/scene/json_fields.h"
#include "scene/body_parser.h"

namespace rbsim::scene_detail {

namespace {

constexpr double kDegreesToRadians = kPi / 180.0;
// The exterior angles of a convex polygon wound once sum to 2 pi; rounding leaves far less than
// this, a polygon wound twice is 2 pi away.
constexpr double kTurningTolerance = 1e-6;  // [rad]
// A polygon of more corners than this is a circle typed as a list; detection is corners x edges.
constexpr std::size_t kMaxPlanarCorners = 1024;  // [corners]
// Corner-edge tests of one step's contact detection (all pairs, both ways, plus the lines): at
// about 2 ns each, the limit is ~0.1 s of detection per step, 10 minutes per simulated second.
constexpr double kMaxPlanarDetectionWork = 5e7;  // [tests per step]

Vec2 vec2(const JsonObject& o, const char* key, const Vec2& fallback) {
  if (!o.has(key)) return fallback;
  const nlohmann::json& v = o.raw(key);
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) o.fail(key, "expected an array of 2 numbers");
  const Vec2 out(v[0].get<double>(), v[1].get<double>());
  if (!out.allFinite()) o.fail(key, "expected finite numbers");
  return out;
}

// Convex and counter-clockwise: every turn to the left, and the turns adding up to one revolution
// (a pentagram turns left at every corner too, but winds twice around its centre).
void checkConvex(const JsonObject& shape, const std::vector<Vec2>& corners) {
  double turning = 0.0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec2 a = corners[(i + 1) % corners.size()] - corners[i];
    const Vec2 b = corners[(i + 2) % corners.size()] - corners[(i + 1) % corners.size()];
    const double turn = cross2(a, b);
    if (!(turn > 0.0) || !std::isfinite(turn)) {
      shape.fail("corners", "expected a convex polygon wound counter-clockwise; the turn at corner " +
                                std::to_string((i + 1) % corners.size()) + " is " + formatNumber(turn) +
                                " m^2 (expected finite and > 0: a left turn, not a repeated, collinear or overflowing corner)");
    }
    turning += std::atan2(turn, a.dot(b));  // the exterior angle, in (0, pi)
  }
  if (std::abs(turning - 2.0 * kPi) > kTurningTolerance) {
    shape.fail("corners", "expected a convex polygon wound once counter-clockwise; its turns add up to " +
                              formatNumber(turning / (2.0 * kPi)) + " revolutions (the edges cross each other)");
  }
}

std::vector<Vec2> parseShape(const JsonObject& body) {
  const JsonObject shape = body.object("shape", {"type", "extents", "corners"});
  const std::string type = shape.requiredString("type");
  if (type == "box") {
    const Vec2 e = vec2(shape, "extents", Vec2::Zero());
    if (!(e.minCoeff() > 0.0)) shape.fail("extents", "expected 2 positive numbers [width, height] in m");
    return {Vec2(-0.5 * e.x(), -0.5 * e.y()), Vec2(0.5 * e.x(), -0.5 * e.y()), Vec2(0.5 * e.x(), 0.5 * e.y()),
            Vec2(-0.5 * e.x(), 0.5 * e.y())};
  }
  if (type != "polygon") shape.fail("type", "expected \"box\" or \"polygon\"");
  if (!shape.has("corners") || !shape.raw("corners").is_array()) shape.fail("corners", "expected an array of [x, y] corners");
  const nlohmann::json& list = shape.raw("corners");
  if (list.size() < 3 || list.size() > kMaxPlanarCorners) {
    shape.fail("corners", "expected 3 to " + std::to_string(kMaxPlanarCorners) + " corners, got " + std::to_string(list.size()));
  }
  std::vector<Vec2> corners;
  for (const nlohmann::json& c : list) {
    if (!c.is_array() || c.size() != 2 || !c[0].is_number() || !c[1].is_number()) shape.fail("corners", "expected [x, y] pairs");
    corners.emplace_back(c[0].get<double>(), c[1].get<double>());
  }
  checkConvex(shape, corners);
  return corners;
}

// Contact detection tests every corner of each body against every edge of every other body (both
// ways) and against every line, each step: its cost in corner-edge tests.
double detectionWork(const std::vector<PlanarBody>& bodies, std::size_t lines) {
  double work = 0.0, cornersBefore = 0.0;
  for (const PlanarBody& b : bodies) {
    const double corners = static_cast<double>(b.polygon().size());
    work += 2.0 * corners * cornersBefore + corners * static_cast<double>(lines);
    cornersBefore += corners;
  }
  return work;
}

}  // namespace

void parsePlanar(const JsonObject& root, Scene& scene) {
  if (!root.has("planar")) return;
  const JsonObject p = root.object("planar", {"depth", "lines", "bodies"});
  scene.planarDepth = p.positiveNumber("depth", scene.planarDepth);
  PlanarWorld world;
  for (const JsonObject& l : p.objectArray("lines", {"normal", "offset", "restitution", "friction_static", "friction_kinetic"})) {
    PlanarLine line;
    line.normal = vec2(l, "normal", line.normal);
    // stableNorm: components near 1e308 or 1e-320 have a length that norm() overflows or loses.
    if (!(line.normal.stableNorm() > 0.0)) l.fail("normal", "expected a non-zero direction");
    line.normal = line.normal.stableNormalized();
    line.offset = l.number("offset", 0.0);
    line.material = parseMaterial(l);
    world.addLine(line);
  }
  for (const JsonObject& b : p.objectArray("bodies", {"name", "shape", "mass", "position", "angle_deg", "velocity",
                                                      "angular_velocity", "restitution", "friction_static",
                                                      "friction_kinetic", "color"})) {
    const std::string name = b.string("name", "shape" + std::to_string(world.bodies().size()));
    const std::vector<Vec2> corners = parseShape(b);
    const double mass = b.positiveNumber("mass", 1.0);
    std::optional<PlanarBody> made;
    try {
      made.emplace(name, corners, mass, parseMaterial(b));
    } catch (const std::invalid_argument& e) {  // area, centroid or inertia not finite and positive
      b.fail(std::string(e.what()).find("inertia") != std::string::npos ? "mass" : "shape", e.what());
    }
    PlanarBody& body = *made;
    body.state().position = vec2(b, "position", Vec2::Zero());
    double reach = 0.0;  // the farthest corner from the centroid [m]
    for (const Vec2& corner : body.polygon()) reach = std::max(reach, corner.stableNorm());
    if (!std::isfinite(body.state().position.cwiseAbs().maxCoeff() + reach)) {
      b.fail("position", "the corners' world positions (position + " + formatNumber(reach) + " m) overflow; expected finite sums");
    }
    body.state().angle = kDegreesToRadians * b.number("angle_deg", 0.0);
    const Vec2 velocity = vec2(b, "velocity", Vec2::Zero());
    body.state().linearMomentum = body.mass() * velocity;
    if (!body.state().linearMomentum.allFinite()) {
      b.fail("velocity", "the momentum m v = " + formatNumber(body.mass()) + " kg x " + formatNumber(velocity.stableNorm()) +
                             " m/s overflows; expected a finite product");
    }
    const double spin = b.number("angular_velocity", 0.0);
    body.state().angularMomentum = body.inertia() * spin;
    if (!std::isfinite(body.state().angularMomentum)) {
      b.fail("angular_velocity", "the angular momentum I omega = " + formatNumber(body.inertia()) + " kg m^2 x " +
                                     formatNumber(spin) + " rad/s overflows; expected a finite product");
    }
    const Vec3 color = b.vec3("color", Vec3(0.8, 0.5, 0.2));
    if (color.minCoeff() < 0.0 || color.maxCoeff() > 1.0) b.fail("color", "components must lie in [0, 1]");
    scene.planarColors.push_back(color);
    world.addBody(body);
    const double work = detectionWork(world.bodies(), world.lines().size());
    if (work > kMaxPlanarDetectionWork) {
      p.fail("bodies", "with body " + std::to_string(world.bodies().size() - 1) + " (\"" + name + "\") contact detection tests " +
                           formatNumber(work) + " corner-edge pairs per step (every body against every other); the limit is " +
                           formatNumber(kMaxPlanarDetectionWork) + " per step: use fewer bodies or corners");
    }
  }
  if (world.bodies().empty()) p.fail("bodies", "expected a non-empty array of 2D bodies");
  scene.planar = world;
}

}  // namespace rbsim::scene_detail
