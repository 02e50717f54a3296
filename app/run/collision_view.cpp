#include "run/collision_view.h"

#include <chrono>
#include <cstdio>
#include <limits>

#include "rbsim/world/queries.h"
#include "render/debug_shapes.h"
#include "run/format.h"
#include "run/to_glm.h"
#include "render/body_colors.h"

namespace rbsim::app {

namespace {

constexpr float kNormalLength = 0.3f;       // drawn length of a contact normal [m]
constexpr float kContactPointPixels = 9.0f;  // [px]
constexpr float kGhostOpacity = 0.3f;

// Brute force over the boxes the broad phase was given, timed: the reference the overlay
// compares sweep and prune with.
void compareWithBruteForce(const World& world, render::OverlayData& overlay) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<ProxyPair> brute = bruteForcePairs(world);
  const double bruteMs = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const StageStats& sap = world.stageStats(Stage::BroadPhase);
  const double sapMs = sap.runs > 0 ? 1e3 * sap.seconds / static_cast<double>(sap.runs) : 0.0;
  const std::vector<ProxyPair>& pairs = candidatePairs(world);
  const bool same = brute == pairs;
  overlay.rows.push_back({"bodies", format("%.0f", static_cast<double>(world.bodies().size())), render::RowLevel::Useful});
  overlay.rows.push_back({"pairs: sweep and prune", format("%.0f (%.3f ms per step, mean)", static_cast<double>(pairs.size()), sapMs), render::RowLevel::Essential});
  overlay.rows.push_back({"pairs: brute force", format("%.0f (%.3f ms, this frame)", static_cast<double>(brute.size()), bruteMs), render::RowLevel::Essential});
  overlay.rows.push_back({"pair sets equal", same ? "yes" : "NO", render::RowLevel::Essential});
}

constexpr std::size_t kListedContacts = 6;  // overlay rows of per-contact detail
// Drawn length of an impulse arrow per unit of impulse [m / (N s)]: a 1 kg box resting at
// dt = 1/240 s receives 0.04 N s per step, drawn 0.2 m long.
constexpr float kImpulseArrowScale = 5.0f;

// The contact solver's impulses (seed 000's j on body 1, the manifold's body B), and the
// quantities a student checks them against: the total impulse and the energy.
void drawImpulses(const World& world, render::FrameData& frame) {
  if (!world.settings().respondToContacts) return;
  double normalTotal = 0.0, frictionTotal = 0.0;
  int sticking = 0;
  for (const SolvedContactPoint& p : world.contactPoints()) {
    normalTotal += p.normalImpulse;
    frictionTotal += p.frictionImpulse.norm();
    sticking += p.sticking ? 1 : 0;
    const glm::vec3 from = toGlm(p.position);
    render::appendArrowLines(frame.lines, from, from + kImpulseArrowScale * toGlm(p.impulse()), render::kDebugImpulseColor);
  }
  double kinetic = 0.0, potential = 0.0;
  for (const RigidBody& body : world.bodies()) {
    kinetic += body.kineticEnergy();
    potential -= body.mass() * world.settings().gravity.dot(body.position());
  }
  // Short labels and one figure per row: the panel is at most 45 % of the frame wide.
  frame.overlay.rows.push_back({"normal impulse", format("%.4f N s (this step)", normalTotal), render::RowLevel::Useful});
  frame.overlay.rows.push_back({"friction impulse", format("%.4f N s (this step)", frictionTotal), render::RowLevel::Detail});
  frame.overlay.rows.push_back({"points sticking", format("%.0f of %.0f", sticking, static_cast<double>(world.contactPoints().size())), render::RowLevel::Detail});
  frame.overlay.rows.push_back({"all: kinetic energy", format("%.3f J", kinetic), render::RowLevel::Detail});
  frame.overlay.rows.push_back({"all: + potential", format("%.3f J", kinetic + potential), render::RowLevel::Useful});
  frame.overlay.rows.push_back({"awake bodies", format("%.0f of %.0f", static_cast<double>(awakeCount(world)), static_cast<double>(world.bodies().size())), render::RowLevel::Detail});
}

}  // namespace

