#version 450
// One triangle that covers the screen. Its corners carry the world-space view ray through them:
// far-plane points are an affine function of screen position (clip w is constant there), so the
// interpolated ray is exact and the fragment shader only normalises it.
uniform mat4 uInvViewProj;
uniform vec3 uEye;

out vec3 vRay;

void main() {
  vec2 corner = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  vec4 farPoint = uInvViewProj * vec4(corner, 1.0, 1.0);
  vRay = farPoint.xyz / farPoint.w - uEye;
  gl_Position = vec4(corner, 1.0, 1.0);  // on the far plane: drawn last, only where nothing is
}
