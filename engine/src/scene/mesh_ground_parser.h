#pragma once
// The body key "collide_as": "triangles" (issue 40, "Mesh ground"): a static body of a "mesh"
// shape that collides triangle by triangle (world/mesh_ground_contacts.h), a terrain or a level
// from an OBJ, open or closed, without a signed distance grid. Without the key a mesh body keeps
// what it had (a grid for a closed non-convex mesh, its convex hull otherwise), so existing scenes
// collide as before. Internal to scene/.
#include "rbsim/body/body_def.h"
#include "rbsim/scene/cook.h"
#include "rbsim/scene/json_fields.h"

namespace rbsim::scene_detail {

// Whether the body asks to collide as its triangles; throws, naming the file and the field,
// unless the value is "triangles", the shape is a "mesh" file and there is no "sdf" or "shapes".
bool collidesAsTriangles(const JsonObject& b);
// The collision shape of such a body: its mesh as a Mesh shape, and the request to cook its
// triangle hierarchy (rbsim/scene/cook.h).
CookRequest triangleGround(const JsonObject& b, BodyDef& def);
// After "static" is read: a body that moves cannot be a ground (its triangles have no inside).
void checkTriangleGroundIsStatic(const JsonObject& b, const BodyDef& def);

}  // namespace rbsim::scene_detail
