#version 330 core
// The view model's opaque pixels, before and after the scene (view_model_layer.h). Drawn first (the mask), it
// writes depth 0 into the scene's depth buffer there, colour writes off: the scene's fragments under them fail
// the early depth test and are never shaded. Built with COPY (the copy), it later writes those pixels' layer
// texels into the scene, where the depth test (EQUAL 0) passes only them: one lookup each, where the
// composite's edge filter reads nine (llvmpipe runs both sides of its branch).
uniform sampler2D u_layer;
out vec4 o_color;
void main() {
    vec4 c = texelFetch(u_layer, ivec2(gl_FragCoord.xy), 0);
#ifdef COPY
    o_color = c;
#else
    if (c.a < 1.0) discard;
    o_color = c;
#endif
}
