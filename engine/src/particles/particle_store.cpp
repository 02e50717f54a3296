#include "rbsim/particles/particle_store.h"

#include <stdexcept>
#include <string>

namespace rbsim {

ParticleStore::ParticleStore(std::size_t capacity)
    : position(capacity, Vec3::Zero()),
      velocity(capacity, Vec3::Zero()),
      inverseMass(capacity, 1.0),
      age(capacity, 0.0),
      lifetime(capacity, 0.0),
      color(capacity, Eigen::Vector3f::Ones()),
      size(capacity, 0.0f),
      capacity_(capacity) {}

void ParticleStore::setCount(std::size_t count) {
  if (count > capacity_) {
    throw std::invalid_argument("ParticleStore::setCount: " + std::to_string(count) + " particles, capacity " +
                                std::to_string(capacity_));
  }
  count_ = count;
}

std::size_t ParticleStore::add() {
  if (count_ == capacity_) return capacity_;
  const std::size_t i = count_++;
  position[i] = Vec3::Zero();
  velocity[i] = Vec3::Zero();
  inverseMass[i] = 1.0;
  age[i] = 0.0;
  lifetime[i] = 0.0;
  color[i] = Eigen::Vector3f::Ones();
  size[i] = 0.0f;
  return i;
}

void ParticleStore::remove(std::size_t i) {
  const std::size_t last = --count_;
  if (i == last) return;
  position[i] = position[last];
  velocity[i] = velocity[last];
  inverseMass[i] = inverseMass[last];
  age[i] = age[last];
  lifetime[i] = lifetime[last];
  color[i] = color[last];
  size[i] = size[last];
}

void ParticleStore::removeExpired() {
  std::size_t i = 0;
  while (i < count_) {
    if (age[i] >= lifetime[i]) {
      remove(i);  // the particle moved into i is tested next
    } else {
      ++i;
    }
  }
}

Vec3 ParticleStore::momentum() const {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < count_; ++i) {
    if (inverseMass[i] > 0.0) p += velocity[i] / inverseMass[i];
  }
  return p;
}

}  // namespace rbsim
