#version 450
// Debug segments (AABBs, contact normals) as screen-space quads. Each of a quad's 4 vertices
// carries the whole segment and its corner number. The quad is the segment widened by uHalfWidth
// pixels plus half a pixel for the antialiased border, and lengthened by uHalfWidth at both ends
// so the edges of an AABB meet in closed corners.
layout(location = 0) in vec4 aStart;  // xyz; w: corner 0..3 (bit 0: at the end, bit 1: side)
layout(location = 1) in vec4 aEnd;    // xyz
layout(location = 2) in vec3 aColor;  // linear RGB

uniform mat4 uViewProj;
uniform vec3 uEye;
uniform float uPull;       // fraction of the distance to the eye (see below)
uniform vec2 uViewport;    // [px]
uniform float uHalfWidth;  // [px]

out vec4 vColor;
noperspective out float vAcross;  // [px] from the centre line

void main() {
  int corner = int(aStart.w);
  // Moved a little towards the eye along the view ray: the same place on screen, slightly nearer,
  // so a segment lying on a surface (an AABB on the ground) is not stippled by the depth test.
  vec4 ca = uViewProj * vec4(mix(aStart.xyz, uEye, uPull), 1.0);
  vec4 cb = uViewProj * vec4(mix(aEnd.xyz, uEye, uPull), 1.0);
  // Clip against the near plane (z >= -w) here: the quad's sides need both ends' screen
  // positions, which do not exist behind the eye.
  float da = ca.z + ca.w;
  float db = cb.z + cb.w;
  if (da < 0.0 && db < 0.0) {
    gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // all four corners equal and outside: no pixels
    vColor = vec4(0.0);
    vAcross = 0.0;
    return;
  }
  if (da < 0.0) ca = mix(ca, cb, da / (da - db));
  if (db < 0.0) cb = mix(cb, ca, db / (db - da));
  vec2 halfViewport = 0.5 * uViewport;
  vec2 sa = ca.xy / ca.w * halfViewport;
  vec2 sb = cb.xy / cb.w * halfViewport;
  vec2 along = sb - sa;
  float length = length(along);
  along = length > 1e-4 ? along / length : vec2(1.0, 0.0);  // a dot: any direction will do
  vec2 across = vec2(-along.y, along.x);
  bool atB = (corner & 1) != 0;
  float side = (corner & 2) != 0 ? 1.0 : -1.0;
  float extent = uHalfWidth + 0.5;
  vec2 offsetPx = side * extent * across + (atB ? 1.0 : -1.0) * uHalfWidth * along;
  vec4 c = atB ? cb : ca;
  gl_Position = c + vec4(offsetPx / halfViewport * c.w, 0.0, 0.0);
  vColor = vec4(pow(aColor, vec3(1.0 / 2.2)), 1.0);  // flat colours: encode per vertex
  vAcross = side * extent;
}
