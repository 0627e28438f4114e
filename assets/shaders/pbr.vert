#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_tangent;
layout(location = 4) in mat4 i_model;
layout(location = 8) in vec4 i_params;
uniform mat4 u_view_projection;
uniform mat4 u_shadow_matrix;
out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
out vec4 v_tangent;
out vec4 v_shadow;
out float v_emissive_scale;
out vec3 v_tint; // MeshInstance::tint
void main() {
    vec4 world = i_model * vec4(a_position, 1.0);
    mat3 normal_matrix = mat3(i_model); // models use uniform scale; level meshes are baked in world space
    v_world = world.xyz;
    v_normal = normal_matrix * a_normal;
    v_tangent = vec4(normal_matrix * a_tangent.xyz, a_tangent.w);
    v_uv = a_uv;
    v_shadow = u_shadow_matrix * world;
    v_emissive_scale = i_params.x;
    v_tint = i_params.yzw;
    gl_Position = u_view_projection * world;
}
