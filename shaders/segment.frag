#version 450
// Segmentation pass: the body's index, written as it is into the 32-bit integer target (flat: one
// value over the triangle, never interpolated or blended).
flat in int vSegment;
layout(location = 0) out int fragSegment;

void main() {
  fragSegment = vSegment;
}
