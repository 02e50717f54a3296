#pragma once
// What the renderer is given for one frame: a read-only snapshot the app builds from the World.
// The engine never sees this file; the renderer never sees the engine.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace rbsim::render {

// One body, already transformed by the engine (seed 004: "do this transform yourself, not with a
// graphics function"): world vertices p' = R p + x, and the body's triangle list.
struct BodyView {
  std::vector<glm::vec3> worldVertices;
  const std::vector<std::array<std::uint32_t, 3>>* triangles = nullptr;  // owned by the mesh
  glm::vec3 position{0.0f};          // x: centre of mass, world frame [m]
  glm::mat3 rotation{1.0f};          // R: columns are the body axes in world frame
  glm::vec3 color{0.8f, 0.5f, 0.2f};  // linear RGB in [0, 1]
  float axisLength = 0.5f;           // length of the drawn body axes [m]
  bool selected = false;             // the body whose variables the overlay shows
  // Below 1 the body is a see-through "ghost" (e.g. drawn at its time of impact): blended over
  // everything opaque, farthest ghost first, without a shadow. 0 or less: not drawn at all.
  float opacity = 1.0f;
  // A smooth surface (a cloth): normals averaged over the triangles sharing each vertex, and only
  // its open border outlined, instead of flat faces with every crease drawn.
  bool smooth = false;
  // The rigid mesh the body was built from (type-erased: the renderer never sees the engine), or
  // empty for a surface that deforms (cloth, soft body) or a one-off shape. Bodies naming the same
  // mesh may be drawn as instances of it: the renderer uploads its shape once, in body space, and
  // per frame only each body's (R, x) - the engine's own transform, unchanged, so the picture is
  // the one worldVertices describe (seed 004: the app, not a graphics call, owns the pose).
  // Holding the owner keeps the address, the renderer's cache key, from being reused meanwhile.
  std::shared_ptr<const void> mesh;
};

// A force drawn as an arrow from its application point (world frame).
struct ForceArrow {
  glm::vec3 point{0.0f};
  glm::vec3 force{0.0f};  // [N]; drawn scaled by RenderOptions::forceScale
};

// A debug segment (AABB edge, contact normal, swept box), world frame. Depth-tested against the
// bodies unless onTop, which draws it over everything (a normal starting inside two bodies).
struct DebugLine {
  glm::vec3 a{0.0f};
  glm::vec3 b{0.0f};
  glm::vec3 color{1.0f};  // linear RGB in [0, 1]
  bool onTop = false;
};

// A debug dot (contact point): a round screen-space disc with a thin dark rim, always drawn over
// everything, so a contact buried between overlapping bodies still shows.
struct DebugPoint {
  glm::vec3 position{0.0f};  // world frame [m]
  glm::vec3 color{1.0f};     // linear RGB in [0, 1]
  float sizePixels = 8.0f;   // diameter in pixels of the output image, whatever its size
};

// Suggested debug colours (linear RGB), chosen to stand apart from body colours and from each
// other on the grey ground and blue sky.
inline constexpr glm::vec3 kDebugAabbColor{0.25f, 0.85f, 1.00f};           // cyan
inline constexpr glm::vec3 kDebugOverlapAabbColor{1.00f, 0.08f, 0.06f};    // red: pair overlaps
inline constexpr glm::vec3 kDebugSweptAabbColor{0.75f, 0.78f, 0.82f};      // light grey
inline constexpr glm::vec3 kDebugContactPointColor{1.00f, 0.90f, 0.00f};   // yellow
inline constexpr glm::vec3 kDebugContactNormalColor{1.00f, 0.10f, 0.90f};  // magenta
inline constexpr glm::vec3 kDebugGridNormalColor{0.30f, 1.00f, 0.25f};     // green: normal from grad phi
inline constexpr glm::vec3 kDebugImpulseColor{1.00f, 0.50f, 0.00f};        // orange: impulse j
inline constexpr glm::vec3 kDebugVertexColor{0.10f, 0.95f, 1.00f};         // cyan-white: a world vertex p' = R p + x

// One particle drawn as a camera-facing sprite; the layout is the renderer's instance attribute.
struct Sprite {
  glm::vec3 position{0.0f};  // centre, world frame [m]
  float size = 0.05f;        // diameter [m]
  glm::vec4 color{1.0f};     // linear RGB + opacity in [0, 1]
};

// The sprites of one particle system. Additive: light adds up, order does not matter (fire).
// Alpha: each covers what is behind it, so they come sorted farthest first (smoke).
struct SpriteBatch {
  bool additive = false;
  std::vector<Sprite> sprites;
};

