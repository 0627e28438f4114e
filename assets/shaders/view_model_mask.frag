#version 330 core
// The view model's opaque pixels, written before the scene (view_model_layer.h): their colour, and depth 0 in
// the scene's depth buffer, so the scene's fragments under them fail the early depth test and are never
// shaded, and the composite's edge filter (nine lookups) runs only on the pixels left (depth LESS).
uniform sampler2D u_layer;
out vec4 o_color;
void main() {
    vec4 c = texelFetch(u_layer, ivec2(gl_FragCoord.xy), 0);
    if (c.a < 1.0) discard;
    o_color = c;
}
