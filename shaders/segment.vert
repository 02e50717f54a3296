#version 450
// Segmentation pass (app/render/segmentation_pass.h): world-space triangles, each vertex carrying
// the index of the body it belongs to. The position is transformed as mesh.vert does, so both
// passes cover the same pixels.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in int aSegment;

uniform mat4 uViewProj;

flat out int vSegment;

void main() {
  vSegment = aSegment;
  gl_Position = uViewProj * vec4(aPosition, 1.0);
}
