#version 450
// The bodies' lighting, shared by mesh.vert and mesh_instanced.vert: a vertex shader object of
// its own, linked into both programs (ShaderProgram's vertexLibrary). One directional light
// (Lambert + a little Blinn-Phong) plus hemisphere ambient (brighter from above), so the three
// visible faces of a box always get three different shades; returns the display (sRGB) colour.
uniform vec3 uEye;
uniform vec3 uLightDir;    // unit vector towards the light
uniform vec3 uLightColor;
uniform vec3 uSkyAmbient;
uniform vec3 uGroundAmbient;

vec3 litColor(vec3 world, vec3 normal, vec3 albedo) {
  vec3 n = normalize(normal);
  vec3 toEye = normalize(uEye - world);
  // Two-sided: a mesh file with inward winding still shades as seen from outside. On a flat face
  // the side the eye is on is the same at every point, so deciding it per vertex is exact.
  if (dot(n, toEye) < 0.0) n = -n;
  float diffuse = max(dot(n, uLightDir), 0.0);
  float specular = pow(max(dot(n, normalize(uLightDir + toEye)), 0.0), 40.0);
  vec3 ambient = mix(uGroundAmbient, uSkyAmbient, 0.5 + 0.5 * n.y);
  vec3 color = albedo * (ambient + diffuse * uLightColor) + 0.12 * specular * uLightColor;
  return pow(color, vec3(1.0 / 2.2));
}
