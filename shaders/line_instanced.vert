#version 450
// Outlines (feature edges) of instanced bodies: body-space segments placed by each body's R and
// x, in a quarter of the body's colour as scene_geometry.cpp gives the other bodies. Feeds
// line.frag.
layout(location = 0) in vec3 aPosition;  // body frame
layout(location = 3) in vec3 iPosition;
layout(location = 4) in vec3 iAxisX;
layout(location = 5) in vec3 iAxisY;
layout(location = 6) in vec3 iAxisZ;
layout(location = 7) in vec3 iColor;     // the body's linear RGB

uniform mat4 uViewProj;
uniform float uEdgeShade;  // outline colour = uEdgeShade * body colour

out vec4 vColor;

void main() {
  vColor = vec4(pow(uEdgeShade * iColor, vec3(1.0 / 2.2)), 1.0);
  vec3 p = mat3(iAxisX, iAxisY, iAxisZ) * aPosition + iPosition;
  gl_Position = uViewProj * vec4(p, 1.0);
}
