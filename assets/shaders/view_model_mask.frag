#version 330 core
// The view model's opaque pixels written into the scene's depth buffer at the near plane before the scene
// is drawn (colour writes off): the scene's fragments under them then fail the early depth test and are
// never shaded; the composite later covers exactly these pixels with alpha 1.
uniform sampler2D u_layer;
void main() {
    if (texelFetch(u_layer, ivec2(gl_FragCoord.xy), 0).a < 1.0) discard;
}
