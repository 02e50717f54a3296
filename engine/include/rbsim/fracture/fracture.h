#pragma once
// A rigid body breaking into pieces (seed 000 "Fracture"). Each piece gets its own exact mass
// properties from its geometry, the velocity its new centre of mass had before the break,
// v_i = v + omega x r_i, and the body's angular velocity, omega_i = omega. With the pieces filling
// the body exactly, sum m_i = M and sum m_i r_i = 0, so
//   sum m_i v_i = M v                                  (linear momentum kept), and
//   sum (r_i x m_i v_i + I_i omega) = I omega          (angular momentum kept, parallel axes),
// which is why the body's own inertia must be the exact one of its mesh.
#include <memory>
#include <string>
#include <vector>

#include "rbsim/body/body_def.h"
#include "rbsim/body/rigid_body.h"
#include "rbsim/geometry/mesh.h"

namespace rbsim {

// How a body breaks: its pieces, precomputed in its body frame (centre of mass at the origin),
// and the contact impulse that breaks it.
struct FracturePattern {
  // The body breaks in the first step in which the normal impulses of its contacts sum to more
  // than this [N s]. Resting on the ground costs m |g| dt per step, so the threshold must exceed
  // that; an impact delivers m |dv| whatever the step.
  double impulseThreshold = 0.0;
  std::vector<std::shared_ptr<const Mesh>> pieces;  // closed, outward-wound, filling the body
};

// Empty when the pattern fits the body: at least two pieces, each a closed mesh of positive
// volume, their volumes summing to the body's and their centres of mass averaging to its own
// within kFractureFitTolerance of its size, and the body's inertia the exact one of its mesh.
// Otherwise what is wrong, in words.
std::string checkFracturePattern(const FracturePattern& pattern, const BodyDef& body);
inline constexpr double kFractureFitTolerance = 1e-9;  // relative [1]

// The definitions of the pieces of `body` breaking now, named "<body>/k", with the body's
// material and colour. A static body's pieces start at rest and are dynamic: a wall held in place
// until it breaks. Mass and inertia of piece i come from its mesh at the body's density.
std::vector<BodyDef> fracturePieces(const RigidBody& body, const FracturePattern& pattern, const Material& material);

}  // namespace rbsim
