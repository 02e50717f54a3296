#version 450
// Planar shadow: each body vertex is slid along the light direction onto the ground y = 0.
// Cheap and exact for a flat ground, and it shows at a glance whether a body touches the floor.
layout(location = 0) in vec3 aPosition;

uniform mat4 uViewProj;
uniform vec3 uLightDir;  // unit vector towards the light, y > 0

void main() {
  vec3 p = aPosition;
  p.xz -= uLightDir.xz * (p.y / uLightDir.y);
  p.y = 0.0;
  gl_Position = uViewProj * vec4(p, 1.0);
}
