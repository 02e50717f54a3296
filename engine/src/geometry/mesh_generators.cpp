#include "rbsim/geometry/mesh_generators.h"

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/polygon_triangulation.h"

namespace rbsim {

namespace {

void require(bool ok, const std::string& shape, const std::string& what) {
  if (!ok) throw std::invalid_argument(shape + ": " + what);
}

// A point at polar angle `polar` from -y (0 = bottom pole) and azimuth `azimuth` about +y.
Vec3 fromBottomPole(double radius, double polar, double azimuth) {
  const double rho = radius * std::sin(polar);
  return {rho * std::cos(azimuth), -radius * std::cos(polar), rho * std::sin(azimuth)};
}

// Triangles of a band of quads between ring rows `lower` and `upper` (each `segments` vertices,
// wrapping around +y), row `upper` above `lower`; outward = away from the y axis when
// !towardsAxis.
void bandBetween(Mesh& m, std::uint32_t lower, std::uint32_t upper, int segments, bool towardsAxis) {
  for (int s = 0; s < segments; ++s) {
    const std::uint32_t next = (s + 1) % segments;
    const std::uint32_t a = lower + s, b = lower + next, c = upper + s, d = upper + next;
    if (towardsAxis) {
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({b, d, c});
    } else {
      m.triangles.push_back({a, c, b});
      m.triangles.push_back({b, c, d});
    }
  }
}

// Hemisphere from the bottom pole to y = 0 in `rings` bands; returns the first vertex of its rim
// row. Facing away from the centre unless `inward`.
std::uint32_t addHemisphere(Mesh& m, double radius, int segments, int rings, bool inward) {
  const std::uint32_t pole = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.emplace_back(0.0, -radius, 0.0);
  std::uint32_t previous = pole;
  for (int r = 1; r <= rings; ++r) {
    const std::uint32_t row = static_cast<std::uint32_t>(m.vertices.size());
    for (int s = 0; s < segments; ++s) {
      m.vertices.push_back(fromBottomPole(radius, 0.5 * kPi * r / rings, 2.0 * kPi * s / segments));
    }
    if (r == 1) {
      for (int s = 0; s < segments; ++s) {
        const std::uint32_t a = row + s, b = row + (s + 1) % segments;
        if (inward) {
          m.triangles.push_back({pole, b, a});
        } else {
          m.triangles.push_back({pole, a, b});
        }
      }
    } else {
      bandBetween(m, previous, row, segments, inward);
    }
    previous = row;
  }
  return previous;
}

}  // namespace

Mesh makeUvSphere(double radius, int segments, int rings) {
  require(radius > 0.0, "makeUvSphere", "radius is " + std::to_string(radius) + ", expected > 0");
  require(segments >= 3, "makeUvSphere", "segments is " + std::to_string(segments) + ", expected >= 3");
  require(rings >= 2, "makeUvSphere", "rings is " + std::to_string(rings) + ", expected >= 2");
  Mesh m;
  m.name = "uv sphere";
  const std::uint32_t bottom = 0;
  m.vertices.emplace_back(0.0, -radius, 0.0);
  std::uint32_t previous = bottom;
  for (int r = 1; r < rings; ++r) {
    const std::uint32_t row = static_cast<std::uint32_t>(m.vertices.size());
    for (int s = 0; s < segments; ++s) {
      m.vertices.push_back(fromBottomPole(radius, kPi * r / rings, 2.0 * kPi * s / segments));
    }
    if (r == 1) {
      for (int s = 0; s < segments; ++s) {
        m.triangles.push_back({bottom, row + s, row + static_cast<std::uint32_t>((s + 1) % segments)});
      }
    } else {
      bandBetween(m, previous, row, segments, false);
    }
    previous = row;
  }
  const std::uint32_t top = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.emplace_back(0.0, radius, 0.0);
  for (int s = 0; s < segments; ++s) {
    m.triangles.push_back({top, previous + static_cast<std::uint32_t>((s + 1) % segments), previous + s});
  }
  return m;
}

Mesh makeCapsule(double radius, double length, int segments, int rings) {
  require(radius > 0.0, "makeCapsule", "radius is " + std::to_string(radius) + ", expected > 0");
  require(length >= 0.0, "makeCapsule", "length is " + std::to_string(length) + ", expected >= 0");
  require(segments >= 3, "makeCapsule", "segments is " + std::to_string(segments) + ", expected >= 3");
  require(rings >= 2 && rings % 2 == 0, "makeCapsule", "rings is " + std::to_string(rings) + ", expected even, >= 2");
  Mesh m;
  m.name = "capsule";
  const double half = 0.5 * length;
  const std::uint32_t bottom = 0;
  m.vertices.emplace_back(0.0, -radius - half, 0.0);
  std::uint32_t previous = bottom;
  // The sphere's rings, the lower half moved down by half the length and the upper half up; the
  // equator ring is laid twice, once at each cap's rim, with the cylinder's band between them.
  for (int r = 1; r < rings; ++r) {
    std::vector<double> shifts{r < rings / 2 ? -half : half};
    if (r == rings / 2 && half > 0.0) shifts = {-half, half};
    for (const double shift : shifts) {
      const std::uint32_t row = static_cast<std::uint32_t>(m.vertices.size());
      for (int s = 0; s < segments; ++s) {
        m.vertices.push_back(fromBottomPole(radius, kPi * r / rings, 2.0 * kPi * s / segments) + Vec3(0.0, shift, 0.0));
      }
      if (r == 1 && row == 1) {
        for (int s = 0; s < segments; ++s) {
          m.triangles.push_back({bottom, row + s, row + static_cast<std::uint32_t>((s + 1) % segments)});
        }
      } else {
        bandBetween(m, previous, row, segments, false);
      }
      previous = row;
    }
  }
  const std::uint32_t top = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.emplace_back(0.0, radius + half, 0.0);
  for (int s = 0; s < segments; ++s) {
    m.triangles.push_back({top, previous + static_cast<std::uint32_t>((s + 1) % segments), previous + s});
  }
  return m;
}

Mesh makeRoundedBox(const Vec3& coreHalfExtents, double radius, int bandSegments) {
  require(radius > 0.0 && std::isfinite(radius), "makeRoundedBox", "radius is " + std::to_string(radius) + ", expected > 0");
  require(coreHalfExtents.allFinite() && coreHalfExtents.minCoeff() >= 0.0, "makeRoundedBox", "core half extents must be >= 0");
  require(bandSegments >= 1, "makeRoundedBox", "bandSegments is " + std::to_string(bandSegments) + ", expected >= 1");
  const Vec3& h = coreHalfExtents;
  // Grid coordinates along axis j on the outer box: h_j + r tan(theta) over the band, theta in
  // equal steps to 45 degrees (where the neighbouring face's band takes over), mirrored.
  std::array<std::vector<double>, 3> ticks;
  for (int j = 0; j < 3; ++j) {
    std::vector<double> upper;
    for (int i = 0; i < bandSegments; ++i) upper.push_back(h[j] + radius * std::tan(0.25 * kPi * i / bandSegments));
    upper.push_back(h[j] + radius);  // exactly the neighbouring face's plane (tan(pi/4) rounds below 1)
    for (auto it = upper.rbegin(); it != upper.rend(); ++it) ticks[j].push_back(-*it);
    for (double t : upper) {
      if (t > ticks[j].back()) ticks[j].push_back(t);  // a zero core extent shares its middle tick
    }
  }
  Mesh m;
  m.name = "rounded_box";
  std::map<std::array<double, 3>, std::uint32_t> index;  // the faces' shared seams, merged
  const auto vertex = [&](const Vec3& p) {
    const Vec3 core = p.cwiseMax(-h).cwiseMin(h);
    const Vec3 q = core + radius * (p - core).normalized();
    const auto [it, added] = index.try_emplace({q.x(), q.y(), q.z()}, static_cast<std::uint32_t>(m.vertices.size()));
    if (added) m.vertices.push_back(q);
    return it->second;
  };
  for (int k = 0; k < 3; ++k) {
    const int u = (k + 1) % 3, v = (k + 2) % 3;  // e_u x e_v = e_k
    for (const double side : {1.0, -1.0}) {
      for (std::size_t i = 0; i + 1 < ticks[u].size(); ++i) {
        for (std::size_t j = 0; j + 1 < ticks[v].size(); ++j) {
          std::array<std::uint32_t, 4> c;
          for (int corner = 0; corner < 4; ++corner) {
            Vec3 p;
            p[k] = side * (h[k] + radius);
            p[u] = ticks[u][i + ((corner == 1 || corner == 2) ? 1 : 0)];
            p[v] = ticks[v][j + (corner >= 2 ? 1 : 0)];
            c[static_cast<std::size_t>(corner)] = vertex(p);
          }
          // Counter-clockwise seen from outside: (u, v) turns about +e_k, so flip on the - side.
          if (side > 0.0) {
            m.triangles.push_back({c[0], c[1], c[2]});
            m.triangles.push_back({c[0], c[2], c[3]});
          } else {
            m.triangles.push_back({c[0], c[2], c[1]});
            m.triangles.push_back({c[0], c[3], c[2]});
          }
        }
      }
    }
  }
  return m;
}

Mesh makeTorus(double majorRadius, double minorRadius, int majorSegments, int minorSegments) {
  require(minorRadius > 0.0 && majorRadius > minorRadius, "makeTorus",
          "radii are " + std::to_string(majorRadius) + " and " + std::to_string(minorRadius) +
              " m, expected majorRadius > minorRadius > 0");
  require(majorSegments >= 3 && minorSegments >= 3, "makeTorus",
          "segments are " + std::to_string(majorSegments) + " and " + std::to_string(minorSegments) +
              ", expected >= 3 each");
  Mesh m;
  m.name = "torus";
  // The tube's rings start at its outer equator, so with an even count one runs along the inner
  // equator, R - r from the axis. As r nears R that ring closes on the axis: its triangles become
  // slivers thinner than rounding, and those of opposite sides meet (issue 37: r = 0.49999999,
  // R = 0.5 was refused as self-crossing). Where that ring would be nearer the axis than turning
  // the rings by half a step puts the innermost ones, they turn: those are then
  // R - r cos(pi / n) >= r (1 - cos(pi / n)) from it for any r < R, as with an odd count always.
  const double halfStep = kPi / minorSegments;
  const bool innerRing = minorSegments % 2 == 0;
  const double phase =
      innerRing && majorRadius - minorRadius < minorRadius * (1.0 - std::cos(halfStep)) ? halfStep : 0.0;
  for (int i = 0; i < majorSegments; ++i) {
    const double theta = 2.0 * kPi * i / majorSegments;
    for (int j = 0; j < minorSegments; ++j) {
      const double psi = phase + 2.0 * kPi * j / minorSegments;
      const double rho = majorRadius + minorRadius * std::cos(psi);
      m.vertices.emplace_back(rho * std::cos(theta), minorRadius * std::sin(psi), rho * std::sin(theta));
    }
  }
  const auto at = [&](int i, int j) {
    return static_cast<std::uint32_t>((i % majorSegments) * minorSegments + j % minorSegments);
  };
  for (int i = 0; i < majorSegments; ++i) {
    for (int j = 0; j < minorSegments; ++j) {
      // Increasing i turns about +y towards +z, increasing j climbs the tube: (c - a) x (b - a)
      // points away from the tube's centre circle.
      const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i, j + 1), d = at(i + 1, j + 1);
      m.triangles.push_back({a, c, b});
      m.triangles.push_back({b, c, d});
    }
  }
  return m;
}

