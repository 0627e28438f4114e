#version 330 core
layout(location = 0) in vec2 a_corner;
layout(location = 1) in vec4 i_position_size; // xyz, size
layout(location = 2) in vec4 i_color;         // linear rgb, alpha
layout(location = 3) in float i_rotation;
uniform mat4 u_view;
uniform mat4 u_projection;
out vec2 v_uv;
out vec4 v_color;
void main() {
    float c = cos(i_rotation), s = sin(i_rotation);
    vec2 corner = mat2(c, s, -s, c) * a_corner;
    vec4 view = u_view * vec4(i_position_size.xyz, 1.0);
    view.xy += corner * i_position_size.w;
    v_uv = a_corner + 0.5;
    v_color = i_color;
    gl_Position = u_projection * view;
}
