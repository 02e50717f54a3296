#version 450
// Planar shadow of an instanced body (see shadow.vert): p' = R p + x, then slid along the light
// direction onto the ground y = 0.
layout(location = 0) in vec3 aPosition;  // body frame
layout(location = 3) in vec3 iPosition;
layout(location = 4) in vec3 iAxisX;
layout(location = 5) in vec3 iAxisY;
layout(location = 6) in vec3 iAxisZ;

uniform mat4 uViewProj;
uniform vec3 uLightDir;  // unit vector towards the light, y > 0

void main() {
  vec3 p = mat3(iAxisX, iAxisY, iAxisZ) * aPosition + iPosition;
  p.xz -= uLightDir.xz * (p.y / uLightDir.y);
  p.y = 0.0;
  gl_Position = uViewProj * vec4(p, 1.0);
}