Mesh makeBowl(double outerRadius, double wallThickness, int segments, int rings) {
  require(wallThickness > 0.0 && outerRadius > wallThickness, "makeBowl",
          "outerRadius " + std::to_string(outerRadius) + " m and wallThickness " +
              std::to_string(wallThickness) + " m, expected outerRadius > wallThickness > 0");
  require(segments >= 3, "makeBowl", "segments is " + std::to_string(segments) + ", expected >= 3");
  require(rings >= 1, "makeBowl", "rings is " + std::to_string(rings) + ", expected >= 1");
  Mesh m;
  m.name = "bowl";
  const std::uint32_t outerRim = addHemisphere(m, outerRadius, segments, rings, false);
  const std::uint32_t innerRim = addHemisphere(m, outerRadius - wallThickness, segments, rings, true);
  // The flat rim at y = 0 faces +y: from the outer row inward, then around.
  for (int s = 0; s < segments; ++s) {
    const std::uint32_t next = (s + 1) % segments;
    m.triangles.push_back({outerRim + s, innerRim + s, outerRim + next});
    m.triangles.push_back({outerRim + next, innerRim + s, innerRim + next});
  }
  return m;
}

Mesh makeExtrudedPolygon(const std::vector<Vec2>& outline, double depth) {
  require(outline.size() >= 3, "makeExtrudedPolygon",
          "the outline has " + std::to_string(outline.size()) + " corners, expected >= 3");
  require(depth > 0.0, "makeExtrudedPolygon", "depth is " + std::to_string(depth) + ", expected > 0");
  double twiceArea = 0.0;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Vec2& a = outline[i];
    const Vec2& b = outline[(i + 1) % outline.size()];
    twiceArea += a.x() * b.y() - a.y() * b.x();
  }
  require(twiceArea > 0.0, "makeExtrudedPolygon",
          "the outline's signed area is " + std::to_string(0.5 * twiceArea) +
              " m^2, expected > 0 (counter-clockwise corners)");
  Mesh m;
  m.name = "extruded polygon";
  const std::uint32_t n = static_cast<std::uint32_t>(outline.size());
  for (const Vec2& p : outline) m.vertices.emplace_back(p.x(), p.y(), -0.5 * depth);
  for (const Vec2& p : outline) m.vertices.emplace_back(p.x(), p.y(), 0.5 * depth);
  std::vector<std::uint32_t> top(n), bottom(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    top[i] = n + i;            // counter-clockwise seen from +z
    bottom[i] = n - 1 - i;     // reversed: counter-clockwise seen from -z
  }
  require(triangulatePolygon(m.vertices, top, m.triangles) &&
              triangulatePolygon(m.vertices, bottom, m.triangles),
          "makeExtrudedPolygon", "the outline is not a simple polygon (edges meet or it has no area)");
  for (std::uint32_t i = 0; i < n; ++i) {
    // The side over edge i -> j faces (edge direction) x z: outward for a counter-clockwise outline.
    const std::uint32_t j = (i + 1) % n;
    m.triangles.push_back({i, j, n + j});
    m.triangles.push_back({i, n + j, n + i});
  }
  return m;
}

Mesh makeLetterU(double width, double height, double stroke, double depth) {
  require(stroke > 0.0 && 2.0 * stroke < width && stroke < height, "makeLetterU",
          "stroke " + std::to_string(stroke) + " m for width " + std::to_string(width) +
              " m and height " + std::to_string(height) + " m, expected 0 < 2 stroke < width and stroke < height");
  const double x = 0.5 * width, y = 0.5 * height;
  Mesh m = makeExtrudedPolygon({{-x, -y}, {x, -y}, {x, y}, {x - stroke, y}, {x - stroke, -y + stroke},
                                {-x + stroke, -y + stroke}, {-x + stroke, y}, {-x, y}},
                               depth);
  m.name = "letter U";
  return m;
}

}  // namespace rbsim
