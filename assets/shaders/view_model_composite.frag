#version 330 core
// The view model's resolved multisampled layer, texel for pixel: colour premultiplied by coverage (the layer
// was cleared to transparent black), blended with ONE, ONE_MINUS_SRC_ALPHA.
uniform sampler2D u_layer;
out vec4 o_color;
void main() { o_color = texelFetch(u_layer, ivec2(gl_FragCoord.xy), 0); }
