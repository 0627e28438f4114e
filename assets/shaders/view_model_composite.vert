#version 330 core
// The view model's footprint (its convex hull on screen, or its rectangle) as a triangle fan in clip space.
layout(location = 0) in vec2 a_position;
void main() {
    // Depth 0, nearer than anything the scene draws: the mask's depth (view_model_mask.frag), which the
    // composite's two passes test against where the mask was written.
    gl_Position = vec4(a_position, -1.0, 1.0);
}
