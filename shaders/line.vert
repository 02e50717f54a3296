#version 450
// Axes, force shafts and outlines: coloured world-space line segments.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aColor;  // linear RGB + alpha

uniform mat4 uViewProj;

out vec4 vColor;

void main() {
  // Flat colours: encode to sRGB once per vertex rather than per pixel.
  vColor = vec4(pow(aColor.rgb, vec3(1.0 / 2.2)), aColor.a);
  gl_Position = uViewProj * vec4(aPosition, 1.0);
}
