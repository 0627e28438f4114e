// SceneRenderer's visibility pass: the lights in view, frustum and occluder culling, and the grouping of
// what remains into instanced batches, nearest first.
#include "render/scene_renderer.h"

#include "geometry/frustum.h"
#include "render/gpu_mesh.h"
#include "render/material.h"
#include "render/scene_renderer_units.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace ks::render {

using namespace scene_units;

void SceneRenderer::pick_lights(const SceneFrame& frame, FrameStats& stats) {
    lights_in_view_.clear();
    if (!frame.lights) return;
    geometry::Frustum frustum(frame.camera.projection() * frame.camera.view());
    for (size_t i = 0; i < frame.lights->size() && lights_in_view_.size() < kMaxLightsInView; ++i) {
        const Light& l = (*frame.lights)[i];
        if (l.intensity <= 0.0f || l.range <= 0.0f) continue;
        if (frustum.intersects_sphere(l.position, l.range)) lights_in_view_.push_back(static_cast<int>(i));
    }
    stats.lights_in_view = static_cast<int>(lights_in_view_.size());
}

namespace {
float distance_to_box(const Vec3& p, const geometry::Aabb& b) {
    Vec3 d = glm::max(glm::max(b.min - p, p - b.max), Vec3(0.0f));
    return glm::length(d);
}

// A box the eye stands over or under (it spans the eye's x and z): a floor or a ceiling of the room the eye
// is in, which can hide only what lies beyond its own plane.
bool eye_over_or_under(const Vec3& eye, const geometry::Aabb& b) {
    return eye.x >= b.min.x && eye.x <= b.max.x && eye.z >= b.min.z && eye.z <= b.max.z;
}
} // namespace

std::uint32_t SceneRenderer::light_mask(const SceneFrame& frame, const geometry::Aabb& box, int cap,
                                        bool dynamic_only) const {
    // The lights whose range reaches this box; keep the nearest `cap`.
    std::uint32_t mask = 0;
    float nearest[kMaxLightsPerDraw];
    int count = 0;
    int slot_of[kMaxLightsPerDraw];
    for (size_t k = 0; k < lights_in_view_.size(); ++k) {
        const Light& l = (*frame.lights)[static_cast<size_t>(lights_in_view_[k])];
        if (dynamic_only && !l.dynamic) continue;
        float d = distance_to_box(l.position, box);
        if (d >= l.range) continue;
        if (count < cap) {
            nearest[count] = d;
            slot_of[count++] = static_cast<int>(k);
            mask |= 1u << k;
        } else if (count > 0) {
            int worst = static_cast<int>(std::max_element(nearest, nearest + count) - nearest);
            if (d < nearest[worst]) {
                mask &= ~(1u << slot_of[worst]);
                nearest[worst] = d;
                slot_of[worst] = static_cast<int>(k);
                mask |= 1u << k;
            }
        }
    }
    return mask;
}

