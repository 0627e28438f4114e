#version 330 core
// The fast path's pixels: base colour x (light map or per-vertex light) + emissive, fog from the view depth
// (fog_amount), ACES and a gamma-2 encoding like pbr.frag's sRGB.
in vec2 v_uv;
in vec2 v_lightmap_uv;
in float v_fog_half;
in vec3 v_diffuse;
in vec3 v_specular;
flat in float v_emissive_scale;
flat in vec3 v_tint; // MeshInstance::tint: its colour replaces part of the shading
out vec4 o_color;

uniform sampler2D u_base_map;
uniform sampler2D u_orm_map;
uniform sampler2D u_emissive_map;
uniform sampler2D u_lightmap;
uniform vec4 u_base_factor;
uniform vec3 u_emissive_factor;
uniform vec2 u_metal_rough;
uniform int u_map_flags; // 2 orm, 4 emissive, 32 light map, 64 sRGB maps read raw, 128 orm in base (alpha)
uniform float u_lightmap_range; // > 0: the light map is 8-bit, sqrt-encoded over 0..range
uniform vec3 u_fog_color;
uniform float u_exposure;

vec3 aces(vec3 x) { // Narkowicz 2015 fit
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
// Gamma 2 instead of the sRGB curve: a square root and a square instead of pow() per channel (within
// 9/255 of sRGB in the mid-tones; a texture shown at unit light round-trips exactly).
vec3 encode(vec3 c) { return sqrt(c); }

// Exponential-squared fog, 1 - exp(-(density x view depth)^2), from v_fog_half = density x depth / 2:
// exp(-4s) as (1 / (1 + s + s^2/2 + s^3/6))^4 with s = v_fog_half^2, within 0.0015 of exp everywhere
// (0.4/255), where llvmpipe's exp() and the depth buffer's division cost a sixth of a level pixel.
float fog_amount() {
    float s = v_fog_half * v_fog_half;
    float e = 1.0 / (1.0 + s * (1.0 + s * (0.5 + s * (1.0 / 6.0))));
    e *= e;
    return 1.0 - e * e;
}

// Which maps a draw reads. The general program ("fast") decides per draw from u_map_flags; the model
// programs ("fast_model", "fast_model_orm", ...) are this file built with FIXED_MAPS and fix them at compile
// time, because llvmpipe runs both sides of a branch on a uniform, texture lookups included: a rifle pixel
// paid for four lookups (base, ORM, light map, emissive) where it needs one or two.
#ifdef FIXED_MAPS
#define ORM_MAP (FIXED_ORM == 1)
#define ORM_IN_BASE (FIXED_ORM == 2) // base x occlusion in rgb, metalness in alpha (one lookup)
#define EMISSIVE_MAP FIXED_EMISSIVE
#define BAKED false
#else
#define ORM_IN_BASE ((u_map_flags & 128) != 0)
#define ORM_MAP ((u_map_flags & 2) != 0)
#define EMISSIVE_MAP ((u_map_flags & 4) != 0)
#define BAKED ((u_map_flags & 32) != 0)
#endif

void main() {
    vec4 base = texture(u_base_map, v_uv);
    bool raw = (u_map_flags & 64) != 0;
    if (raw) base.rgb *= base.rgb;
    float metallic = u_metal_rough.x, ao = 1.0;
    if (ORM_IN_BASE) {
        metallic *= base.a;
        base.a = 1.0;
    }
    base *= u_base_factor;
    if (ORM_MAP) {
        vec3 orm = texture(u_orm_map, v_uv).rgb;
        ao = orm.r;
        metallic *= orm.b;
    }
    vec3 f0 = mix(vec3(0.04), base.rgb, metallic);
    vec3 color;
    if (BAKED) {
        // The light map holds irradiance (ambient + sun + lights, diffuse); metals get a rough
        // specular share of it.
        vec3 light = texture(u_lightmap, v_lightmap_uv).rgb;
        if (u_lightmap_range > 0.0) light = light * light * u_lightmap_range;
        light *= ao;
        color = light * (base.rgb * (1.0 - metallic) + f0 * 0.5);
    } else {
        color = base.rgb * (1.0 - metallic) * v_diffuse * ao + f0 * v_specular;
    }
    vec3 emissive = u_emissive_factor * v_emissive_scale;
    if (EMISSIVE_MAP) {
        vec3 e = texture(u_emissive_map, v_uv).rgb;
        emissive *= raw ? e * e : e;
    }
    color += emissive;
    // A tint pulls the colour toward itself: the other channels dim as it adds its own (a hit robot reads
    // red, not orange); no tint leaves the colour as it was.
    color = color * (1.0 - 0.6 * clamp(max(v_tint.r, max(v_tint.g, v_tint.b)), 0.0, 1.0)) + v_tint;

    color = mix(color, u_fog_color, fog_amount());
    o_color = vec4(encode(aces(color * u_exposure)), base.a);
}
