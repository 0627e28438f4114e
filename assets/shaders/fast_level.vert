#version 330 core
// The fast path's baked level geometry (walls, floors, stairs): position, texture and light-map
// coordinates, nothing else (its light is in the light map). fast.vert handles everything else.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
layout(location = 4) in mat4 i_model;
layout(location = 9) in vec2 a_lightmap_uv;
uniform mat4 u_view_projection;
out vec2 v_uv;
out vec2 v_lightmap_uv;

void main() {
    gl_Position = u_view_projection * (i_model * vec4(a_position, 1.0));
    v_uv = a_uv;
    v_lightmap_uv = a_lightmap_uv;
}
