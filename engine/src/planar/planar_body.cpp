#include "rbsim/planar/planar_body.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

#include "rbsim/math/format_number.h"

namespace rbsim {

PlanarBody::PlanarBody(std::string name, std::vector<Vec2> polygon, double mass, const Material& material)
    : name_(std::move(name)), polygon_(std::move(polygon)), mass_(mass), material_(material) {
  if (polygon_.size() < 3) throw std::invalid_argument("planar body '" + name_ + "': expected at least 3 corners");
  if (!(mass > 0.0) || !std::isfinite(mass)) throw std::invalid_argument("planar body '" + name_ + "': expected mass > 0");
  // Area, centroid and second moment of a polygon from its triangles with the origin (the
  // shoelace sums): A = 1/2 sum c_i, C = sum c_i (p_i + p_j) / (6 A), J_O = sum c_i (p_i.p_i +
  // p_i.p_j + p_j.p_j) / 12 per unit density, c_i = p_i x p_j.
  double area = 0.0, second = 0.0;
  Vec2 centroid = Vec2::Zero();
  for (std::size_t i = 0; i < polygon_.size(); ++i) {
    const Vec2& p = polygon_[i];
    const Vec2& q = polygon_[(i + 1) % polygon_.size()];
    const double c = cross2(p, q);
    area += 0.5 * c;
    centroid += c * (p + q);
    second += c * (p.dot(p) + p.dot(q) + q.dot(q)) / 12.0;
  }
  if (!(area > 0.0) || !std::isfinite(area)) {
    throw std::invalid_argument("planar body '" + name_ + "': expected counter-clockwise corners enclosing a finite, positive "
                                "area; the area is " + formatNumber(area) + " m^2 (corners so large or so close that it overflows or underflows)");
  }
  centroid /= 6.0 * area;
  if (!centroid.allFinite()) throw std::invalid_argument("planar body '" + name_ + "': the centroid overflows (corners too far out)");
  for (Vec2& p : polygon_) p -= centroid;
  // Parallel axis theorem to the centroid, scaled from unit density to the mass.
  inertia_ = mass_ / area * (second - area * centroid.squaredNorm());
  if (!(inertia_ > 0.0) || !std::isfinite(inertia_) || !std::isfinite(1.0 / inertia_)) {
    throw std::invalid_argument("planar body '" + name_ + "': the inertia m J / A = " + formatNumber(inertia_) +
                                " kg m^2 (mass " + formatNumber(mass_) + " kg, area " + formatNumber(area) +
                                " m^2) is not a finite, positive number with a finite inverse");
  }
}

double PlanarBody::kineticEnergy() const {
  return 0.5 * state_.linearMomentum.squaredNorm() / mass_ + 0.5 * state_.angularMomentum * state_.angularMomentum / inertia_;
}

void PlanarBody::applyForceAtPoint(const Vec2& force, const Vec2& worldPoint) {
  force_ += force;
  torque_ += cross2(Vec2(worldPoint - state_.position), force);
}

void PlanarBody::step(double dt, const Vec2& gravity) {
  state_.linearMomentum += dt * (force_ + mass_ * gravity);
  state_.angularMomentum += dt * torque_;  // tau = L' (seed 002)
  state_.position += dt * velocity();
  state_.angle += dt * angularVelocity();  // theta' = omega
  force_ = Vec2::Zero();
  torque_ = 0.0;
}

void PlanarBody::applyImpulse(const Vec2& impulse, const Vec2& worldPoint) {
  state_.linearMomentum += impulse;
  state_.angularMomentum += cross2(Vec2(worldPoint - state_.position), impulse);
}

Mat2 planarImpulseFactor(double inverseMass, double inverseInertia, const Vec2& r) {
  const Vec2 perpendicular(-r.y(), r.x());
  return inverseMass * Mat2::Identity() + inverseInertia * perpendicular * perpendicular.transpose();
}

}  // namespace rbsim
