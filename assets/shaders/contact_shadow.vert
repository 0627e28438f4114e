#version 330 core
// Contact shadows (render/contact_shadows.h): one quad per ellipse on the floor, in world space, with its
// ellipse coordinates (x along the shadow, away from its light; y across; both -1..1 at the edge).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec2 a_ellipse;
layout(location = 2) in vec2 a_darkness_feet; // darkness 0..1, where the caster stands along x
uniform mat4 u_view_projection;
out vec2 v_ellipse;
flat out vec2 v_darkness_feet;
void main() {
    v_ellipse = a_ellipse;
    v_darkness_feet = a_darkness_feet;
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
