#include "scene/fracture_parser.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "fracture/convex_clip.h"
#include "fracture/pieces.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/scene/json_fields.h"
#include "scene/body_keys.h"

namespace rbsim::scene_detail {

std::shared_ptr<const FracturePattern> parseFracture(const JsonObject& body, const BodyDef& def) {
  const JsonObject f = body.object("fracture", kFractureKeys);
  if (!f.has("threshold")) f.fail("threshold", "expected the breaking impulse in N s");
  auto pattern = std::make_shared<FracturePattern>();
  pattern->impulseThreshold = f.positiveNumber("threshold", 1.0);
  const Mesh& mesh = *def.mesh;
  if (!isConvexSurface(mesh, clipTolerance(mesh) * 1e3)) {
    body.fail("fracture", "only a convex body can be cut into pieces; \"" + mesh.name + "\" is not convex");
  }
  std::vector<Mesh> pieces;
  if (f.has("planes")) {
    if (f.has("pieces") || f.has("seed")) f.fail("planes", "give either \"planes\" or \"pieces\" (and \"seed\"), not both");
    const std::vector<JsonObject> planeBlocks = f.objectArray("planes", kCutPlaneKeys);
    // Every plane that cuts adds at least one piece, so more planes than pieces allowed cannot all cut.
    if (planeBlocks.size() > static_cast<std::size_t>(kMaxFracturePieces - 1)) {
      f.fail("planes", "expected at most " + std::to_string(kMaxFracturePieces - 1) + " planes (each plane that cuts adds a "
                       "piece; the limit is " + std::to_string(kMaxFracturePieces) + " pieces), got " +
                       std::to_string(planeBlocks.size()));
    }
    std::vector<CutPlane> planes;
    for (const JsonObject& p : planeBlocks) {
      const Vec3 normal = p.vec3("normal", Vec3::UnitY());
      // stableNorm: components near 1e308 (or 1e-320) have a length that norm() overflows (or loses).
      if (!(normal.stableNorm() > 0.0)) p.fail("normal", "expected a non-zero direction");
      CutPlane plane;
      // Written in the file's axes about the centre of mass; cut in the body's (principal) axes.
      const Mat3& axes = def.fileFrame.axes;
      plane.normal = axes.transpose() * normal.stableNormalized();
      if (!plane.normal.allFinite() || std::abs(plane.normal.norm() - 1.0) > kUnitTolerance) {
        p.fail("normal", "cannot be made a unit direction (its length is " + formatNumber(normal.stableNorm()) + ")");
      }
      const Vec3 point = axes.transpose() * p.vec3("point", Vec3::Zero());
      plane.offset = plane.normal.dot(point);
      if (!std::isfinite(plane.offset)) {
        p.fail("point", "the plane's offset n . p overflows (" + formatNumber(plane.offset) + " m); expected a finite point");
      }
      planes.push_back(plane);
    }
    try {
      pieces = cutByPlanes(mesh, planes, static_cast<std::size_t>(kMaxFracturePieces));
    } catch (const std::length_error& e) {  // the pieces' budget
      f.fail("planes", e.what());
    }
    if (pieces.size() < 2) f.fail("planes", "the planes miss the body: expected at least 2 pieces");
  } else {
    const int count = f.positiveInt("pieces", 8);
    if (count < 2 || count > kMaxFracturePieces) {
      f.fail("pieces", "expected 2 to " + std::to_string(kMaxFracturePieces) + " pieces, got " + std::to_string(count));
    }
    const int seed = f.positiveInt("seed", 1);
    try {
      pieces = voronoiPieces(mesh, sitesInside(mesh, count, static_cast<std::uint64_t>(seed)));
    } catch (const std::invalid_argument& e) {  // a body too thin to place the sites in
      f.fail("pieces", e.what());
    }
  }
  for (Mesh& piece : pieces) pattern->pieces.push_back(std::make_shared<const Mesh>(std::move(piece)));
  const std::string misfit = checkFracturePattern(*pattern, def);
  if (!misfit.empty()) body.fail("fracture", misfit);
  return pattern;
}

}  // namespace rbsim::scene_detail
