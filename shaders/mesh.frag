#version 450
// The colour lit per vertex (mesh.vert, mesh_instanced.vert), plus the optional wireframe. Per
// vertex, not per pixel: faces are flat, so only the specular term varies across one, and on
// llvmpipe the per-pixel lighting and gamma encode were a third of the 1000-body frame (the
// bodies pass went from 9.0 to 5.9 ms; the picture moved by 92 dB PSNR, under one level).
uniform int uWireframe;    // 1: draw triangle edges over the surface
uniform vec3 uWireColor;
uniform float uAlpha;

in vec3 vShaded;
in vec3 vBarycentric;
out vec4 fragColor;

void main() {
  vec3 color = vShaded;
  if (uWireframe != 0) {
    vec3 edgeDist = vBarycentric / max(fwidth(vBarycentric), vec3(1e-6));  // in pixels
    float edge = 1.0 - smoothstep(0.4, 1.4, min(min(edgeDist.x, edgeDist.y), edgeDist.z));
    color = mix(color, uWireColor, 0.85 * edge);
  }
  fragColor = vec4(color, uAlpha);
}