void SceneRenderer::cull_and_batch(const SceneFrame& frame, FrameStats& stats) {
    visible_.clear();
    batches_.clear();
    instance_data_.clear();
    const Vec3 eye = frame.camera.position;
    const bool view_model_pass = !view_world_.empty();
    const std::vector<MeshInstance>& source = view_model_pass ? view_world_ : *frame.instances;
    geometry::Frustum frustum(frame.camera.projection() * frame.camera.view());
    const int light_cap = std::clamp(settings_.max_lights_per_draw, 0, kMaxLightsPerDraw);
    // Fast path: the faces of the occluder boxes (walls, floors) in view that face the eye. What lies
    // entirely behind one of them is skipped: the rooms next door cost no vertex shading or binning.
    occluder_faces_.clear();
    const bool occlusion =
        fast_ && settings_.occlusion_culling && !view_model_pass && !frame.camera.orthographic();
    if (occlusion)
        for (const auto& inst : source)
            if (inst.occluder && inst.mesh) {
                geometry::Aabb local = inst.mesh->bounds();
                local.min += inst.occluder_inset;
                local.max -= inst.occluder_inset;
                geometry::Aabb box = geometry::transform_aabb(local, inst.world);
                if (frustum.intersects(box)) append_occluder_faces(box, eye, occluder_faces_);
            }
    if (occlusion) merge_occluder_faces(occluder_faces_);
    for (const auto& inst : source) {
        if (!inst.mesh || !inst.material) continue;
        geometry::Aabb box = geometry::transform_aabb(inst.mesh->bounds(), inst.world);
        if (!view_model_pass && !frustum.intersects(box)) {
            ++stats.instances_culled;
            continue;
        }
        if (occlusion &&
            std::any_of(occluder_faces_.begin(), occluder_faces_.end(),
                        [&](const OccluderFace& f) { return hidden_behind(box, f, frame.camera); })) {
            ++stats.instances_occluded;
            continue;
        }
        // A baked surface's level lights are in its light map: only dynamic lights (muzzle flashes) are
        // added to it.
        const bool baked = fast_ && inst.lightmap != 0;
        const std::uint32_t mask = light_mask(frame, box, light_cap, baked);
        visible_.push_back({&inst, distance_to_box(eye, box), mask, box, baked ? inst.lightmap : 0u,
                            baked && eye_over_or_under(eye, box), glm::determinant(Mat3(inst.world)) < 0.0f});
    }
    // Group identical (material, mesh, lights, handedness) together; each group is drawn at its nearest
    // member's distance.
    std::sort(visible_.begin(), visible_.end(), [](const Visible& a, const Visible& b) {
        if (a.instance->material->id != b.instance->material->id)
            return a.instance->material->id < b.instance->material->id;
        if (a.instance->mesh != b.instance->mesh) return a.instance->mesh < b.instance->mesh;
        if (a.light_mask != b.light_mask) return a.light_mask < b.light_mask;
        if (a.lightmap != b.lightmap) return a.lightmap < b.lightmap;
        if (a.floor_or_ceiling != b.floor_or_ceiling) return b.floor_or_ceiling;
        if (a.mirrored != b.mirrored) return b.mirrored;
        return a.distance < b.distance;
    });
    std::vector<float>& batch_distance = batch_distance_;
    batch_distance.clear();
    for (size_t i = 0; i < visible_.size();) {
        size_t j = i;
        const Visible& head = visible_[i];
        while (j < visible_.size() && visible_[j].instance->material == head.instance->material &&
               visible_[j].instance->mesh == head.instance->mesh &&
               visible_[j].light_mask == head.light_mask && visible_[j].lightmap == head.lightmap &&
               visible_[j].floor_or_ceiling == head.floor_or_ceiling && visible_[j].mirrored == head.mirrored)
            ++j;
        batches_.push_back({head.instance->mesh, head.instance->material, head.light_mask,
                            static_cast<int>(i), static_cast<int>(j - i), head.lightmap,
                            head.floor_or_ceiling, head.mirrored});
        batch_distance.push_back(head.distance);
        i = j;
    }
    // Nearest batch first (front to back); ties keep material order. Floors and ceilings after everything
    // else: in front of nothing the eye sees, so drawn last they are shaded only where nothing else covers
    // them (no overdraw under the walls, even without the pre-pass).
    order_.resize(batches_.size());
    for (size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
    std::stable_sort(order_.begin(), order_.end(), [&](int a, int b) {
        const bool floor_a = batches_[static_cast<size_t>(a)].floor_or_ceiling;
        const bool floor_b = batches_[static_cast<size_t>(b)].floor_or_ceiling;
        if (floor_a != floor_b) return floor_b;
        return batch_distance[a] < batch_distance[b];
    });
    sorted_batches_.clear();
    for (int b : order_) {
        Batch batch = batches_[static_cast<size_t>(b)];
        int first = static_cast<int>(instance_data_.size());
        for (int k = 0; k < batch.count; ++k) {
            const MeshInstance& inst = *visible_[static_cast<size_t>(batch.first + k)].instance;
            instance_data_.push_back({inst.world, Vec4(inst.emissive_scale, inst.tint)});
        }
        batch.first = first;
        sorted_batches_.push_back(batch);
    }
    batches_.swap(sorted_batches_);
}

void SceneRenderer::upload_instances() {
    glBindBuffer(GL_ARRAY_BUFFER, instance_buffer_);
    // Orphan then fill: the driver hands back fresh storage instead of waiting for last frame's draws.
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(instance_data_.capacity() * sizeof(InstanceData)),
                 nullptr, GL_STREAM_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(instance_data_.size() * sizeof(InstanceData)),
                    instance_data_.data());
}

} // namespace ks::render
