#version 450
// A large square on y = 0 centred under the camera (4 vertices, triangle strip, no buffer).
uniform mat4 uViewProj;
uniform vec2 uCentre;    // xz
uniform float uHalfSize; // [m]

out vec3 vWorld;

void main() {
  vec2 corner = vec2((gl_VertexID & 1) != 0 ? 1.0 : -1.0, (gl_VertexID & 2) != 0 ? 1.0 : -1.0);
  vWorld = vec3(uCentre.x + corner.x * uHalfSize, 0.0, uCentre.y + corner.y * uHalfSize);
  gl_Position = uViewProj * vec4(vWorld, 1.0);
}
