#version 330 core
// The view model's layer, texel for pixel: colour premultiplied by coverage (the layer was cleared to
// transparent black), blended with ONE, ONE_MINUS_SRC_ALPHA. A multisampled layer arrives resolved, its edges
// already blended. A single-sample one (u_edge_filter = 1) has hard 0/1 coverage: a pixel just outside the
// silhouette (uncovered, with a covered 4-neighbour) takes the 3x3 tent-weighted mean of its neighbourhood,
// which turns each one-pixel stair step into a ramp of partial coverage. Covered pixels keep their exact,
// opaque texels: the ramp lies outside, so the scene under every covered pixel is hidden and need not be
// drawn (view_model_mask.frag).
uniform sampler2D u_layer;
uniform int u_edge_filter;
uniform ivec2 u_last_texel; // the layer's size - 1: neighbours past the border repeat the border
out vec4 o_color;
vec4 at(ivec2 p) { return texelFetch(u_layer, clamp(p, ivec2(0), u_last_texel), 0); }
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 c = texelFetch(u_layer, p, 0);
    if (u_edge_filter != 0 && c.a < 1.0) {
        vec4 l = at(p + ivec2(-1, 0)), r = at(p + ivec2(1, 0)), d = at(p + ivec2(0, -1)), u = at(p + ivec2(0, 1));
        if (max(max(l.a, r.a), max(d.a, u.a)) > 0.5) {
            vec4 corners = at(p + ivec2(-1, -1)) + at(p + ivec2(1, -1)) + at(p + ivec2(-1, 1)) + at(p + ivec2(1, 1));
            c = (4.0 * c + 2.0 * (l + r + d + u) + corners) / 16.0;
        }
    }
    o_color = c;
}
