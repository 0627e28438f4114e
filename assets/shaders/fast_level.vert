#version 330 core
// The fast path's baked level geometry (walls, floors, stairs): position, texture and light-map
// coordinates, nothing else (its light is in the light map). fast.vert handles everything else.
// DYNAMIC_LIGHTS (the fast_level_lit program): also the world position and normal, for the per-pixel
// dynamic lights (muzzle flashes) that are not in the light map.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
layout(location = 4) in mat4 i_model;
layout(location = 9) in vec2 a_lightmap_uv;
uniform mat4 u_view_projection;
uniform float u_fog_density; // 0: no fog (orthographic views, the view model)
out vec2 v_uv;
out vec2 v_lightmap_uv;
out float v_fog_half; // fog density x view depth / 2: affine in space, so interpolated exactly
#ifdef DYNAMIC_LIGHTS
layout(location = 1) in vec3 a_normal;
out vec3 v_world;
out vec3 v_normal;
#endif

void main() {
    vec4 world = i_model * vec4(a_position, 1.0);
    gl_Position = u_view_projection * world;
    v_fog_half = 0.5 * u_fog_density * gl_Position.w; // w = view depth (perspective)
    v_uv = a_uv;
    v_lightmap_uv = a_lightmap_uv;
#ifdef DYNAMIC_LIGHTS
    v_world = world.xyz;
    v_normal = mat3(i_model) * a_normal;
#endif
}
