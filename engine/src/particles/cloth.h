#pragma once
// A rectangular cloth as particles joined by springs (seed 000's homework lists cloth among the
// particle systems): nu x nv nodes on a grid, structural springs to grid neighbours, shear springs
// along the diagonals, bend springs two nodes apart (Provot, "Deformation constraints in a
// mass-spring model", Graphics Interface 1995), and two triangles per grid cell for drawing.
#include <vector>

#include "rbsim/geometry/mesh.h"
#include "rbsim/particles/particle_def.h"
#include "rbsim/particles/particle_forces.h"
#include "rbsim/particles/particle_store.h"

namespace rbsim {

// Adds the cloth's particles (node (i, j) at index first + j nu + i, immortal, at rest), springs
// (rest lengths from the flat grid) and triangles (indices into the store). The store must have
// room for nu nv particles.
void buildCloth(const ClothDef& cloth, ParticleStore& store, std::vector<ParticleSpring>& springs,
                std::vector<Triangle>& triangles);

}  // namespace rbsim
