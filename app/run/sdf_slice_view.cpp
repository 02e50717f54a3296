#include "run/sdf_slice_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "rbsim/geometry/sdf_slice.h"
#include "run/to_glm.h"

namespace rbsim::app {

namespace {

// Diverging map (ColorBrewer's RdBu, as shown): white at phi = 0, red inside, blue outside,
// saturated at the body's depth (the most negative phi of its grid) either side.
const glm::vec3 kZeroColor(0.97f, 0.97f, 0.97f);
const glm::vec3 kInsideMid(0.96f, 0.65f, 0.51f), kInsideEnd(0.70f, 0.09f, 0.17f);
const glm::vec3 kOutsideMid(0.57f, 0.77f, 0.87f), kOutsideEnd(0.13f, 0.40f, 0.67f);
constexpr int kColorBarSteps = 32;  // stops of the drawn colour bar [1]
// Region colours: light where the narrow band set the value, dark where fast marching did.
const glm::vec3 kOutsideBand(0.62f, 0.80f, 0.96f), kOutsideMarched(0.16f, 0.33f, 0.58f);
const glm::vec3 kInsideBand(1.00f, 0.74f, 0.42f), kInsideMarched(0.72f, 0.33f, 0.10f);
const glm::vec3 kCavityBand(0.84f, 0.70f, 0.96f), kCavityMarched(0.45f, 0.27f, 0.62f);
const glm::vec3 kOnSurfaceColor(1.0f, 1.0f, 1.0f);
const glm::vec3 kGivenColor(0.55f, 0.55f, 0.58f);  // a grid of given values: no build stages
const glm::vec3 kContourColor(0.0f, 0.0f, 0.0f);
// In the 3D view: the layer's outline and its zero contour, drawn over the body.
const glm::vec3 kSliceFrame3d(1.0f, 0.85f, 0.1f), kContour3d(1.0f, 1.0f, 1.0f);

glm::vec3 mix(const glm::vec3& a, const glm::vec3& b, float t) { return a + (b - a) * t; }

// phi / depth in [-1, 1] to the diverging colour, through the middle stop at |t| = 1/2.
glm::vec3 divergingColor(double phi, double depth) {
  const float t = static_cast<float>(std::clamp(std::abs(phi) / depth, 0.0, 1.0));
  const glm::vec3& mid = phi < 0.0 ? kInsideMid : kOutsideMid;
  const glm::vec3& end = phi < 0.0 ? kInsideEnd : kOutsideEnd;
  return t < 0.5f ? mix(kZeroColor, mid, 2.0f * t) : mix(mid, end, 2.0f * t - 1.0f);
}

glm::vec3 regionColor(SdfFillRegion region, SdfStage stage) {
  const bool band = stage == SdfStage::ExactBand;
  switch (region) {
    case SdfFillRegion::Outside: return band ? kOutsideBand : kOutsideMarched;
    case SdfFillRegion::Inside: return band ? kInsideBand : kInsideMarched;
    case SdfFillRegion::Cavity: return band ? kCavityBand : kCavityMarched;
    case SdfFillRegion::OnSurface: return kOnSurfaceColor;
    case SdfFillRegion::Unknown: break;
  }
  return kGivenColor;
}

std::string sliceText(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c);
  return buffer;
}

}  // namespace

