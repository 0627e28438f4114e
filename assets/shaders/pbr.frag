#version 330 core
#define MAX_LIGHTS 8
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_tangent;
in vec4 v_shadow;
in float v_emissive_scale;
in vec3 v_tint; // MeshInstance::tint: its colour replaces part of the shading
out vec4 o_color;

uniform sampler2D u_base_map;
uniform sampler2D u_normal_map;
uniform sampler2D u_orm_map;
uniform sampler2D u_emissive_map;
uniform sampler2D u_height_map;
uniform sampler2DShadow u_shadow_map;
uniform vec4 u_base_factor;
uniform vec3 u_emissive_factor;
uniform vec2 u_metal_rough;   // factors multiplying the ORM map's B and G
uniform float u_bump_strength;
uniform int u_map_flags;      // 1 normal, 2 orm, 4 emissive, 8 height (bump when no normal map), 16 shadow receiver

uniform vec3 u_camera_position;
uniform vec3 u_sun_direction; // towards the sun
uniform vec3 u_sun_color;
uniform vec3 u_sky_color;
uniform vec3 u_ground_color;
uniform vec3 u_fog_color;
uniform float u_fog_density;
uniform float u_exposure;
uniform int u_light_count;
uniform vec4 u_light_position[MAX_LIGHTS];  // xyz, w = range
uniform vec4 u_light_color[MAX_LIGHTS];     // linear rgb * intensity, w = 1 spot / 0 point
uniform vec4 u_light_direction[MAX_LIGHTS]; // spot axis xyz, w = cos(outer)
uniform float u_light_inner[MAX_LIGHTS];    // cos(inner)

const float PI = 3.14159265;

vec3 aces(vec3 x) { // Narkowicz 2015 fit
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
vec3 linear_to_srgb(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

vec3 shade(vec3 n, vec3 v, vec3 l, vec3 radiance, vec3 albedo, vec3 f0, float a2, float metallic) {
    float nl = max(dot(n, l), 0.0);
    if (nl <= 0.0) return vec3(0.0);
    vec3 h = normalize(v + l);
    float nv = max(dot(n, v), 1e-4);
    float nh = max(dot(n, h), 0.0);
    float d = nh * nh * (a2 - 1.0) + 1.0;
    float D = a2 / (PI * d * d);
    float k = sqrt(a2);
    float V = 0.5 / (nl * (nv * (1.0 - k) + k) + nv * (nl * (1.0 - k) + k));
    vec3 F = f0 + (1.0 - f0) * pow(1.0 - max(dot(v, h), 0.0), 5.0);
    vec3 diffuse = (1.0 - F) * (1.0 - metallic) * albedo / PI;
    return (diffuse + D * V * F) * radiance * nl;
}

void main() {
    vec4 base = texture(u_base_map, v_uv) * u_base_factor;
    vec3 albedo = base.rgb;
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;
    if ((u_map_flags & 1) != 0) {
        vec3 t = normalize(v_tangent.xyz - n * dot(n, v_tangent.xyz));
        vec3 b = cross(n, t) * v_tangent.w;
        vec3 tn = texture(u_normal_map, v_uv).xyz * 2.0 - 1.0;
        n = normalize(t * tn.x + b * tn.y + n * tn.z);
    } else if ((u_map_flags & 8) != 0) {
        // Bump: the height's screen-space gradient tilts the normal (Mikkelsen's surface gradient).
        float h = texture(u_height_map, v_uv).r * u_bump_strength;
        vec3 dpdx = dFdx(v_world), dpdy = dFdy(v_world);
        float dhdx = dFdx(h), dhdy = dFdy(h);
        vec3 r1 = cross(dpdy, n), r2 = cross(n, dpdx);
        float det = dot(dpdx, r1);
        vec3 grad = sign(det) * (dhdx * r1 + dhdy * r2);
        n = normalize(abs(det) * n - grad);
    }
    float ao = 1.0, roughness = u_metal_rough.y, metallic = u_metal_rough.x;
    if ((u_map_flags & 2) != 0) {
        vec3 orm = texture(u_orm_map, v_uv).rgb;
        ao = orm.r;
        roughness *= orm.g;
        metallic *= orm.b;
    }
    roughness = clamp(roughness, 0.045, 1.0);
    float a = roughness * roughness;
    float a2 = a * a;
    vec3 f0 = mix(vec3(0.04), albedo, metallic);
    vec3 v = normalize(u_camera_position - v_world);

    // Ambient: sky/ground hemisphere, specular via Karis' analytic environment BRDF.
    float hemi = n.y * 0.5 + 0.5;
    vec3 ambient = mix(u_ground_color, u_sky_color, hemi);
    float nv = max(dot(n, v), 1e-4);
    vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022), c1 = vec4(1.0, 0.0425, 1.04, -0.04);
    vec4 r = roughness * c0 + c1;
    float a004 = min(r.x * r.x, exp2(-9.28 * nv)) * r.x + r.y;
    vec2 env = vec2(-1.04, 1.04) * a004 + r.zw;
    vec3 color = ambient * ao * (albedo * (1.0 - metallic) + (f0 * env.x + env.y) * 0.6);

    float shadow = 1.0;
    if ((u_map_flags & 16) != 0) {
        vec3 s = v_shadow.xyz / v_shadow.w;
        if (all(greaterThan(s, vec3(0.0))) && all(lessThan(s, vec3(1.0)))) shadow = texture(u_shadow_map, s);
    }
    color += shade(n, v, u_sun_direction, u_sun_color * shadow, albedo, f0, a2, metallic);

    for (int i = 0; i < u_light_count; ++i) {
        vec3 to_light = u_light_position[i].xyz - v_world;
        float dist2 = dot(to_light, to_light);
        float range = u_light_position[i].w;
        if (dist2 >= range * range) continue;
        float dist = sqrt(dist2);
        vec3 l = to_light / dist;
        // The reference's falloff (three.js legacy lights, decay 1): linear to zero at the range. Light
        // colours arrive multiplied by PI, as three.js does outside its physically-correct mode.
        float atten = 1.0 - dist / range;
        if (u_light_color[i].w > 0.5) {
            float cd = dot(-l, u_light_direction[i].xyz);
            atten *= smoothstep(u_light_direction[i].w, u_light_inner[i], cd);
        }
        if (atten > 0.0) color += shade(n, v, l, u_light_color[i].rgb * atten, albedo, f0, a2, metallic);
    }

    vec3 emissive = u_emissive_factor * v_emissive_scale;
    if ((u_map_flags & 4) != 0) emissive *= texture(u_emissive_map, v_uv).rgb;
    color += emissive;
    // A tint pulls the colour toward itself: the other channels dim as it adds its own (a hit robot reads
    // red, not orange); no tint leaves the colour as it was.
    color = color * (1.0 - 0.6 * clamp(max(v_tint.r, max(v_tint.g, v_tint.b)), 0.0, 1.0)) + v_tint;

    float dist = length(u_camera_position - v_world);
    float fog = 1.0 - exp(-u_fog_density * u_fog_density * dist * dist);
    color = mix(color, u_fog_color, clamp(fog, 0.0, 1.0));
    o_color = vec4(linear_to_srgb(aces(color * u_exposure)), base.a);
}
