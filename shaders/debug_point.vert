#version 450
// Debug points (contact points) as screen-space squares, half a pixel larger than the disc so its
// antialiased border fits; the fragment shader cuts the disc. Each of a square's 4 vertices
// carries the point and its corner number.
layout(location = 0) in vec4 aPosition;  // xyz; w: corner 0..3 (bit 0: +x side, bit 1: +y side)
layout(location = 1) in vec4 aSize;      // x: disc diameter [px]
layout(location = 2) in vec3 aColor;     // linear RGB

uniform mat4 uViewProj;
uniform vec2 uViewport;  // [px]

flat out vec3 vColor;
flat out float vRadius;   // [px]
noperspective out vec2 vLocal;  // [px] from the centre

void main() {
  int corner = int(aPosition.w);
  vec4 c = uViewProj * vec4(aPosition.xyz, 1.0);
  vRadius = 0.5 * aSize.x;
  vColor = pow(aColor, vec3(1.0 / 2.2));
  vLocal = vec2((corner & 1) != 0 ? 1.0 : -1.0, (corner & 2) != 0 ? 1.0 : -1.0) * (vRadius + 0.5);
  // Behind the eye the quad would flip through infinity; the whole point is dropped instead
  // (the clipper discards primitives entirely outside z in [-w, w]).
  if (c.w <= 0.0) c = vec4(0.0, 0.0, 2.0, 1.0);
  // Screen y grows downwards in images but upwards in NDC; the disc is symmetric, so the sign of
  // the offset does not matter.
  gl_Position = c + vec4(vLocal / (0.5 * uViewport) * c.w, 0.0, 0.0);
}
