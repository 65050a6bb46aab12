#version 330 core
// Transparent faces. The triangles arrive sorted from farthest to nearest
// (render/scene_buffers.cc) and are blended with "over" (SRC_ALPHA, ONE_MINUS_SRC_ALPHA), so
// the layers are composited in depth order: A seen through the dish, the dish through B's
// band. Depth is tested (not written) against the opaque edges drawn before.
in vec4 v_color;  // shaded in surface.vert
layout(location = 0) out vec4 o_color;

void main() { o_color = v_color; }
