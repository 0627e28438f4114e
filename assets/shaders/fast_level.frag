#version 330 core
// fast.frag's baked branch alone, without a branch: llvmpipe runs both sides of an `if` on a uniform with
// masks, texture lookups included, so the general shader paid for the ORM and emissive maps on every level
// pixel. This one is two lookups (base colour x occlusion, read raw and squared; the light map) and the
// same arithmetic as fast.frag for a baked surface without ORM or emissive maps (the renderer uses fast.frag
// for those).
in vec2 v_uv;
in vec2 v_lightmap_uv;
out vec4 o_color;

uniform sampler2D u_base_map;
uniform sampler2D u_lightmap;
uniform vec4 u_base_factor;
uniform vec3 u_emissive_factor;
uniform vec2 u_metal_rough;
uniform float u_lightmap_range; // > 0: the light map is 8-bit, sqrt-encoded over 0..range; 0: linear float
uniform vec3 u_fog_color;
uniform float u_fog_density;
uniform float u_exposure;
uniform vec2 u_depth_to_view;  // view depth = x / (y - window depth): x = n f / (f - n), y = f / (f - n)

vec3 aces(vec3 x) { // Narkowicz 2015 fit
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

void main() {
    vec4 base = texture(u_base_map, v_uv);
    base.rgb *= base.rgb; // sRGB map read raw: gamma 2
    base *= u_base_factor;
    float metallic = u_metal_rough.x;
    vec3 f0 = mix(vec3(0.04), base.rgb, metallic);
    vec3 light = texture(u_lightmap, v_lightmap_uv).rgb;
    light *= mix(vec3(1.0), light * u_lightmap_range, float(u_lightmap_range > 0.0));
    vec3 color = light * (base.rgb * (1.0 - metallic) + f0 * 0.5) + u_emissive_factor;

    float dist = u_depth_to_view.x / (u_depth_to_view.y - gl_FragCoord.z);
    float fog = 1.0 - exp(-u_fog_density * u_fog_density * dist * dist);
    color = mix(color, u_fog_color, clamp(fog, 0.0, 1.0));
    o_color = vec4(sqrt(aces(color * u_exposure)), base.a);
}
