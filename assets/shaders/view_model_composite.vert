#version 330 core
// The view model's footprint (its convex hull on screen, or its rectangle) as a triangle fan in clip space.
layout(location = 0) in vec2 a_position;
void main() {
#ifdef NEAR_DEPTH
    gl_Position = vec4(a_position, -1.0, 1.0); // depth 0: nearer than anything the scene draws
#else
    gl_Position = vec4(a_position, 0.0, 1.0);
#endif
}
