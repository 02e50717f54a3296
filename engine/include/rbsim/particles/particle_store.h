#pragma once
// The particles of one system as a structure of arrays: each attribute in its own contiguous
// array, so the step streams only the attributes it uses (position, velocity, inverse mass, age,
// lifetime) and never the ones only drawing reads (colour, size). Storage is made once for the
// system's capacity; live particles are [0, count), and a dead one is replaced by the last live
// one, so emission and death never allocate.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "rbsim/math/types.h"

namespace rbsim {

class ParticleStore {
 public:
  explicit ParticleStore(std::size_t capacity);

  std::size_t count() const { return count_; }
  std::size_t capacity() const { return capacity_; }

  // Index of a new particle with every attribute zero (inverse mass 1), or capacity() when full.
  std::size_t add();
  // Moves the last live particle into slot i; the order of particles is not kept.
  void remove(std::size_t i);
  // Removes every particle with age >= lifetime, in one pass.
  void removeExpired();
  // Sets the number of live particles (<= capacity(), else std::invalid_argument), leaving the
  // attributes as they are: for restoring a recorded state (app/record), whose caller writes them.
  void setCount(std::size_t count);

  // Attributes, indexed [0, count()).
  std::vector<Vec3> position;        // x [m]
  std::vector<Vec3> velocity;        // v [m/s]
  std::vector<double> inverseMass;   // 1 / m [1/kg]; 0 holds the particle in place (pinned)
  std::vector<double> age;           // time since birth [s]
  std::vector<double> lifetime;      // dies when age >= lifetime [s]; kImmortal never does
  std::vector<Eigen::Vector3f> color;  // linear RGB at birth [1]
  std::vector<float> size;           // drawn diameter [m]

  double mass(std::size_t i) const { return inverseMass[i] > 0.0 ? 1.0 / inverseMass[i] : 0.0; }  // [kg]
  Vec3 momentum() const;             // sum m v over movable particles [kg m/s]

 private:
  std::size_t count_ = 0;
  std::size_t capacity_;
};

}  // namespace rbsim
