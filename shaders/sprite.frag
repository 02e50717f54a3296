#version 450
// A soft round blob: opacity falls off as a Gaussian of the distance from the centre and reaches
// zero at the square's inscribed circle, so neighbouring sprites blend into a smooth cloud.
in vec2 vLocal;
flat in vec4 vColor;  // display (sRGB) colour + opacity
out vec4 fragColor;

// exp(-kSharpness r^2): the edge of the disc keeps e^-3 = 5 % of the centre's opacity before the
// (1 - r^2) factor takes it to zero.
const float kSharpness = 3.0;

void main() {
  float r2 = dot(vLocal, vLocal);
  if (r2 >= 1.0) discard;
  float falloff = exp(-kSharpness * r2) * (1.0 - r2);
  fragColor = vec4(vColor.rgb, vColor.a * falloff);
}
