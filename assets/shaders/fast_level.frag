#version 330 core
// fast.frag's baked branch alone, without a branch: llvmpipe runs both sides of an `if` on a uniform with
// masks, texture lookups included, so the general shader paid for the ORM and emissive maps on every level
// pixel. This one is two lookups (base colour x occlusion, read raw and squared; the light map) and the
// same arithmetic as fast.frag for a baked surface without ORM or emissive maps (the renderer uses fast.frag
// for those). DYNAMIC_LIGHTS (the fast_level_lit program) adds the lights that are not in the light map
// (muzzle flashes) per pixel, in fast.vert's units: the renderer uses it only for surfaces one reaches.
in vec2 v_uv;
in vec2 v_lightmap_uv;
in float v_fog_half;
out vec4 o_color;
#ifdef DYNAMIC_LIGHTS
#define MAX_LIGHTS 8
in vec3 v_world;
in vec3 v_normal;
uniform int u_light_count;
uniform vec4 u_light_position[MAX_LIGHTS];  // xyz, w = range
uniform vec4 u_light_color[MAX_LIGHTS];     // linear rgb * intensity * PI, w = 1 spot / 0 point
uniform vec4 u_light_direction[MAX_LIGHTS]; // spot axis xyz, w = cos(outer)
uniform float u_light_inner[MAX_LIGHTS];    // cos(inner)
const float PI = 3.14159265;

// Irradiance from the dynamic lights, as fast.vert's diffuse term.
vec3 dynamic_light() {
    vec3 n = normalize(v_normal);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < u_light_count; ++i) {
        vec3 to_light = u_light_position[i].xyz - v_world;
        float dist = length(to_light);
        float range = u_light_position[i].w;
        if (dist >= range) continue;
        vec3 l = to_light / max(dist, 1e-4);
        float atten = 1.0 - dist / range;
        if (u_light_color[i].w > 0.5)
            atten *= smoothstep(u_light_direction[i].w, u_light_inner[i], dot(-l, u_light_direction[i].xyz));
        sum += u_light_color[i].rgb * atten * max(dot(n, l), 0.0) / PI;
    }
    return sum;
}
#endif

uniform sampler2D u_base_map;
uniform sampler2D u_lightmap;
uniform vec4 u_base_factor;
uniform vec3 u_emissive_factor;
uniform vec2 u_metal_rough;
uniform float u_lightmap_range; // > 0: the light map is 8-bit, sqrt-encoded over 0..range; 0: linear float
uniform vec3 u_fog_color;
uniform float u_exposure;

vec3 aces(vec3 x) { // Narkowicz 2015 fit
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// Exponential-squared fog, 1 - exp(-(density x view depth)^2), from v_fog_half = density x depth / 2:
// exp(-4s) as (1 / (1 + s + s^2/2 + s^3/6))^4 with s = v_fog_half^2, within 0.0015 of exp everywhere
// (0.4/255), where llvmpipe's exp() and the depth buffer's division cost a sixth of a level pixel.
float fog_amount() {
    float s = v_fog_half * v_fog_half;
    float e = 1.0 / (1.0 + s * (1.0 + s * (0.5 + s * (1.0 / 6.0))));
    e *= e;
    return 1.0 - e * e;
}

void main() {
    vec4 base = texture(u_base_map, v_uv);
    base.rgb *= base.rgb; // sRGB map read raw: gamma 2
    float metallic = u_metal_rough.x;
    vec3 light = texture(u_lightmap, v_lightmap_uv).rgb;
    light *= mix(vec3(1.0), light * u_lightmap_range, float(u_lightmap_range > 0.0));
#ifdef DYNAMIC_LIGHTS
    light += dynamic_light();
#endif
    // fast.frag's light x (base (1 - metallic) + F0 / 2) with F0 = mix(0.04, base, metallic), multiplied out.
    vec3 color = light * (base.rgb * u_base_factor.rgb * (1.0 - 0.5 * metallic) + 0.02 * (1.0 - metallic)) +
                 u_emissive_factor;

    color = mix(color, u_fog_color, fog_amount());
    o_color = vec4(sqrt(aces(color * u_exposure)), 1.0); // opaque: nothing reads the level's alpha
}
