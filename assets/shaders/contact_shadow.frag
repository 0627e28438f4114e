#version 330 core
// Multiplies what is drawn under the ellipse (blend: destination x source colour): soft edges, darkest from
// the caster's feet back, fading to half toward the far tip. Both paths write gamma-encoded colour (sqrt on
// the fast path, sRGB on the full), so taking a share `a` of the light away is a factor sqrt(1 - a).
in vec2 v_ellipse;
flat in vec2 v_darkness_feet;
out vec4 o_color;
void main() {
    float edge = 1.0 - smoothstep(0.45, 1.0, length(v_ellipse));
    float feet = v_darkness_feet.y;
    float along = clamp((v_ellipse.x - feet) / max(1.0 - feet, 1e-3), 0.0, 1.0);
    float a = v_darkness_feet.x * edge * (1.0 - 0.5 * along);
    o_color = vec4(vec3(sqrt(1.0 - a)), 1.0);
}
