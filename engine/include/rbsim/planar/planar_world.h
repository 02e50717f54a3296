#pragma once
// A world of 2D rigid bodies (seed 002 section 2) on ground lines: convex polygons that fall,
// tumble, collide and come to rest. Contacts are polygon corners inside a line or another
// polygon; the response is the 3D engine's, in 2D: accumulated impulses per contact point by
// projected Gauss-Seidel (seed 001's non-penetration, repulsion and complementarity), restitution
// above a threshold, Coulomb friction in the cone mu j_n, and split-impulse position correction
// that adds no energy (Catto, GDC 2005 and 2009).
#include <cstddef>
#include <vector>

#include "rbsim/planar/planar_body.h"

namespace rbsim {

struct PlanarSettings {
  Vec2 gravity = Vec2(0.0, -9.81);     // [m/s^2]
  double timeStep = 1.0 / 240.0;       // [s]
  int velocityIterations = 10;         // [sweeps]
  int positionIterations = 4;          // [sweeps]
  double restitutionThreshold = 0.5;   // [m/s]: slower approaches do not bounce
  double contactMargin = 0.01;         // [m]: corners this close are speculative contacts
  double contactSlop = 0.005;          // [m]: penetration left alone
  double positionCorrection = 0.2;     // [1] of the excess depth removed per step
};

// An infinite static line n . p = offset, solid on the side -n.
struct PlanarLine {
  Vec2 normal = Vec2::UnitY();
  double offset = 0.0;  // [m]
  Material material;
};

struct PlanarContact {
  std::size_t body = 0;   // receives +impulse
  std::size_t other = 0;  // the other body (receives -impulse), or the line
  bool againstLine = false;
  int feature = 0;             // which point of the pair (corner or clipped end), for warm starting
  Vec2 point = Vec2::Zero();   // world [m]
  Vec2 normal = Vec2::UnitY(); // unit, towards `body`
  double depth = 0.0;          // [m], < 0 when apart within the margin
  double normalImpulse = 0.0;  // [N s], after the solve
  double tangentImpulse = 0.0; // [N s]
};

class PlanarWorld {
 public:
  explicit PlanarWorld(const PlanarSettings& settings = {});  // throws on a bad time step
  std::size_t addBody(const PlanarBody& body);
  void addLine(const PlanarLine& line);  // throws unless the normal is unit

  void step();  // throws SimulationError naming the body when its state stops being finite

  std::vector<PlanarBody>& bodies() { return bodies_; }
  const std::vector<PlanarBody>& bodies() const { return bodies_; }
  const std::vector<PlanarLine>& lines() const { return lines_; }
  const std::vector<PlanarContact>& contacts() const { return contacts_; }
  const PlanarSettings& settings() const { return settings_; }
  double time() const { return static_cast<double>(steps_) * settings_.timeStep; }

 private:
  void detect();
  void collidePolygons(std::size_t i, std::size_t j, const std::vector<Vec2>& a, const std::vector<Vec2>& b);
  void solve();

  PlanarSettings settings_;
  std::vector<PlanarBody> bodies_;
  std::vector<PlanarLine> lines_;
  std::vector<PlanarContact> contacts_;
  std::vector<PlanarContact> previous_;  // last step's, sorted by (body, other, line, feature)
  std::size_t steps_ = 0;
};

}  // namespace rbsim
