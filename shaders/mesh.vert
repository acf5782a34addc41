#version 450
// A mesh, flat-shaded: the fragment shader takes the face normal from the
// screen-space derivatives of the view-space position, so meshes need no
// normals.
layout(location = 0) in vec3 position;

layout(push_constant) uniform Push {
  mat4 mvp;
  vec4 rotation[3];  // rows of the model-view rotation
  vec4 color;
} push;

layout(location = 0) out vec3 viewPosition;

void main() {
  gl_Position = push.mvp * vec4(position, 1.0);
  viewPosition = vec3(dot(push.rotation[0].xyz, position), dot(push.rotation[1].xyz, position),
                      dot(push.rotation[2].xyz, position));
}
