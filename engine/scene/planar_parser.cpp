// "planar": {"depth": 0.4, "lines": [{"normal": [0, 1], "offset": 0}], "bodies": [{"name",
// "shape": {"type": "box", "extents": [w, h]} or {"type": "polygon", "corners": [[x, y], ...]},
// "mass", "position": [x, y], "angle_deg", "velocity": [vx, vy], "angular_velocity",
// "restitution", "friction_static", "friction_kinetic", "color"}]}
#include "scene/planar_parser.h"

#include <cmath>
#include <stdexcept>

#include "scene/body_parser.h"

namespace rbsim::scene_detail {

namespace {

constexpr double kDegreesToRadians = M_PI / 180.0;

Vec2 vec2(const JsonObject& o, const char* key, const Vec2& fallback) {
  if (!o.has(key)) return fallback;
  const nlohmann::json& v = o.raw(key);
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) o.fail(key, "expected an array of 2 numbers");
  const Vec2 out(v[0].get<double>(), v[1].get<double>());
  if (!out.allFinite()) o.fail(key, "expected finite numbers");
  return out;
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
  std::vector<Vec2> corners;
  for (const nlohmann::json& c : shape.raw("corners")) {
    if (!c.is_array() || c.size() != 2 || !c[0].is_number() || !c[1].is_number()) shape.fail("corners", "expected [x, y] pairs");
    corners.emplace_back(c[0].get<double>(), c[1].get<double>());
  }
  // Convex and counter-clockwise: every turn to the left.
  for (std::size_t i = 0; i < corners.size() && corners.size() >= 3; ++i) {
    const Vec2 a = corners[(i + 1) % corners.size()] - corners[i];
    const Vec2 b = corners[(i + 2) % corners.size()] - corners[(i + 1) % corners.size()];
    if (!(cross2(a, b) > 0.0)) shape.fail("corners", "expected a convex polygon wound counter-clockwise");
  }
  if (corners.size() < 3) shape.fail("corners", "expected at least 3 corners");
  return corners;
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
    if (!(line.normal.norm() > 0.0)) l.fail("normal", "expected a non-zero direction");
    line.normal.normalize();
    line.offset = l.number("offset", 0.0);
    line.material = parseMaterial(l);
    world.addLine(line);
  }
  for (const JsonObject& b : p.objectArray("bodies", {"name", "shape", "mass", "position", "angle_deg", "velocity",
                                                      "angular_velocity", "restitution", "friction_static",
                                                      "friction_kinetic", "color"})) {
    const std::string name = b.string("name", "shape" + std::to_string(world.bodies().size()));
    PlanarBody body(name, parseShape(b), b.positiveNumber("mass", 1.0), parseMaterial(b));
    body.state().position = vec2(b, "position", Vec2::Zero());
    body.state().angle = kDegreesToRadians * b.number("angle_deg", 0.0);
    body.state().linearMomentum = body.mass() * vec2(b, "velocity", Vec2::Zero());
    body.state().angularMomentum = body.inertia() * b.number("angular_velocity", 0.0);
    const Vec3 color = b.vec3("color", Vec3(0.8, 0.5, 0.2));
    if (color.minCoeff() < 0.0 || color.maxCoeff() > 1.0) b.fail("color", "components must lie in [0, 1]");
    scene.planarColors.push_back(color);
    world.addBody(body);
  }
  if (world.bodies().empty()) p.fail("bodies", "expected a non-empty array of 2D bodies");
  scene.planar = world;
}

}  // namespace rbsim::scene_detail
