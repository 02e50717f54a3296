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
flat out vec4 vColor;  // display (sRGB) colour + opacity

void main() {
  vec2 corner = vec2((gl_VertexID & 1) != 0 ? 1.0 : -1.0, (gl_VertexID & 2) != 0 ? 1.0 : -1.0);
  vLocal = corner;
  // Gamma-encoded once per sprite, not per pixel: the colour is flat across it, and the encode
  // per pixel was most of the particle demo's sprite pass on llvmpipe.
  vColor = vec4(pow(aColor.rgb, vec3(1.0 / 2.2)), aColor.a);
  vec3 world = aCentre + 0.5 * aSize * (corner.x * uRight + corner.y * uUp);
  gl_Position = uViewProj * vec4(world, 1.0);
}
