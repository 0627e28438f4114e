// SceneRenderer's contact shadows (contact_shadows.h): after the opaque pass, the movers' ellipses are
// drawn as quads just above their floors that multiply the colour under them (depth-tested, not written),
// so walls in front hide them and the movers themselves, drawn already, stay unshaded.
#include "render/scene_renderer.h"

#include "geometry/frustum.h"
#include "render/gpu_mesh.h"

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

namespace ks::render {

void SceneRenderer::draw_contact_shadows(const SceneFrame& frame, FrameStats& stats) {
    if (!settings_.contact_shadows || !frame.shadow_casters || frame.shadow_casters->empty()) return;
    // What blocks a light from a caster's floor: the solid boxes of the level (walls, floors, closed doors);
    // the sun's blockers leave out what casts no sun shadow (ceilings), as the bake and the shadow map do.
    ShadowLights& in = contact_lights_;
    in.environment = &frame.environment;
    // The full path's sun shadow map already holds the movers.
    in.sun = fast_ || !settings_.shadows || shadow_texture_ == 0;
    in.lights = frame.lights;
    in.candidates = &lights_in_view_;
    in.blockers.clear();
    in.sun_blockers.clear();
    if (frame.instances)
        for (const MeshInstance& inst : *frame.instances) {
            if (!inst.occluder || !inst.mesh) continue;
            in.blockers.push_back(geometry::transform_aabb(inst.mesh->bounds(), inst.world));
            if (inst.casts_shadow) in.sun_blockers.push_back(in.blockers.back());
        }
    contact_shadows_.clear();
    contact_shadows(*frame.shadow_casters, in, contact_shadows_);

    const geometry::Frustum frustum(frame.camera.projection() * frame.camera.view());
    contact_vertices_.clear();
    constexpr float kAboveFloor = 0.02f; // plus a polygon offset: never fights the floor for depth
    for (const ContactShadow& s : contact_shadows_) {
        const Vec3 along = Vec3(s.axis.x, 0.0f, s.axis.y) * s.half_length;
        const Vec3 across = Vec3(-s.axis.y, 0.0f, s.axis.x) * s.half_width;
        const Vec3 c = s.centre + Vec3(0.0f, kAboveFloor, 0.0f);
        const float reach = s.half_length + s.half_width;
        if (!frustum.intersects({c - Vec3(reach, 0.0f, reach), c + Vec3(reach, 0.0f, reach)})) continue;
        const Vec2 df(s.darkness, s.feet);
        const ContactVertex corners[4] = {{c - along - across, Vec2(-1, -1), df},
                                          {c + along - across, Vec2(1, -1), df},
                                          {c + along + across, Vec2(1, 1), df},
                                          {c - along + across, Vec2(-1, 1), df}};
        for (int k : {0, 1, 2, 0, 2, 3}) contact_vertices_.push_back(corners[k]);
    }
    if (contact_vertices_.empty()) return;
    stats.contact_shadows = static_cast<int>(contact_vertices_.size() / 6);

    contact_shadow_.use();
    const Mat4 view_projection = frame.camera.projection() * frame.camera.view();
    glUniformMatrix4fv(contact_shadow_.location("u_view_projection"), 1, GL_FALSE,
                       glm::value_ptr(view_projection));
    glBindVertexArray(contact_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, contact_buffer_);
    const auto bytes = static_cast<GLsizeiptr>(contact_vertices_.size() * sizeof(ContactVertex));
    glBufferData(GL_ARRAY_BUFFER, bytes, nullptr, GL_STREAM_DRAW); // orphan last frame's
    glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, contact_vertices_.data());
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_SRC_COLOR); // destination x the shadow's factor
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.0f, -4.0f);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(contact_vertices_.size()));
    ++stats.draw_calls;
    stats.triangles += static_cast<long long>(contact_vertices_.size() / 3);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO); // GL's default
}

} // namespace ks::render
