#include "rbsim/scene/json_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <Eigen/SVD>

#include "rbsim/math/types.h"

#include "rbsim/body/rigid_body.h"
#include "rbsim/io/input_error.h"
#include "rbsim/math/rotation.h"

namespace rbsim {

namespace {

const char* typeName(const nlohmann::json& v) {
  return v.is_number() ? "a number" : v.type_name();
}

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The rotation nearest to M in the Frobenius norm (the polar factor U V^T of M = U S V^T), for a
// matrix of positive determinant.
Mat3 nearestRotation(const Mat3& M) {
  const Eigen::JacobiSVD<Mat3> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

}  // namespace

std::string nearestKey(const std::string& key, const std::vector<std::string>& known) {
  std::string best;
  std::size_t bestDistance = std::max<std::size_t>(2, key.size() / 3) + 1;
  for (const std::string& candidate : known) {
    const std::size_t d = editDistance(key, candidate);
    if (d < bestDistance) {
      bestDistance = d;
      best = candidate;
    }
  }
  return best;
}

JsonObject::JsonObject(const nlohmann::json& value, std::string file, std::string path, KeyNames allowed)
    : value_(value), file_(std::move(file)), path_(std::move(path)) {
  if (!value_.is_object()) {
    throw InputError(file_, path_.empty() ? "(top level)" : path_,
                     std::string("expected an object, got ") + typeName(value_));
  }
  std::vector<std::string> known;
  for (std::size_t i = 0; i < allowed.size(); ++i) known.emplace_back(allowed[i]);
  for (const auto& item : value_.items()) {
    if (std::find(known.begin(), known.end(), item.key()) != known.end()) continue;
    const std::string near = nearestKey(item.key(), known);
    std::string problem = "unknown key";
    if (!near.empty()) problem += " (did you mean \"" + near + "\"?)";
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    throw InputError(file_, pathOf(item.key().c_str()), problem + "; known keys here: " + list);
  }
}

std::string JsonObject::pathOf(const char* key) const {
  return path_.empty() ? std::string(key) : path_ + "." + key;
}

void JsonObject::fail(const char* key, const std::string& problem) const {
  throw InputError(file_, pathOf(key), problem);
}

double JsonObject::number(const char* key, double fallback) const {
  if (!has(key)) return fallback;
  const nlohmann::json& v = value_.at(key);
  if (!v.is_number()) fail(key, std::string("expected a number, got ") + typeName(v));
  const double d = v.get<double>();
  if (!std::isfinite(d)) fail(key, "expected a finite number");
  return d;
}

double JsonObject::requiredNumber(const char* key) const {
  if (!has(key)) fail(key, "missing; a number is required");
  return number(key, 0.0);
}

double JsonObject::positiveNumber(const char* key, double fallback) const {
  const double d = number(key, fallback);
  if (!(d > 0.0)) fail(key, "expected a positive number, got " + formatNumber(d));
  return d;
}

std::optional<double> JsonObject::optionalPositive(const char* key) const {
  if (!has(key)) return std::nullopt;
  return positiveNumber(key, 0.0);
}

int JsonObject::positiveInt(const char* key, int fallback) const {
  if (!has(key)) return fallback;
  const nlohmann::json& v = value_.at(key);
  if (v.is_number_float()) {
    // nlohmann-json reads a whole number past 64 bits as a double: it is too large, not a
    // fraction (issue 56: substeps = 10**30 was "expected an integer, got a number").
    const double d = v.get<double>();
    if (std::isfinite(d) && d == std::floor(d) && d > static_cast<double>(kMaxCount)) {
      fail(key, "expected a positive integer, got " + formatNumber(d) + " (the limit is " + std::to_string(kMaxCount) + ")");
    }
    fail(key, "expected an integer, got " + formatNumber(d));
  }
  if (!v.is_number_integer()) fail(key, std::string("expected an integer, got ") + typeName(v));
  // nlohmann-json keeps every integer >= 0 as unsigned, and one above 2^63 - 1 would read as a
  // negative long long: compare each as the number it is.
  const bool positive = v.is_number_unsigned() ? v.get<std::uint64_t>() > 0 : v.get<long long>() > 0;
  const bool tooLarge = v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(kMaxCount);
  if (!positive || tooLarge) {
    fail(key, "expected a positive integer, got " + v.dump() + (tooLarge ? " (the limit is " + std::to_string(kMaxCount) + ")" : ""));
  }
  return static_cast<int>(v.get<long long>());
}

void JsonObject::allowOnly(KeyNames keys, const std::string& owner) const {
  for (const auto& item : value_.items()) {
    bool known = false;
    for (std::size_t i = 0; i < keys.size() && !known; ++i) known = item.key() == keys[i];
    if (known) continue;
    std::string list;
    for (std::size_t i = 0; i < keys.size(); ++i) list += (list.empty() ? "" : ", ") + std::string(keys[i]);
    fail(item.key().c_str(), "does not apply to " + owner + " (its keys: " + list + ")");
  }
}

bool JsonObject::boolean(const char* key, bool fallback) const {
  if (!has(key)) return fallback;
  const nlohmann::json& v = value_.at(key);
  if (!v.is_boolean()) fail(key, std::string("expected true or false, got ") + typeName(v));
  return v.get<bool>();
}

std::string JsonObject::string(const char* key, const std::string& fallback) const {
  if (!has(key)) return fallback;
  const nlohmann::json& v = value_.at(key);
  if (!v.is_string()) fail(key, std::string("expected a string, got ") + typeName(v));
  return v.get<std::string>();
}

std::string JsonObject::requiredString(const char* key) const {
  if (!has(key)) fail(key, "missing; a string is required");
  return string(key, "");
}

std::vector<double> JsonObject::numbers(const char* key, std::size_t count) const {
  const nlohmann::json& v = value_.at(key);
  if (!v.is_array() || v.size() != count) {
    fail(key, "expected an array of " + std::to_string(count) + " numbers");
  }
  std::vector<double> out;
  for (std::size_t i = 0; i < count; ++i) {
    if (!v[i].is_number() || !std::isfinite(v[i].get<double>())) {
      fail(key, "element " + std::to_string(i) + " is not a finite number");
    }
    out.push_back(v[i].get<double>());
  }
  return out;
}

Vec3 JsonObject::vec3(const char* key, const Vec3& fallback) const {
  if (!has(key)) return fallback;
  const std::vector<double> n = numbers(key, 3);
  return Vec3(n[0], n[1], n[2]);
}

std::optional<Vec3> JsonObject::optionalVec3(const char* key) const {
  if (!has(key)) return std::nullopt;
  return vec3(key, Vec3::Zero());
}

Vec3 JsonObject::boundedVec3(const char* key, const Vec3& fallback, double limit, const char* unit,
                              const char* what) const {
  const Vec3 v = vec3(key, fallback);
  if (!(v.stableNorm() <= limit)) {
    fail(key, "its length " + formatPastLimit(v.stableNorm(), limit) + " " + unit + " exceeds " + formatNumber(limit) + " " + unit +
                  " (" + what + "); expected a smaller value");
  }
  return v;
}

Vec3 JsonObject::positiveVec3(const char* key) const {
  if (!has(key)) fail(key, "missing; an array of 3 positive numbers is required");
  const Vec3 v = vec3(key, Vec3::Zero());
  if (!(v.minCoeff() > 0.0)) fail(key, "every component must be positive");
  return v;
}

std::optional<Quat> JsonObject::optionalOrientation(const char* key) const {
  if (!has(key)) return std::nullopt;
  const JsonObject o = object(key, kOrientationKeys);
  // Normalising is the scene's choice ("normalize": true), never rbsim's: a quaternion or matrix
  // typed with a few digits is otherwise taken only when it is a rotation to within 1e-6.
  const bool normalize = o.boolean("normalize", false);
  if (o.value_.size() != (o.has("normalize") ? 2u : 1u)) {
    fail(key, "give exactly one of quaternion, matrix, axis_angle_deg, euler_zyx_deg");
  }
  if (o.has("quaternion")) {
    const std::vector<double> n = o.numbers("quaternion", 4);
    const Quat q(n[0], n[1], n[2], n[3]);
    if (normalize) {
      // Scaled by its largest component first: the norm of [1e200, 0, 0, 0] overflows, its
      // direction does not.
      const double largest = q.coeffs().cwiseAbs().maxCoeff();
      if (!(largest > 0.0)) o.fail("quaternion", "the zero quaternion has no direction to normalise");
      return Quat(q.coeffs() / largest).normalized();
    }
    if (!(std::abs(q.norm() - 1.0) <= kRotationTolerance)) {
      o.fail("quaternion", "expected a unit quaternion [w, x, y, z], its norm is " + formatNumber(q.norm()) +
                               " (add \"normalize\": true to have it normalised)");
    }
    return q.normalized();  // within tolerance: removes only the rounding of typed digits
  }
  if (o.has("matrix")) {
    const nlohmann::json& rows = o.value_.at("matrix");
    if (!rows.is_array() || rows.size() != 3) o.fail("matrix", "expected 3 rows of 3 numbers");
    Mat3 R;
    for (int r = 0; r < 3; ++r) {
      if (!rows[r].is_array() || rows[r].size() != 3) o.fail("matrix", "expected 3 rows of 3 numbers");
      for (int c = 0; c < 3; ++c) {
        if (!rows[r][c].is_number()) o.fail("matrix", "entries must be numbers");
        R(r, c) = rows[r][c].get<double>();
      }
    }
    if (!R.allFinite()) o.fail("matrix", "entries must be finite");
    // Scaled by its largest entry before normalising: the polar factor does not change with a
    // positive scale, and R^T R of entries near 1e200 would overflow.
    if (normalize && R.cwiseAbs().maxCoeff() > 0.0) R /= R.cwiseAbs().maxCoeff();
    if (normalize && R.determinant() > 0.0) R = nearestRotation(R);
    // Written as "not within": with entries near 1e200 R^T R overflows, the error is NaN and a
    // plain "greater than" test would pass the matrix.
    if (!(orthonormalityError(R) <= kRotationTolerance) || !(R.determinant() > 0.0)) {
      o.fail("matrix", "expected a rotation matrix (orthonormal, determinant +1); ||R^T R - I|| = " +
                           formatNumber(orthonormalityError(R)) + ", det = " + formatNumber(R.determinant()) +
                           (normalize ? " (no rotation is near a matrix of determinant <= 0)"
                                      : " (add \"normalize\": true for the nearest rotation)"));
    }
    return Quat(R).normalized();
  }
  if (o.has("euler_zyx_deg")) {
    // Yaw about z, pitch about the new y, roll about the newest x (math/rotation.h), degrees.
    const std::vector<double> n = o.numbers("euler_zyx_deg", 3);
    Vec3 radians;
    for (int i = 0; i < 3; ++i) radians[i] = std::fmod(n[static_cast<std::size_t>(i)], 360.0) * kPi / 180.0;
    return quatFromEulerZyx(radians);
  }
  if (!o.has("axis_angle_deg")) fail(key, "give exactly one of quaternion, matrix, axis_angle_deg, euler_zyx_deg");
  const std::vector<double> n = o.numbers("axis_angle_deg", 4);
  const Vec3 axis(n[0], n[1], n[2]);
  if (!(axis.stableNorm() > 0.0)) o.fail("axis_angle_deg", "the axis must be non-zero");
  // fmod is exact: the same rotation, and 1e308 degrees no longer overflows in the conversion.
  return quatFromAxisAngle(axis.stableNormalized() * (std::fmod(n[3], 360.0) * kPi / 180.0));
}

JsonObject JsonObject::object(const char* key, KeyNames allowed) const {
  if (!has(key)) fail(key, "missing; an object is required");
  return JsonObject(value_.at(key), file_, pathOf(key), allowed);
}

std::vector<JsonObject> JsonObject::objectArray(const char* key, KeyNames allowed) const {
  std::vector<JsonObject> out;
  if (!has(key)) return out;
  const nlohmann::json& v = value_.at(key);
  if (!v.is_array()) fail(key, std::string("expected an array, got ") + typeName(v));
  for (std::size_t i = 0; i < v.size(); ++i) {
    out.emplace_back(v[i], file_, pathOf(key) + "[" + std::to_string(i) + "]", allowed);
  }
  return out;
}

}  // namespace rbsim
