#version 450
// Bodies drawn as instances of a shared mesh: body-space triangles (flat normals, 3 vertices per
// triangle) placed by each body's rotation R and centre of mass x, p' = R p + x, the transform
// the engine computed. Lit like mesh.vert (lighting.glsl); feeds mesh.frag.
layout(location = 0) in vec3 aPosition;  // body frame
layout(location = 1) in vec3 aNormal;    // body frame
layout(location = 3) in vec3 iPosition;  // x, world frame
layout(location = 4) in vec3 iAxisX;     // columns of R
layout(location = 5) in vec3 iAxisY;
layout(location = 6) in vec3 iAxisZ;
layout(location = 7) in vec3 iColor;     // linear RGB

uniform mat4 uViewProj;

// lighting.glsl: display colour of a surface point with this normal and linear-RGB albedo.
vec3 litColor(vec3 world, vec3 normal, vec3 albedo);

out vec3 vShaded;
out vec3 vBarycentric;

void main() {
  mat3 R = mat3(iAxisX, iAxisY, iAxisZ);
  vec3 world = R * aPosition + iPosition;
  vShaded = litColor(world, R * aNormal, iColor);  // R is a rotation: normals turn like positions
  int corner = gl_VertexID % 3;  // each mesh buffer starts at vertex 0 with whole triangles
  vBarycentric = vec3(corner == 0, corner == 1, corner == 2);
  gl_Position = uViewProj * vec4(world, 1.0);
}
