#version 450
// Bodies and arrow heads: world-space triangles (the engine already applied p' = R p + x), three
// vertices per triangle, each carrying its triangle's normal for flat shading (or, on a smooth
// surface such as a cloth, its own averaged normal: Gouraud shading there). Lit here, per vertex,
// by lighting.glsl (linked as a second vertex shader object); mesh.frag only writes the colour.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColor;

uniform mat4 uViewProj;

// lighting.glsl: display colour of a surface point with this normal and linear-RGB albedo.
vec3 litColor(vec3 world, vec3 normal, vec3 albedo);

out vec3 vShaded;       // display (sRGB) colour
out vec3 vBarycentric;  // for the wireframe: distance to each triangle edge

void main() {
  vShaded = litColor(aPosition, aNormal, aColor);
  int corner = gl_VertexID % 3;  // vertices are not shared, so the corner follows from the index
  vBarycentric = vec3(corner == 0, corner == 1, corner == 2);
  gl_Position = uViewProj * vec4(aPosition, 1.0);
}
