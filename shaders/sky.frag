#version 450
// Background: a gradient over the view ray's elevation, so the sky's horizon lines up with the
// ground plane's vanishing line whatever the camera does. Colours are already display (sRGB)
// values: a gradient needs no lighting maths, and skipping the encode keeps this pass cheap.
uniform vec3 uZenith;
uniform vec3 uHorizon;
uniform vec3 uNadir;  // below the horizon (seen only when the ground is off)

in vec3 vRay;
out vec4 fragColor;

void main() {
  float elevation = normalize(vRay).y;
  float up = clamp(elevation, 0.0, 1.0);
  vec3 color = elevation >= 0.0 ? mix(uHorizon, uZenith, up * (2.0 - up))
                                : mix(uHorizon, uNadir, clamp(-4.0 * elevation, 0.0, 1.0));
  fragColor = vec4(color, 1.0);
}
