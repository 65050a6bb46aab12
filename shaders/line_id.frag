#version 330 core
// Element-id pass for edges: drawn over the faces' ids with the same depth bias as line.vert,
// an edge's id shows where the edge is visible.
flat in int g_element;
flat in int g_object;
uniform int u_id_base[2];  // id of edge 0 of A and of B
layout(location = 0) out int o_id;

void main() { o_id = u_id_base[g_object] + g_element; }
