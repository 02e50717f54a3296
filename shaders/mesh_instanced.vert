#version 450
// Bodies drawn as instances of a shared mesh: body-space triangles (flat normals, 3 vertices per
// triangle) placed by each body's rotation R and centre of mass x, p' = R p + x, the transform
// the engine computed. Feeds mesh.frag like mesh.vert does.
layout(location = 0) in vec3 aPosition;  // body frame
layout(location = 1) in vec3 aNormal;    // body frame
layout(location = 3) in vec3 iPosition;  // x, world frame
layout(location = 4) in vec3 iAxisX;     // columns of R
layout(location = 5) in vec3 iAxisY;
layout(location = 6) in vec3 iAxisZ;
layout(location = 7) in vec3 iColor;     // linear RGB

uniform mat4 uViewProj;

out vec3 vWorld;
out vec3 vNormal;
out vec3 vColor;
out vec3 vBarycentric;

void main() {
  mat3 R = mat3(iAxisX, iAxisY, iAxisZ);
  vWorld = R * aPosition + iPosition;
  vNormal = R * aNormal;  // R is a rotation: normals turn like positions
  vColor = iColor;
  int corner = gl_VertexID % 3;  // each mesh buffer starts at vertex 0 with whole triangles
  vBarycentric = vec3(corner == 0, corner == 1, corner == 2);
  gl_Position = uViewProj * vec4(vWorld, 1.0);
}
