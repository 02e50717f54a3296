#version 450
// Segmentation pass: the ground square of ground.vert, one code over all of it
// (kSegmentGround in app/render/segmentation_pass.h).
uniform int uSegment;
layout(location = 0) out int fragSegment;

void main() {
  fragSegment = uSegment;
}
