#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 4) in mat4 i_model;
uniform mat4 u_light_view_projection;
void main() { gl_Position = u_light_view_projection * i_model * vec4(a_position, 1.0); }
