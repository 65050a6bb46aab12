#version 330 core
// Element-id pass: which face is nearest to the eye at each pixel, so that labels are anchored
// at points where their element is visible. The id's layout is in render/scene_element.h.
flat in int v_element;
flat in int v_object;
uniform int u_id_base[2];  // id of face 0 of A and of B
layout(location = 0) out int o_id;

void main() { o_id = u_id_base[v_object] + v_element; }
