#version 450
// Ground plane with a procedural grid: major lines every metre, faint minor lines between. Lines
// are measured in screen pixels (fwidth) so they stay crisp and one width at any distance, fade
// out where cells shrink to a few pixels (no moire), and fade with distance into the horizon.
// Colours are display (sRGB) values mixed directly: there is no lighting here, and skipping a
// per-pixel gamma encode keeps this screen-filling pass cheap on llvmpipe.
uniform vec3 uEye;
uniform vec3 uGroundColor;
uniform vec3 uMinorColor;
uniform vec3 uMajorColor;
uniform vec3 uHorizon;
uniform float uMinorSpacing;  // [m]
uniform float uMajorSpacing;  // [m]
uniform float uLineWidth;     // [px]
uniform float uFadeStart;     // [m] grid lines start fading
uniform float uFadeEnd;       // [m] everything has become horizon colour

in vec3 vWorld;
out vec4 fragColor;

// Coverage in [0, 1] of grid lines every `spacing` metres. `perMetre` is fwidth(world xz):
// metres per pixel, shared by every grid level.
float gridLines(vec2 p, vec2 perMetre, float spacing, float widthPx) {
  vec2 perPixel = perMetre / spacing;  // cells per pixel
  vec2 distPx = abs(fract(p / spacing - 0.5) - 0.5) / perPixel;
  vec2 cover = clamp(0.5 * widthPx + 0.5 - distPx, 0.0, 1.0);
  cover *= clamp(2.0 - 14.0 * perPixel, 0.0, 1.0);  // fades out as cells shrink to 14..7 px
  return max(cover.x, cover.y);
}

void main() {
  vec2 perMetre = max(fwidth(vWorld.xz), vec2(1e-6));
  float dist = length(vWorld - uEye);
  float lineFade = 1.0 - smoothstep(uFadeStart, mix(uFadeStart, uFadeEnd, 0.6), dist);
  vec3 color = uGroundColor;
  color = mix(color, uMinorColor, lineFade * gridLines(vWorld.xz, perMetre, uMinorSpacing, uLineWidth));
  color = mix(color, uMajorColor, lineFade * gridLines(vWorld.xz, perMetre, uMajorSpacing, 1.5 * uLineWidth));
  // World axes through the origin, x reddish (line z = 0) and z bluish (line x = 0), as in most
  // 3D tools; a bit wider than the major lines.
  vec2 axisCover = clamp(uLineWidth + 0.5 - abs(vWorld.zx) / perMetre.yx, 0.0, 1.0) * lineFade;
  color = mix(color, vec3(0.70, 0.30, 0.28), axisCover.x);
  color = mix(color, vec3(0.30, 0.42, 0.72), axisCover.y);
  color = mix(color, uHorizon, smoothstep(0.3 * uFadeEnd, uFadeEnd, dist));
  fragColor = vec4(color, 1.0);
}
