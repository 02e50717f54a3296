#pragma once
// What a scene file says about how it is shown (its "view" block and each particle system's
// look): plain data the scene loader fills and the app turns into pixels. The engine itself
// never reads it.
#include <cstddef>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "rbsim/math/types.h"

namespace rbsim {

// A layer of one body's signed distance grid shown beside the scene (view.sdf_slice; app/run/
// sdf_slice_view.h): phi with its zero contour, and the narrow band and flood-fill regions that
// built it (seed 000 "Constructing Signed Distance Functions"). In the body frame, so it moves
// with the body; the layer nearest the offset is shown.
struct SdfSliceDesc {
  std::size_t body = 0;   // index into the scene's bodies; the body has a grid
  int axis = 2;           // the layer's normal, a body axis: 0 x, 1 y, 2 z
  double offset = 0.0;    // along the axis from the centre of mass at t = 0 [m]
  double sweepTo = 0.0;   // at the scene's end [m], moved linearly in time; = offset: still
};

// How the scene is shown; plain data, the app turns it into pixels.
struct ViewDesc {
  Vec3 eye = Vec3(4.0, 3.0, 6.0);      // camera position [m]
  Vec3 target = Vec3(0.0, 0.5, 0.0);   // point looked at [m]
  Vec3 up = Vec3(0.0, 1.0, 0.0);
  double fovDegrees = 45.0;            // vertical field of view
  int width = 1280;                    // [px]
  int height = 720;                    // [px]
  int fps = 30;                        // frames per simulated second
  bool overlay = true;
  // How much of the variables panel shows: compact, the title, the caption and about 8 rows chosen
  // for the scene; full, every row; off, none (plots and captions stay).
  enum class Panel { Compact, Full, Off };
  Panel panel = Panel::Compact;
  bool wireframe = false;
  bool axes = true;
  bool grid = true;
  bool aabbs = false;     // draw AABBs (red when in a pair), compare pairs with brute force
  bool contacts = false;  // draw contact points, normals, distances and impact ghosts
  // Draw each body's vertex list p' = R p + x as the engine computed it (seed 004 section 2: "do
  // this transform yourself"), as dots over the body the renderer drew from R and x.
  bool vertices = false;
  // Bodies that share a mesh may be drawn as instances of it: its body-space copy moved by (R, x)
  // on the GPU. Off, every body is drawn from the world vertices the engine computed, as seed 004's
  // assignment asks ("do this transform yourself"); demo 2 draws so.
  bool instancing = true;
  std::size_t selected = 0;            // body shown in the overlay
  // The camera moves with the selected body (eye and target keep their offset from it), so a
  // body that rolls or flies away stays in view.
  bool follow = false;
  std::string caption;
  // Time plots in the overlay (app/run/plot_history.h): names of kPlotQuantities, of the whole
  // scene or (plotSelected) of the selected body, over the last plotSeconds (0: the whole scene).
  std::vector<std::string> plots;
  bool plotSelected = false;
  double plotSeconds = 0.0;  // [s]
  std::optional<SdfSliceDesc> sdfSlice;  // none: no slice shown
};

// A body drawn without a colour of its own [linear RGB].
inline const Vec3 kDefaultBodyColor(0.85, 0.45, 0.2);

// The colours of a scene's bodies (each key "color", linear RGB in [0, 1]), which the engine never
// keeps: by name for the listed bodies (and those added by a program), by spawner name for the
// copies NAME_k a spawner makes. The app finds a body's by its name (app/render/body_colors.h).
struct BodyColors {
  std::unordered_map<std::string, Vec3> byBody;
  std::unordered_map<std::string, Vec3> bySpawner;
};

// The quantities view.plots may name.
inline const std::vector<std::string> kPlotQuantities = {"ke", "pe", "E", "|P|", "|L|", "contacts", "error", "drift"};

// How one particle system is drawn: camera-facing sprites whose colour, opacity and size follow
// the particle's age fraction a = age / lifetime from birth (a = 0) to death (a = 1).
struct ParticleLook {
  enum class Blend { Additive, Alpha };
  Blend blend = Blend::Alpha;        // additive: light adds up (fire); alpha: covers (smoke)
  bool hasColorEnd = false;          // false: the birth colour throughout
  Vec3 colorEnd = Vec3::Zero();      // linear RGB at a = 1, mixed linearly from the birth colour
  double alphaStart = 1.0;           // opacity at a = 0 [1]
  double alphaEnd = 1.0;             // opacity at a = 1 [1]
  double sizeEndScale = 1.0;         // drawn size at a = 1 over the size at birth [1]
};

}  // namespace rbsim
