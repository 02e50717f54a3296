#version 450
// Bodies and arrow heads: world-space triangles (the engine already applied p' = R p + x), three
// vertices per triangle, each carrying its triangle's normal for flat shading (or, on a smooth
// surface such as a cloth, its own averaged normal, interpolated across the triangle).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColor;

uniform mat4 uViewProj;

out vec3 vWorld;
out vec3 vNormal;  // the same on all 3 corners of a flat face
out vec3 vColor;
out vec3 vBarycentric;  // for the wireframe: distance to each triangle edge

void main() {
  vWorld = aPosition;
  vNormal = aNormal;
  vColor = aColor;
  int corner = gl_VertexID % 3;  // vertices are not shared, so the corner follows from the index
  vBarycentric = vec3(corner == 0, corner == 1, corner == 2);
  gl_Position = uViewProj * vec4(aPosition, 1.0);
}
