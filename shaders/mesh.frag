#version 450
layout(location = 0) in vec3 viewPosition;

layout(push_constant) uniform Push {
  mat4 mvp;
  vec4 rotation[3];
  vec4 color;
} push;

layout(location = 0) out vec4 outColor;

void main() {
  vec3 n = normalize(cross(dFdx(viewPosition), dFdy(viewPosition)));
  // A headlight from above the eye; two-sided, as CAD meshes are rarely closed.
  float lambert = abs(dot(n, normalize(vec3(0.3, 0.5, 1.0))));
  // Alpha from the colour: 1 for the bodies, less for the ghost (blended).
  outColor = vec4(push.color.rgb * (0.25 + 0.75 * lambert), push.color.a);
}
