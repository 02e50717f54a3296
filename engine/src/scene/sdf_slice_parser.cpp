#include "scene/sdf_slice_parser.h"

#include <cstdio>
#include <string>

#include "rbsim/geometry/signed_distance_grid.h"
#include "scene/body_parser.h"

namespace rbsim {

SdfSliceDesc parseSdfSlice(const JsonObject& o, const Scene& scene) {
  SdfSliceDesc d;
  if (!o.has("body")) o.fail("body", "missing: expected the name of a body with a signed distance grid");
  d.body = scene_detail::findBody(scene.bodies, o, "body");
  const BodyDef& def = scene.bodies[d.body];
  // Read before cooking: the grid the body's shape will have, laid as build() lays it.
  const CookRequest* grid = nullptr;
  for (const CookRequest& request : scene.cooking) {
    if (request.mesh == def.mesh && request.kind != CookRequest::Kind::Triangles) grid = &request;
  }
  if (grid == nullptr) {
    o.fail("body", "body '" + def.name + "' has no signed distance grid (a sphere, capsule, box or convex mesh has none); "
                   "expected a non-convex mesh, an implicit shape or a body with \"sdf\"");
  }
  const std::string axis = o.string("axis", "z");
  if (axis == "x") d.axis = 0;
  else if (axis == "y") d.axis = 1;
  else if (axis == "z") d.axis = 2;
  else o.fail("axis", "expected \"x\", \"y\" or \"z\" (a body axis), got \"" + axis + "\"");
  // The grid's extent along the axis: the offsets pick one of its layers.
  SdfGridOptions options;
  options.resolution = grid->resolution;
  const GridLattice lattice = sdfGridLattice(*def.mesh, options);
  const double first = lattice.origin[d.axis], last = first + lattice.cellSize * (lattice.dims[d.axis] - 1);
  const auto within = [&](const char* key, double fallback) {
    const double value = o.number(key, fallback);
    if (value < first || value > last) {
      char range[160];
      std::snprintf(range, sizeof range, "expected %.4g to %.4g m (the grid of body '%s' along %s), got %.4g m", first, last,
                    def.name.c_str(), axis.c_str(), value);
      o.fail(key, range);
    }
    return value;
  };
  d.offset = within("offset", 0.0);
  d.sweepTo = within("sweep_to", d.offset);
  return d;
}

}  // namespace rbsim
