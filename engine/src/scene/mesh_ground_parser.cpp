#include "scene/mesh_ground_parser.h"

namespace rbsim::scene_detail {

bool collidesAsTriangles(const JsonObject& b) {
  if (!b.has("collide_as")) return false;
  if (b.string("collide_as", "") != "triangles") b.fail("collide_as", "expected \"triangles\" (a static mesh ground)");
  if (b.has("shapes")) b.fail("collide_as", "a compound body collides as its shapes; expected one \"shape\" of type \"mesh\"");
  const bool meshShape = b.has("shape") && b.raw("shape").is_object() && b.raw("shape").value("type", "") == "mesh";
  if (!meshShape) b.fail("collide_as", "only a \"mesh\" shape collides as triangles; expected \"shape\": {\"type\": \"mesh\", ...}");
  if (b.has("sdf")) b.fail("sdf", "a body colliding as triangles has no grid; expected no \"sdf\" with \"collide_as\"");
  return true;
}

CookRequest triangleGround(const JsonObject& b, BodyDef& def) {
  def.shape = Shape::mesh(*def.mesh);
  CookRequest request;
  request.kind = CookRequest::Kind::Triangles;
  request.mesh = def.mesh;
  request.file = b.file();
  request.shapeField = b.pathOf("shape");
  request.resolutionField = request.shapeField;
  return request;
}

void checkTriangleGroundIsStatic(const JsonObject& b, const BodyDef& def) {
  // Checked here too for a compound body, whose "shapes" never reach collidesAsTriangles.
  if (collidesAsTriangles(b) && !def.isStatic) {
    b.fail("collide_as", "only a static body collides as triangles (a mesh ground); expected \"static\": true");
  }
}

}  // namespace rbsim::scene_detail
