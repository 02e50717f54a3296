#version 450
// A disc with an antialiased border and a thin dark rim, so a yellow contact point stays readable
// on a yellow or orange body as well as on the grey ground.
flat in vec3 vColor;
flat in float vRadius;   // [px]
noperspective in vec2 vLocal;  // [px] from the centre
out vec4 fragColor;

void main() {
  float r = length(vLocal);
  float coverage = clamp(vRadius + 0.5 - r, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  // The rim is at most a pixel wide, and at most a fifth of the radius on tiny dots.
  float rimWidth = min(1.0, 0.2 * vRadius);
  float rim = smoothstep(vRadius - rimWidth - 0.5, vRadius - rimWidth + 0.5, r);
  fragColor = vec4(mix(vColor, 0.2 * vColor, rim), coverage);
}
