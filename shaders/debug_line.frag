#version 450
// Coverage of a line of width 2 uHalfWidth at this pixel, from its distance to the centre line.
uniform float uHalfWidth;  // [px]

in vec4 vColor;
noperspective in float vAcross;  // [px]
out vec4 fragColor;

void main() {
  float coverage = clamp(uHalfWidth + 0.5 - abs(vAcross), 0.0, 1.0);
  fragColor = vec4(vColor.rgb, vColor.a * coverage);
}
