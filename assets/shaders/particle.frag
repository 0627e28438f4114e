#version 330 core
in vec2 v_uv;
in vec4 v_color;
uniform sampler2D u_sprite;
uniform vec3 u_fog_color;
out vec4 o_color;
vec3 linear_to_srgb(vec3 c) { return pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)); }
void main() {
    vec4 t = texture(u_sprite, v_uv);
    // Premultiplied output: additive blending uses (ONE, ONE), alpha blending (ONE, ONE_MINUS_SRC_ALPHA).
    float a = t.a * v_color.a;
    o_color = vec4(linear_to_srgb(t.rgb * v_color.rgb) * a, a);
}
