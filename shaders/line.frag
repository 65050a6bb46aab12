#version 330 core
// Edges are opaque: drawn first, with depth, so that the transparent faces in front of an edge
// tint it (it shows through them) and the faces behind it are hidden by it.
flat in int g_element;
flat in int g_object;
uniform vec4 u_edge_styles[128];  // [object * 64 + edge]: rgb colour, width factor in a
layout(location = 0) out vec4 o_color;

void main() { o_color = vec4(u_edge_styles[g_object * 64 + g_element].rgb, 1.0); }
