// SceneRenderer's sun shadow map: redrawn only when the hash of the shadow casters and the sun changes.
#include "render/scene_renderer.h"

#include "render/gpu_mesh.h"

#include <epoxy/gl.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace ks::render {

std::uint64_t SceneRenderer::shadow_caster_hash(const std::vector<MeshInstance>& instances) const {
    // FNV-1a over what decides the shadow map: which meshes cast and where they are, plus the sun.
    std::uint64_t h = 1469598103934665603ULL;
    auto mix = [&h](const void* data, size_t size) {
        auto* bytes = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) h = (h ^ bytes[i]) * 1099511628211ULL;
    };
    for (const auto& inst : instances) {
        if (!casts_shadow(inst)) continue;
        mix(&inst.mesh, sizeof(inst.mesh));
        mix(glm::value_ptr(inst.world), sizeof(Mat4));
    }
    return h | 1; // never 0, which means "invalid"
}

void SceneRenderer::render_shadows(const SceneFrame& frame, FrameStats& stats) {
    if (!settings_.shadows || !frame.instances) return;
    std::uint64_t h = shadow_caster_hash(*frame.instances);
    Vec3 sun = glm::normalize(frame.environment.sun_direction);
    std::uint32_t sun_bits[3];
    std::memcpy(sun_bits, glm::value_ptr(sun), sizeof(sun_bits));
    h ^= (std::uint64_t(sun_bits[0]) << 32) ^ sun_bits[1] ^ (std::uint64_t(sun_bits[2]) << 16);
    h |= 1;
    if (h == shadow_hash_) return;
    shadow_hash_ = h;
    stats.shadow_rendered = true;

    // Fit an orthographic box around every caster, seen from the sun.
    instance_data_.clear();
    shadow_batches_.clear();
    geometry::Aabb bounds = geometry::Aabb::empty();
    shadow_order_.clear();
    for (const auto& inst : *frame.instances)
        if (casts_shadow(inst) && inst.mesh) {
            bounds = geometry::merge(bounds, geometry::transform_aabb(inst.mesh->bounds(), inst.world));
            shadow_order_.push_back(&inst);
        }
    if (!bounds.valid()) return;
    std::sort(shadow_order_.begin(), shadow_order_.end(),
              [](const MeshInstance* a, const MeshInstance* b) { return a->mesh < b->mesh; });
    for (size_t i = 0; i < shadow_order_.size();) {
        size_t j = i;
        while (j < shadow_order_.size() && shadow_order_[j]->mesh == shadow_order_[i]->mesh) {
            instance_data_.push_back({shadow_order_[j]->world, Vec4(0.0f)});
            ++j;
        }
        shadow_batches_.push_back({shadow_order_[i]->mesh, nullptr, 0, static_cast<int>(i),
                                   static_cast<int>(j - i), 0u, false, false});
        i = j;
    }
    Vec3 center = bounds.center();
    float radius = glm::length(bounds.extent()) + 1.0f;
    Vec3 up = std::abs(sun.y) > 0.99f ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
    Mat4 light_view = glm::lookAt(center - sun * radius, center, up);
    geometry::Aabb ls = geometry::transform_aabb(bounds, light_view);
    Mat4 light_proj = glm::ortho(ls.min.x, ls.max.x, ls.min.y, ls.max.y, -ls.max.z - 1.0f, -ls.min.z + 1.0f);
    Mat4 light_vp = light_proj * light_view;
    const Mat4 bias(0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 0.5f, 0, 0.5f, 0.5f, 0.5f, 1.0f);
    shadow_matrix_ = bias * light_vp;

    upload_instances();
    GLint previous_fbo = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_);
    glViewport(0, 0, settings_.shadow_map_size, settings_.shadow_map_size);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 4.0f);
    glDisable(GL_CULL_FACE);
    shadow_.use();
    glUniformMatrix4fv(shadow_.location("u_light_view_projection"), 1, GL_FALSE, glm::value_ptr(light_vp));
    for (const Batch& b : shadow_batches_) {
        draw_instanced(b, stats);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_fbo));
    glViewport(0, 0, internal_width_, internal_height_);
}

} // namespace ks::render
