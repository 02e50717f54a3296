#pragma once
// Scene-file parsing of a body's "fracture" block (seed 000 "Fracture"). Internal to scene/.
#include <memory>

#include "rbsim/body/body_def.h"
#include "rbsim/fracture/fracture.h"
#include "rbsim/scene/json_fields.h"

namespace rbsim::scene_detail {

// "fracture": {"threshold": N s, "pieces": n, "seed": k}: Voronoi cells of n random sites, or
// "fracture": {"threshold": N s, "planes": [{"normal": [...], "point": [...]}, ...]}: cut by planes
// (body frame, through the centre of mass at the origin). The body must be convex, and its inertia
// exact. Fails naming the field.
std::shared_ptr<const FracturePattern> parseFracture(const JsonObject& body, const BodyDef& def);

// More pieces than this is a dust cloud, not a fracture: each piece is a body with its own
// contacts, and n pieces cost n^2 clips to make.
inline constexpr int kMaxFracturePieces = 256;

}  // namespace rbsim::scene_detail
