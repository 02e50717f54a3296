#include "scene/fracture_parser.h"

#include <stdexcept>
#include <string>

#include "fracture/convex_clip.h"
#include "fracture/pieces.h"

namespace rbsim::scene_detail {

std::shared_ptr<const FracturePattern> parseFracture(const JsonObject& body, const BodyDef& def) {
  const JsonObject f = body.object("fracture", {"threshold", "pieces", "seed", "planes"});
  if (!f.has("threshold")) f.fail("threshold", "expected the breaking impulse in N s");
  auto pattern = std::make_shared<FracturePattern>();
  pattern->impulseThreshold = f.positiveNumber("threshold", 1.0);
  const Mesh& mesh = *def.mesh;
  if (!isConvex(mesh, clipTolerance(mesh) * 1e3)) {
    body.fail("fracture", "only a convex body can be cut into pieces; \"" + mesh.name + "\" is not convex");
  }
  std::vector<Mesh> pieces;
  if (f.has("planes")) {
    if (f.has("pieces") || f.has("seed")) f.fail("planes", "give either \"planes\" or \"pieces\" (and \"seed\"), not both");
    std::vector<CutPlane> planes;
    for (const JsonObject& p : f.objectArray("planes", {"normal", "point"})) {
      const Vec3 normal = p.vec3("normal", Vec3::UnitY());
      if (!(normal.stableNorm() > 0.0)) p.fail("normal", "expected a non-zero direction");
      CutPlane plane;
      plane.normal = normal.stableNormalized();
      plane.offset = plane.normal.dot(p.vec3("point", Vec3::Zero()));
      planes.push_back(plane);
    }
    pieces = cutByPlanes(mesh, planes);
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
