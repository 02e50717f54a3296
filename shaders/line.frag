#version 450
uniform float uAlpha;  // < 1 for the faint "seen through the body" pass

in vec4 vColor;
out vec4 fragColor;

void main() { fragColor = vec4(vColor.rgb, vColor.a * uAlpha); }
