#version 330 core
// Edges of both solids as line segments (pairs of consecutive polyline points), widened to a
// constant screen width by line.geom.
//   a_position  solid's own frame
//   a_element   index of the edge in Solid::edges
//   a_object    0 for A, 1 for B
layout(location = 0) in vec3 a_position;
layout(location = 2) in int a_element;
layout(location = 3) in int a_object;

uniform mat4 u_model[2];
uniform mat4 u_view;
uniform mat4 u_projection;
// The edge lies exactly on the faces it bounds; moved this far toward the eye (world units)
// it wins the depth test against them, while a face genuinely in front still covers it.
uniform float u_depth_bias;

flat out int v_element;
flat out int v_object;

void main() {
  vec4 p = u_view * u_model[a_object] * vec4(a_position, 1.0);
  p.xyz += normalize(-p.xyz) * u_depth_bias;
  v_element = a_element;
  v_object = a_object;
  gl_Position = u_projection * p;
}
