#version 450
layout(location = 0) noperspective in vec2 local;
layout(location = 1) flat in float halfLength;
layout(location = 2) flat in float radius;
layout(location = 3) flat in vec4 color;

layout(location = 0) out vec4 outColor;

void main() {
  // Distance from the segment [0, 2 halfLength] on the x axis: a capsule.
  float along = max(abs(local.x - halfLength) - halfLength, 0.0);
  if (along * along + local.y * local.y > radius * radius) discard;
  outColor = vec4(color.rgb, 1.0);
}
