#version 330 core
// Expands each segment into a screen-aligned quad of constant width in pixels (core profile
// GL has no wide lines). Quads are extended by half the width past both ends (square caps),
// so consecutive segments of a polyline overlap at their joins and leave no gaps.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec2 u_viewport;           // target size in pixels
uniform float u_line_width;        // pixels
uniform vec4 u_edge_styles[128];   // [object * 64 + edge]: rgb colour, width factor in a

flat in int v_element[];
flat in int v_object[];
flat out int g_element;
flat out int g_object;

void emit_corner(vec2 pixel, vec4 clip) {
  gl_Position = vec4(pixel / (0.5 * u_viewport) * clip.w, clip.z, clip.w);
  g_element = v_element[0];
  g_object = v_object[0];
  EmitVertex();
}

void main() {
  vec4 c0 = gl_in[0].gl_Position;
  vec4 c1 = gl_in[1].gl_Position;
  // a point behind the eye cannot be projected (automatic framing never puts one there)
  if (c0.w <= 0.0 || c1.w <= 0.0) return;
  vec2 s0 = c0.xy / c0.w * 0.5 * u_viewport;
  vec2 s1 = c1.xy / c1.w * 0.5 * u_viewport;
  vec2 d = s1 - s0;
  float len = length(d);
  vec2 dir = len > 1e-4 ? d / len : vec2(1.0, 0.0);
  vec2 side = vec2(-dir.y, dir.x);
  float half_width = 0.5 * u_line_width * u_edge_styles[v_object[0] * 64 + v_element[0]].a;
  vec2 a = s0 - dir * half_width;
  vec2 b = s1 + dir * half_width;
  emit_corner(a + side * half_width, c0);
  emit_corner(a - side * half_width, c0);
  emit_corner(b + side * half_width, c1);
  emit_corner(b - side * half_width, c1);
  EndPrimitive();
}
