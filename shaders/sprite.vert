#version 450
// Particle sprites, instanced: each instance is one particle, each of its 4 vertices a corner of
// a square facing the camera (spanned by the camera's right and up axes), size in metres.
layout(location = 0) in vec3 aCentre;  // per instance: world position [m]
layout(location = 1) in float aSize;   // per instance: diameter [m]
layout(location = 2) in vec4 aColor;   // per instance: linear RGB + opacity

uniform mat4 uViewProj;
uniform vec3 uRight;  // unit, world frame
uniform vec3 uUp;     // unit, world frame

out vec2 vLocal;  // corner in [-1, 1]^2
flat out vec4 vColor;

void main() {
  vec2 corner = vec2((gl_VertexID & 1) != 0 ? 1.0 : -1.0, (gl_VertexID & 2) != 0 ? 1.0 : -1.0);
  vLocal = corner;
  vColor = aColor;
  vec3 world = aCentre + 0.5 * aSize * (corner.x * uRight + corner.y * uUp);
  gl_Position = uViewProj * vec4(world, 1.0);
}
