#include "scene/implicit_parser.h"

#include <stdexcept>
#include <string>

#include "scene/input_ranges.h"

namespace rbsim::scene_detail {

namespace {


// A required length [m] of a function: positive and within kMaxCoordinate.
double length(const JsonObject& o, const char* key) {
  const double value = o.requiredNumber(key);
  if (!(value > 0.0)) o.fail(key, "expected a length > 0 m, got " + formatNumber(value));
  if (!(value <= kMaxCoordinate)) {
    o.fail(key, "expected at most " + formatNumber(kMaxCoordinate) + " m (" + kFarFromOrigin + ")");
  }
  return value;
}

ImplicitPrimitive parseFunction(const JsonObject& o) {
  const std::string function = o.requiredString("function");
  const std::string owner = "an implicit \"" + function + "\"";
  if (function == "sphere") {
    o.allowOnly({"type", "function", "radius", "position", "orientation", "resolution"}, owner);
    return SphereSurface{length(o, "radius")};
  }
  if (function == "ellipsoid") {
    o.allowOnly({"type", "function", "radii", "position", "orientation", "resolution"}, owner);
    if (!o.has("radii")) o.fail("radii", "missing; the three semi-axes [m] are required");
    const Vec3 radii = o.positiveVec3("radii");
    if (!(radii.maxCoeff() <= kMaxCoordinate)) o.fail("radii", "expected each at most " + formatNumber(kMaxCoordinate) + " m");
    return EllipsoidSurface{radii};
  }
  if (function == "torus") {
    o.allowOnly({"type", "function", "major_radius", "minor_radius", "position", "orientation", "resolution"}, owner);
    const double major = length(o, "major_radius"), minor = length(o, "minor_radius");
    if (!(minor < major)) {
      o.fail("minor_radius", "the tube's radius " + formatNumber(minor) + " m is not less than the ring's " +
                                 formatNumber(major) + " m; expected minor_radius < major_radius");
    }
    return TorusSurface{major, minor};
  }
  if (function == "box") {
    o.allowOnly({"type", "function", "extents", "position", "orientation", "resolution"}, owner);
    if (!o.has("extents")) o.fail("extents", "missing; the box's three edge lengths [m] are required");
    const Vec3 extents = o.positiveVec3("extents");
    if (!(extents.maxCoeff() <= kMaxCoordinate)) o.fail("extents", "expected each at most " + formatNumber(kMaxCoordinate) + " m");
    return BoxSurface{0.5 * extents};
  }
  if (function == "capsule") {
    o.allowOnly({"type", "function", "radius", "length", "position", "orientation", "resolution"}, owner);
    const double radius = length(o, "radius");
    const double between = o.requiredNumber("length");
    if (!(between >= 0.0 && between <= kMaxCoordinate)) {
      o.fail("length", "expected the distance between the caps' centres, 0 to " + formatNumber(kMaxCoordinate) + " m");
    }
    return CapsuleSurface{radius, 0.5 * between};
  }
  if (function == "cylinder") {
    o.allowOnly({"type", "function", "radius", "height", "position", "orientation", "resolution"}, owner);
    const double radius = length(o, "radius");
    return CylinderSurface{radius, 0.5 * length(o, "height")};
  }
  o.fail("function", "expected \"sphere\", \"ellipsoid\", \"torus\", \"box\", \"capsule\" or \"cylinder\", got \"" +
                         function + "\"");
}

ImplicitFunction parseNode(const JsonObject& o, int depth) {
  const std::string type = o.requiredString("type");
  const Vec3 position = o.boundedVec3("position", Vec3::Zero(), kMaxCoordinate, "m", kFarFromOrigin);
  const Quat orientation = o.optionalOrientation("orientation").value_or(Quat::Identity());
  if (type == "implicit") return ImplicitFunction::primitive(parseFunction(o), position, orientation);
  if (type != "csg") {
    o.fail("type", "expected \"implicit\" or \"csg\" for an operand of a CSG shape, got \"" + type + "\"");
  }
  o.allowOnly({"type", "op", "a", "b", "position", "orientation", "resolution"}, "a \"csg\" shape");
  const std::string opName = o.requiredString("op");
  CsgOp op = CsgOp::Union;
  if (opName == "union") op = CsgOp::Union;
  else if (opName == "intersection") op = CsgOp::Intersection;
  else if (opName == "difference") op = CsgOp::Difference;
  else o.fail("op", "expected \"union\", \"intersection\" or \"difference\", got \"" + opName + "\"");
  if (depth >= kMaxCsgDepth) {
    o.fail("op", "operations nested " + std::to_string(depth + 1) + " deep; expected at most " +
                     std::to_string(kMaxCsgDepth) + " levels (each is one more evaluation per grid point)");
  }
  for (const char* key : {"a", "b"}) {
    if (!o.has(key)) o.fail(key, "missing; a CSG operation needs two operands \"a\" and \"b\" (\"implicit\" or \"csg\" shapes)");
  }
  // An operand has a shape's keys but "resolution", which is the outermost shape's.
  const auto operand = [&](const char* key) {
    return parseNode(o.object(key, {"type", "function", "op", "a", "b", "position", "orientation", "radius", "radii",
                                    "major_radius", "minor_radius", "extents", "length", "height"}),
                     depth + 1);
  };
  ImplicitFunction a = operand("a");
  ImplicitFunction b = operand("b");
  return ImplicitFunction::combine(op, std::move(a), std::move(b), position, orientation);
}

}  // namespace

ImplicitShape parseImplicitShape(const JsonObject& shape) {
  ImplicitShape out;
  out.function = std::make_shared<const ImplicitFunction>(parseNode(shape, 0));
  out.resolution = shape.positiveInt("resolution", kDefaultImplicitResolution);
  if (out.resolution < kMinSdfResolution || out.resolution > kMaxSdfResolution) {
    shape.fail("resolution", "expected " + std::to_string(kMinSdfResolution) + " to " +
                                 std::to_string(kMaxSdfResolution) + " cells along the longest side");
  }
  const std::string overBudget = implicitBudgetProblem(out);
  if (!overBudget.empty()) shape.fail("resolution", overBudget + "; use a lower resolution");
  out.budget = std::make_shared<ImplicitBudget>(out.function->primitiveCount());
  return out;
}

ImplicitMeshing meshImplicitShapeOrFail(const JsonObject& shape, const ImplicitShape& implicit) {
  try {
    return meshImplicitShape(implicit);
  } catch (const std::invalid_argument& e) {
    const std::string problem = e.what();
    if (problem.rfind("the solid is empty", 0) != 0) shape.fail("resolution", problem + "; use a lower resolution");
    shape.fail(shape.has("op") ? "op" : "function", problem + "; expected a shape with a volume of at least one grid cell");
  }
}

}  // namespace rbsim::scene_detail
