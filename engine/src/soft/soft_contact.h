#pragma once
// Soft bodies against rigid bodies, both ways: a node found inside a body's solid is put
// back on its surface, and the pair exchanges the impulse of seed 000's collision response for
// a point mass against a rigid body (K = 1/m_node + K_body): restitution on the approach, Coulomb
// friction up to mu j_n. The body receives -j at the node, so momentum is exchanged exactly.
#include <vector>

#include "rbsim/body/rigid_body.h"
#include "rbsim/body/material.h"
#include "rbsim/collision/body_solid.h"
#include "rbsim/soft/soft_body.h"

namespace rbsim {

// Returns the number of nodes in contact. `shapes` and `materials` are per rigid body.
int collideSoftWithRigid(SoftBody& soft, std::vector<RigidBody>& bodies, const std::vector<BodySolid>& shapes,
                         const std::vector<Material>& materials, const Material& softMaterial);

}  // namespace rbsim
