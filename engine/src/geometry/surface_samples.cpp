#include "geometry/surface_samples.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace rbsim {

double surfaceSampleEstimate(const Mesh& mesh, double spacing) {
  double count = double(mesh.vertices.size());
  if (!(spacing > 0.0)) return count;
  for (const Triangle& t : mesh.triangles) {
    double longest = 0.0;
    for (int e = 0; e < 3; ++e) {
      const double length = (mesh.vertices[t[(e + 1) % 3]] - mesh.vertices[t[e]]).norm();
      longest = std::max(longest, length);
      count += std::max(std::ceil(length / spacing) - 1.0, 0.0);
    }
    const double steps = std::ceil(longest / spacing);
    if (steps > 2.0) count += (steps - 1.0) * (steps - 2.0) / 2.0;
  }
  return count;
}

std::string surfaceSampleBudgetProblem(const Mesh& mesh, double spacing) {
  const double estimate = surfaceSampleEstimate(mesh, spacing);
  if (!(estimate > kMaxSurfaceSamples)) return "";  // NaN cannot arise: lengths are finite
  double area = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    area += 0.5 * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
  }
  std::ostringstream problem;
  problem << std::setprecision(3) << "spacing " << spacing << " m on mesh '" << mesh.name << "' (area " << area
          << " m^2) needs up to " << estimate << " surface samples (~" << std::fixed << std::setprecision(0)
          << estimate * sizeof(Vec3) / 1e6 << " MB); the limit is " << std::defaultfloat << std::setprecision(3)
          << kMaxSurfaceSamples << " samples";
  return problem.str();
}

std::vector<Vec3> surfaceSamples(const Mesh& mesh, double spacing) {
  const std::string overBudget = surfaceSampleBudgetProblem(mesh, spacing);
  if (!overBudget.empty()) throw std::invalid_argument("surfaceSamples: " + overBudget);
  std::vector<Vec3> samples = mesh.vertices;
  if (!(spacing > 0.0)) return samples;
  samples.reserve(static_cast<std::size_t>(surfaceSampleEstimate(mesh, spacing)));
  std::set<std::pair<std::uint32_t, std::uint32_t>> edgesDone;
  for (const Triangle& t : mesh.triangles) {
    const Vec3* v[3] = {&mesh.vertices[t[0]], &mesh.vertices[t[1]], &mesh.vertices[t[2]]};
    double longest = 0.0;
    for (int e = 0; e < 3; ++e) {
      const Vec3& a = *v[e];
      const Vec3& b = *v[(e + 1) % 3];
      const double length = (b - a).norm();
      longest = std::max(longest, length);
      if (!edgesDone.insert(std::minmax(t[e], t[(e + 1) % 3])).second) continue;
      // From the smaller index, so both triangles of an edge would place the same points.
      const bool forward = t[e] < t[(e + 1) % 3];
      const Vec3& from = forward ? a : b;
      const Vec3& to = forward ? b : a;
      const int parts = static_cast<int>(std::ceil(length / spacing));
      for (int s = 1; s < parts; ++s) samples.push_back(from + (to - from) * (double(s) / parts));
    }
    const int steps = static_cast<int>(std::ceil(longest / spacing));
    for (int i = 1; i < steps; ++i) {
      for (int j = 1; i + j < steps; ++j) {
        const double u = double(i) / steps, w = double(j) / steps;
        samples.push_back((1.0 - u - w) * *v[0] + u * *v[1] + w * *v[2]);
      }
    }
  }
  return samples;
}

}  // namespace rbsim