struct Camera {
  glm::vec3 eye{4.0f, 3.0f, 6.0f};
  glm::vec3 target{0.0f, 0.5f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fovYDegrees = 45.0f;
  float nearPlane = 0.05f;  // [m]
  float farPlane = 200.0f;  // [m]
};

struct RenderOptions {
  bool grid = true;        // ground grid in the y = 0 plane
  bool wireframe = false;  // triangle edges over the shaded surface
  bool axes = true;        // body axes (columns of R) as red/green/blue lines
  bool overlay = true;     // Dear ImGui panel with the selected body's variables
  float forceScale = 0.1f; // arrow length per newton [m/N]
  // Width of FrameData::lines in pixels of a 720-row image, scaled with the image height like
  // every other line the renderer draws.
  float debugLineWidth = 1.5f;
};

// A caption pinned to a point of the image, e.g. the value each world of a side-by-side
// comparison runs with (app/run/phase.h). The app projects its world point (projection.h).
struct OverlayLabel {
  std::string text;
  glm::vec2 pixel{0.0f};  // where the caption's top centre goes, in pixels from the top left
  bool leftAligned = false;  // pixel is where its top left corner goes instead
};

// A time plot in the overlay (view.plots): one line per series over the last seconds, t
// increasing to the right. NaN values leave a gap (a quantity not defined at that time).
struct OverlayPlot {
  std::string title;  // e.g. "E, total energy"
  std::string unit;   // e.g. "J"
  std::vector<std::string> legend;  // per series; empty names for a single unnamed series
  std::vector<std::vector<float>> times;   // per series [s]
  std::vector<std::vector<float>> values;  // per series, in `unit`
  float tMin = 0.0f, tMax = 1.0f;  // the time axis [s]
  bool nonNegative = false;        // a length, an energy of motion, a count: the axis starts at 0
};

// An image of coloured samples with line segments over it, and its legend: a layer of a body's
// signed distance grid (app/run/sdf_slice_view.h), drawn with ImGui (slice_panel.cpp).
struct OverlayLegendEntry {
  std::vector<glm::vec3> swatches;  // one or more colours, side by side
  std::string text;
};
struct OverlayMap {
  std::string title;
  int columns = 0, rows = 0;       // samples; column 0 at the left, row 0 at the bottom
  std::vector<glm::vec3> colors;   // per sample, columns fastest; RGB in [0, 1] as shown
  std::vector<glm::vec4> lines;    // segments (u0, v0, u1, v1) in sample coordinates
  glm::vec3 lineColor{0.0f};
  float lineWidthPixels = 2.0f;    // in a 720-row image, scaled with the image height
  std::vector<glm::vec3> colorBar;           // a gradient under the map, left to right; empty: none
  std::vector<std::string> colorBarLabels;   // spread evenly under the bar, first at its left end
  std::vector<OverlayLegendEntry> legend;
};
// Maps side by side in a column at the image's right, under a heading and lines of notes.
struct OverlayMaps {
  std::string heading;
  std::vector<std::string> notes;
  std::vector<OverlayMap> maps;
  float leftFraction = 0.5f;  // the column's left edge, of the image width [1]
};

// How much the panel shows (view.panel): a compact panel is the title, the caption and at most
// kCompactRows (panel_rows.h) of the rows, chosen by their level; a full one every row.
enum class PanelMode { Compact, Full, Off };

// How much a row matters, for the compact panel: the Essential rows first, then the Useful ones
// in order while there is room; Detail rows only in the full panel. Action rows tell what the
// user is doing just now (a drag in the window): always shown, and outside the row budget, so the
// scene's rows stay put while they come and go.
enum class RowLevel { Essential, Useful, Detail, Action };

// One row of the panel, its label and its value already formatted by the app.
struct OverlayRow {
  std::string label;
  std::string value;
  RowLevel level = RowLevel::Useful;
};

// Text for the overlay panel: a title and rows already formatted by the app, captions pinned to
// points of the image, and time plots stacked at the bottom right or under the panel.
struct OverlayData {
  std::string title;
  std::string caption;  // e.g. the demo phase being shown
  std::vector<OverlayRow> rows;
  PanelMode panel = PanelMode::Compact;
  std::vector<OverlayLabel> labels;
  std::vector<OverlayPlot> plots;
  float plotsRight = 0.0f;  // the plots' right edge [px from the left]; 0: the image's (less a margin)
  // The plots stacked under the panel, in the info column of a comparison's panes
  // (pane_layout.h), instead of at the bottom right.
  bool plotsUnderPanel = false;
  float plotsBottomInset = 0.0f;  // the plots stand this far above the image's bottom [px] (a timeline below)
  OverlayMaps maps;  // none when maps.maps is empty
};

struct FrameData {
  // A side-by-side comparison (app/run/compare_view.h): one frame per world, each drawn in a pane
  // of its own (pane_layout.h) with its own bodies, lines, camera and options; this frame's
  // scene fields are then unused, and its overlay is drawn once over the whole image.
  std::vector<FrameData> panes;
  bool infoColumn = false;  // the panes leave a column on the left to the panel and plots
  std::vector<BodyView> bodies;
  std::vector<ForceArrow> forces;
  std::vector<DebugLine> lines;    // all drawn with one upload and at most two draw calls
  std::vector<DebugPoint> points;  // one draw call
  std::vector<SpriteBatch> sprites;  // one instanced draw call per batch
  Camera camera;
  RenderOptions options;
  OverlayData overlay;
};

}  // namespace rbsim::render
