#version 450
// One directional light (Lambert + a little Blinn-Phong) plus hemisphere ambient (brighter from
// above), so the three visible faces of a box always get three different shades.
uniform vec3 uEye;
uniform vec3 uLightDir;    // unit vector towards the light
uniform vec3 uLightColor;
uniform vec3 uSkyAmbient;
uniform vec3 uGroundAmbient;
uniform int uWireframe;    // 1: draw triangle edges over the surface
uniform vec3 uWireColor;
uniform float uAlpha;

in vec3 vWorld;
in vec3 vNormal;
in vec3 vColor;
in vec3 vBarycentric;
out vec4 fragColor;

void main() {
  vec3 n = normalize(vNormal);
  vec3 toEye = normalize(uEye - vWorld);
  // Two-sided: a mesh file with inward winding still shades as seen from outside.
  if (dot(n, toEye) < 0.0) n = -n;
  float diffuse = max(dot(n, uLightDir), 0.0);
  float specular = pow(max(dot(n, normalize(uLightDir + toEye)), 0.0), 40.0);
  vec3 ambient = mix(uGroundAmbient, uSkyAmbient, 0.5 + 0.5 * n.y);
  vec3 color = vColor * (ambient + diffuse * uLightColor) + 0.12 * specular * uLightColor;
  if (uWireframe != 0) {
    vec3 edgeDist = vBarycentric / max(fwidth(vBarycentric), vec3(1e-6));  // in pixels
    float edge = 1.0 - smoothstep(0.4, 1.4, min(min(edgeDist.x, edgeDist.y), edgeDist.z));
    color = mix(color, uWireColor, 0.85 * edge);
  }
  fragColor = vec4(pow(color, vec3(1.0 / 2.2)), uAlpha);
}
