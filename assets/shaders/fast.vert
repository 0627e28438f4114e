#version 330 core
// The fast path for software rasterisers (llvmpipe): static level geometry reads its light from the baked
// light map (u_baked = 1: ambient, sun with shadows and every level light, combined on the CPU); models
// are lit per vertex (Gouraud) with the same lights the full path uses, so the fragment shader is two or
// three texture fetches and a multiply-add. Light units and falloff are pbr.frag's.
#define MAX_LIGHTS 8
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 4) in mat4 i_model;
layout(location = 8) in vec4 i_params;
layout(location = 9) in vec2 a_lightmap_uv;
uniform mat4 u_view_projection;
uniform float u_fog_density; // 0: no fog (orthographic views, the view model)
uniform mat4 u_shadow_matrix;
uniform sampler2DShadow u_shadow_map;
uniform int u_baked;          // 1: the light map lights this draw
uniform int u_receive_shadow; // 1: look the sun's shadow up per vertex
uniform vec2 u_metal_rough;   // metallic, roughness factors
uniform vec3 u_camera_position;
uniform vec3 u_sun_direction; // towards the sun
uniform vec3 u_sun_color;
uniform vec3 u_sky_color;
uniform vec3 u_ground_color;
uniform int u_light_count;
uniform vec4 u_light_position[MAX_LIGHTS];  // xyz, w = range
uniform vec4 u_light_color[MAX_LIGHTS];     // linear rgb * intensity * PI, w = 1 spot / 0 point
uniform vec4 u_light_direction[MAX_LIGHTS]; // spot axis xyz, w = cos(outer)
uniform float u_light_inner[MAX_LIGHTS];    // cos(inner)
out vec2 v_uv;
out vec2 v_lightmap_uv;
out float v_fog_half; // fog density x view depth / 2: affine in space, so interpolated exactly
out vec3 v_diffuse;  // times albedo * (1 - metallic) in the fragment shader
out vec3 v_specular; // times F0
flat out float v_emissive_scale; // per instance: flat costs no interpolation per pixel
flat out vec3 v_tint; // MeshInstance::tint (per instance, flat)

const float PI = 3.14159265;

void main() {
    vec4 world = i_model * vec4(a_position, 1.0);
    gl_Position = u_view_projection * world;
    v_fog_half = 0.5 * u_fog_density * gl_Position.w; // w = view depth (perspective)
    v_uv = a_uv;
    v_lightmap_uv = a_lightmap_uv;
    v_emissive_scale = i_params.x;
    v_tint = i_params.yzw;
    v_diffuse = vec3(0.0);
    v_specular = vec3(0.0);
    if (u_baked != 0) return;

    vec3 n = normalize(mat3(i_model) * a_normal);
    vec3 v = normalize(u_camera_position - world.xyz);
    float roughness = clamp(u_metal_rough.y, 0.045, 1.0);
    float a = roughness * roughness;
    // Blinn-Phong exponent matching GGX's peak for this roughness; normalised lobe, implicit visibility.
    float shininess = clamp(2.0 / (a * a) - 2.0, 1.0, 2048.0);
    float lobe = (shininess + 2.0) / (8.0 * PI);

    vec3 ambient = mix(u_ground_color, u_sky_color, n.y * 0.5 + 0.5);
    vec3 diffuse = ambient;
    vec3 specular = ambient * 0.6 * (1.0 - 0.5 * roughness);

    float shadow = 1.0;
    if (u_receive_shadow != 0) {
        vec4 s = u_shadow_matrix * world;
        vec3 p = s.xyz / s.w;
        if (all(greaterThan(p, vec3(0.0))) && all(lessThan(p, vec3(1.0)))) shadow = texture(u_shadow_map, p);
    }
    float nl = max(dot(n, u_sun_direction), 0.0);
    if (nl > 0.0) {
        vec3 radiance = u_sun_color * shadow * nl;
        diffuse += radiance / PI;
        specular += radiance * lobe * pow(max(dot(n, normalize(v + u_sun_direction)), 0.0), shininess);
    }
    for (int i = 0; i < u_light_count; ++i) {
        vec3 to_light = u_light_position[i].xyz - world.xyz;
        float dist2 = dot(to_light, to_light);
        float range = u_light_position[i].w;
        if (dist2 >= range * range) continue;
        float dist = sqrt(dist2);
        vec3 l = to_light / dist;
        float atten = 1.0 - dist / range;
        if (u_light_color[i].w > 0.5)
            atten *= smoothstep(u_light_direction[i].w, u_light_inner[i], dot(-l, u_light_direction[i].xyz));
        float ln = max(dot(n, l), 0.0);
        if (atten <= 0.0 || ln <= 0.0) continue;
        vec3 radiance = u_light_color[i].rgb * atten * ln;
        diffuse += radiance / PI;
        specular += radiance * lobe * pow(max(dot(n, normalize(v + l)), 0.0), shininess);
    }
    v_diffuse = diffuse;
    v_specular = specular;
}