void addSdfSliceView(const World& world, const Scene& scene, render::FrameData& frame) {
  if (!scene.view.sdfSlice || scene.view.sdfSlice->body >= scene.bodies.size()) return;
  const SdfSliceDesc& desc = *scene.view.sdfSlice;
  const BodyDef& def = scene.bodies[desc.body];
  if (!def.sdf || desc.body >= world.bodies().size()) return;
  const SignedDistanceGrid& grid = *def.sdf;
  // The sweep: the offset moves linearly from "offset" to "sweep_to" over the scene's duration.
  const double progress = scene.duration > 0.0 ? std::clamp(world.time() / scene.duration, 0.0, 1.0) : 0.0;
  const SdfSlice slice = sdfSlice(grid, desc.axis, desc.offset + progress * (desc.sweepTo - desc.offset));
  const std::vector<ContourSegment> contour = sdfZeroContour(slice);

  // The whole grid once: its depth (the colour scale) and which regions it has (the legend's).
  double depth = 0.0;
  bool cavity = false, onSurface = false, given = false;
  for (int k = 0; k < grid.dims().z(); ++k) {
    for (int j = 0; j < grid.dims().y(); ++j) {
      for (int i = 0; i < grid.dims().x(); ++i) {
        depth = std::max(depth, -grid.value(i, j, k));
        const SdfFillRegion r = grid.fillRegion(i, j, k);
        cavity = cavity || r == SdfFillRegion::Cavity;
        onSurface = onSurface || r == SdfFillRegion::OnSurface;
        given = given || r == SdfFillRegion::Unknown;
      }
    }
  }
  if (!(depth > 0.0)) depth = grid.cellSize();

  render::OverlayMap phiMap, stageMap;
  phiMap.title = "phi, the signed distance";
  stageMap.title = given ? "no build stages (values given)" : "stage and flood-fill region";
  for (render::OverlayMap* m : {&phiMap, &stageMap}) {
    m->columns = slice.width;
    m->rows = slice.height;
    m->lineColor = kContourColor;
    for (const ContourSegment& c : contour) {
      m->lines.emplace_back(static_cast<float>(c.a.x()), static_cast<float>(c.a.y()), static_cast<float>(c.b.x()),
                            static_cast<float>(c.b.y()));
    }
  }
  phiMap.lineWidthPixels = 2.5f;
  stageMap.lineWidthPixels = 1.5f;
  int exact = 0, marched = 0;
  for (std::size_t i = 0; i < slice.phi.size(); ++i) {
    phiMap.colors.push_back(divergingColor(slice.phi[i], depth));
    stageMap.colors.push_back(regionColor(slice.region[i], slice.stage[i]));
    exact += slice.stage[i] == SdfStage::ExactBand;
    marched += slice.stage[i] == SdfStage::Marched;
  }
  for (int s = 0; s <= kColorBarSteps; ++s) phiMap.colorBar.push_back(divergingColor(depth * (2.0 * s / kColorBarSteps - 1.0), depth));
  phiMap.colorBarLabels = {sliceText("-%.3f m", depth), "0", sliceText("+%.3f m", depth)};
  phiMap.legend = {{{kInsideEnd}, "phi < 0: inside"},
                   {{kOutsideEnd}, "phi > 0: outside (full blue beyond the depth)"},
                   {{kContourColor}, "phi = 0: the zero contour"}};
  const double band = SdfGridOptions{}.exactBandCells;
  if (given) {
    stageMap.legend = {{{kGivenColor}, "values sampled from the shape's exact function: no narrow band, marching or fill"}};
  } else {
    stageMap.legend = {
        {{kOutsideBand, kInsideBand}, sliceText("light: narrow band, exact distance (|phi| <= %.0f h)", band)},
        {{kOutsideMarched, kInsideMarched}, "dark: fast marching out from the band"},
        {{kOutsideBand, kOutsideMarched}, "blue: outside, the flood fill reached it from the grid's border"},
        {{kInsideBand, kInsideMarched}, "orange: inside, enclosed, normals vote in"}};
    if (cavity) stageMap.legend.push_back({{kCavityBand, kCavityMarched}, "purple: a cavity, enclosed, normals vote out"});
    if (onSurface) stageMap.legend.push_back({{kOnSurfaceColor}, "white: a point on the surface, cut off alone"});
  }

  static const char* const kAxisNames[] = {"x", "y", "z"};
  render::OverlayMaps& maps = frame.overlay.maps;
  maps.leftFraction = kSliceColumnLeft;
  maps.heading = scene.title.empty() ? frame.overlay.title : scene.title;  // the phase, not only the demo
  if (!scene.view.caption.empty()) maps.notes.push_back(scene.view.caption);
  const glm::ivec3 dims(grid.dims().x(), grid.dims().y(), grid.dims().z());
  maps.notes.push_back("body '" + def.name + "': grid " + std::to_string(dims.x) + " x " + std::to_string(dims.y) + " x " +
                       std::to_string(dims.z) + " points, cell h = " + sliceText("%.4f m", grid.cellSize()));
  maps.notes.push_back(std::string("slice ") + kAxisNames[slice.axis] + " = " + sliceText("%+.3f m", slice.offset) +
                       " (body frame, layer " + std::to_string(slice.layer + 1) + " of " + std::to_string(grid.dims()[slice.axis]) +
                       "): " + std::to_string(exact) + " exact, " + std::to_string(marched) + " marched; " +
                       kAxisNames[slice.uAxis] + " right, " + kAxisNames[slice.vAxis] + " up");
  maps.maps = {std::move(phiMap), std::move(stageMap)};

  // The layer in the 3D view, where the body is now: its outline and its zero contour.
  const RigidBody& body = world.bodies()[desc.body];
  const auto toWorld = [&](double u, double v) { return toGlm(body.bodyToWorld(slice.point(u, v))); };
  const double uMax = slice.width - 1, vMax = slice.height - 1;
  const glm::vec3 corners[4] = {toWorld(0, 0), toWorld(uMax, 0), toWorld(uMax, vMax), toWorld(0, vMax)};
  for (int c = 0; c < 4; ++c) frame.lines.push_back({corners[c], corners[(c + 1) % 4], kSliceFrame3d, true});
  for (const ContourSegment& c : contour) {
    frame.lines.push_back({toWorld(c.a.x(), c.a.y()), toWorld(c.b.x(), c.b.y()), kContour3d, true});
  }
}

}  // namespace rbsim::app
