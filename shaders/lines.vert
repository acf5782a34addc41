#version 450
// Segments as screen-space quads: instance i draws the segment from point
// 2i to point 2i+1 of the storage buffer, widened to `width` pixels and
// extended by half a width at each end for the round caps the fragment
// shader cuts. Needs no wideLines feature, and polylines get round joins.
struct Point {
  vec4 positionWidth;  // xyz world (or pixels for the HUD), w: width in pixels
  vec4 color;
};
layout(std430, set = 0, binding = 0) readonly buffer Points { Point points[]; };

layout(push_constant) uniform Push {
  mat4 viewProj;
  vec2 viewport;     // pixels
  float depthOffset; // NDC depth pulled towards the eye: lines on a surface stay in front of it
} push;

layout(location = 0) noperspective out vec2 local;  // pixels: x along the segment from its start, y across
layout(location = 1) flat out float halfLength;
layout(location = 2) flat out float radius;
layout(location = 3) flat out vec4 color;

void main() {
  Point a = points[2 * gl_InstanceIndex];
  Point b = points[2 * gl_InstanceIndex + 1];
  vec4 ca = push.viewProj * vec4(a.positionWidth.xyz, 1.0);
  vec4 cb = push.viewProj * vec4(b.positionWidth.xyz, 1.0);
  color = a.color;
  radius = 0.5 * a.positionWidth.w;
  if (ca.w <= 1e-6 || cb.w <= 1e-6) {  // an end behind the eye: not drawn
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    local = vec2(0.0);
    halfLength = 0.0;
    return;
  }
  vec3 na = ca.xyz / ca.w, nb = cb.xyz / cb.w;
  vec2 sa = (na.xy * 0.5 + 0.5) * push.viewport;
  vec2 sb = (nb.xy * 0.5 + 0.5) * push.viewport;
  vec2 d = sb - sa;
  float len = length(d);
  d = len > 1e-4 ? d / len : vec2(1.0, 0.0);
  vec2 n = vec2(-d.y, d.x);
  // Two triangles: (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1) in (end, side).
  const int ends[6] = int[6](0, 1, 1, 0, 1, 0);
  const int sides[6] = int[6](0, 0, 1, 0, 1, 1);
  int end = ends[gl_VertexIndex];
  float side = sides[gl_VertexIndex] == 0 ? -1.0 : 1.0;
  float r = radius + 0.5;  // half a pixel more, so the cap's edge pixels are covered
  vec2 p = (end == 0 ? sa - d * r : sb + d * r) + n * side * r;
  float z = (end == 0 ? na.z : nb.z) - push.depthOffset;
  gl_Position = vec4(p / push.viewport * 2.0 - 1.0, z, 1.0);
  local = vec2(end == 0 ? -r : len + r, side * r);
  halfLength = 0.5 * len;
}
