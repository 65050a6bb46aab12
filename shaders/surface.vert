#version 330 core
// Surfaces of both solids (A's vertices first), for the shaded pass (surface.frag) and the
// element-id pass (surface_id.frag). Vertices are split per face, so each carries its face's
// exact normal.
//   a_position  solid's own frame
//   a_normal    unit outward normal of the exact surface, solid's own frame
//   a_element   index of the face in Solid::faces
//   a_object    0 for A, 1 for B
// Shading is smooth (Gouraud) from those exact normals: per-pixel lighting cost a quarter of
// the frame on llvmpipe (measured 138 -> 114 ms of CPU at 1280x960), and with meshes at the
// default chordal error a triangle covers only ~10 px, so the interpolated colours look alike.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in int a_element;
layout(location = 3) in int a_object;

uniform mat4 u_model[2];    // solid's frame -> world (rigid): [0] A's displayed pose, [1] B: I
uniform mat4 u_view;        // world -> eye
uniform mat4 u_projection;  // eye -> clip
uniform vec4 u_face_colors[128];  // [object * 64 + face]: display colour and opacity

out vec4 v_color;        // shaded colour and opacity, for surface.frag
flat out int v_element;  // for surface_id.frag
flat out int v_object;

// Two lights fixed to the eye (a key from the upper left, a weak fill from the right), so that
// every view is lit alike whatever the scene's orientation.
const vec3 kKeyLight = vec3(-0.40, 0.62, 0.67);
const vec3 kFillLight = vec3(0.70, -0.10, 0.70);

void main() {
  mat4 model_view = u_view * u_model[a_object];
  vec4 p = model_view * vec4(a_position, 1.0);
  gl_Position = u_projection * p;
  v_element = a_element;
  v_object = a_object;

  // rigid transforms: the rotation part maps normals too (no inverse transpose needed)
  vec3 n = normalize(mat3(model_view) * a_normal);
  vec3 to_eye = normalize(-p.xyz);
  // two-sided: the inside of the dish and the far halves of the objects are seen too
  if (dot(n, to_eye) < 0.0) n = -n;

  // Blinn-Phong with a soft ambient term, so that the pastel colours stay light
  vec4 base = u_face_colors[a_object * 64 + a_element];
  vec3 key = normalize(kKeyLight);
  float diffuse = max(dot(n, key), 0.0);
  float fill = max(dot(n, normalize(kFillLight)), 0.0);
  float specular = pow(max(dot(n, normalize(key + to_eye)), 0.0), 60.0);
  vec3 color = base.rgb * (0.52 + 0.38 * diffuse + 0.14 * fill) + vec3(0.30 * specular);

  // a grazing ray crosses more material: opacity rises toward the silhouette, which outlines
  // smooth objects that have no edges (the ellipsoid) without drawing a contour
  float rim = pow(1.0 - abs(dot(n, to_eye)), 3.0);
  float alpha = clamp(base.a + (1.0 - base.a) * 0.5 * rim, 0.0, 0.95);
  v_color = vec4(min(color, vec3(1.0)), alpha);
}