void addCollisionView(const World& world, const Scene& scene, render::FrameData& frame) {
  const ViewDesc& view = scene.view;
  const std::vector<Aabb>& boxes = broadPhaseBoxes(world);
  if (view.aabbs && boxes.size() == world.bodies().size()) {
    std::vector<char> paired(world.bodies().size(), 0);
    for (const ProxyPair& p : candidatePairs(world)) paired[p.a] = paired[p.b] = 1;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const Aabb& box = boxes[i];
      render::appendBoxLines(frame.lines, toGlm(box.min), toGlm(box.max),
                             paired[i] ? render::kDebugOverlapAabbColor : render::kDebugAabbColor);
    }
    compareWithBruteForce(world, frame.overlay);
  }
  if (!view.contacts) return;
  int points = 0;
  double deepest = -std::numeric_limits<double>::infinity();
  int fromGrids = 0;
  for (const Contact& c : world.contacts()) {
    // Normals that came from a signed distance grid (grad phi, seed 000) are drawn in their own
    // colour, so a demo shows which contacts the grid found.
    const bool fromGrid = c.kind == Contact::Kind::BodyBody && (bodySolids(world)[c.a].sdf || bodySolids(world)[c.b].sdf);
    fromGrids += fromGrid ? 1 : 0;
    for (int k = 0; k < c.manifold.count; ++k) {
      const ContactPoint& p = c.manifold.points[k];
      frame.points.push_back({toGlm(p.position), render::kDebugContactPointColor, kContactPointPixels});
      render::appendArrowLines(frame.lines, toGlm(p.position), toGlm(p.position) + kNormalLength * toGlm(c.manifold.normal),
                               fromGrid ? render::kDebugGridNormalColor : render::kDebugContactNormalColor);
      deepest = std::max(deepest, p.depth);
      ++points;
    }
  }
  frame.overlay.rows.push_back({"contacts", format("%.0f manifolds, %.0f points", static_cast<double>(world.contacts().size()), points), render::RowLevel::Essential});
  if (fromGrids > 0) {
    // Pairs of non-convex bodies: surface samples against grids, or crossing triangles (Moller).
    const bool triangles = world.settings().meshContact == Settings::MeshContact::Triangles;
    frame.overlay.rows.push_back({triangles ? "non-convex pairs" : "from SDF grids",
                                  format(triangles ? "%.0f manifolds, green normals (meshes: crossing triangles)" : "%.0f manifolds, green normals", fromGrids)});
  }
  if (points > 0) frame.overlay.rows.push_back({"deepest penetration", format("%.4f m", deepest), render::RowLevel::Useful});
  drawImpulses(world, frame);
  std::size_t listed = 0;
  for (const Contact& c : world.contacts()) {
    if (++listed > kListedContacts) {
      frame.overlay.rows.push_back({"  ...", format("and %.0f more", static_cast<double>(world.contacts().size() - kListedContacts)), render::RowLevel::Detail});
      break;
    }
    const std::string who = c.kind == Contact::Kind::PlaneBody ? "plane-" + world.bodies()[c.b].name()
                                                               : world.bodies()[c.a].name() + "-" + world.bodies()[c.b].name();
    char row[128];
    const Vec3& n = c.manifold.normal;
    std::snprintf(row, sizeof row, "n (%+.2f %+.2f %+.2f) %.4f m deep", n.x(), n.y(), n.z(), c.manifold.maxDepth());
    frame.overlay.rows.push_back({"  " + who, row, render::RowLevel::Detail});
  }

  // Distance from the selected body to the nearest other body (GJK), drawn as a segment.
  double nearest = std::numeric_limits<double>::infinity();
  BodyDistance best;
  for (std::size_t j = 0; j < world.bodies().size(); ++j) {
    if (j == view.selected) continue;
    const BodyDistance d = bodyDistance(world, world.idAt(view.selected), world.idAt(j));
    if (d.distance < nearest) {
      nearest = d.distance;
      best = d;
    }
  }
  if (std::isfinite(nearest)) {
    frame.overlay.rows.push_back({"distance to nearest", best.overlap ? "overlapping" : format("%.4f m", nearest), render::RowLevel::Useful});
    if (!best.overlap) frame.lines.push_back({toGlm(best.pointA), toGlm(best.pointB), glm::vec3(0.2f, 1.0f, 0.3f), true});
  }

  // Where continuous collision stopped a body, the pose the step would have reached.
  for (const Impact& impact : impacts(world)) {
    const RigidBody& body = world.bodies()[impact.body];
    render::BodyView ghost;
    const Mat3 R = impact.unstoppedOrientation.toRotationMatrix();
    for (const Vec3& p : body.mesh().vertices) ghost.worldVertices.push_back(toGlm(R * p + impact.unstoppedPosition));
    ghost.triangles = &body.mesh().triangles;
    ghost.position = toGlm(impact.unstoppedPosition);
    for (int c = 0; c < 3; ++c) ghost.rotation[c] = toGlm(R.col(c));
    ghost.color = toGlm(bodyColor(scene.colors, body.name()));
    ghost.opacity = kGhostOpacity;
    frame.bodies.push_back(std::move(ghost));
    frame.overlay.rows.push_back({"stopped at impact", body.name() + format(" at s = %.3f of the step", impact.fraction), render::RowLevel::Essential});
  }
}

}  // namespace rbsim::app
