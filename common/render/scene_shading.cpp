// SceneRenderer's shaded draws: the full path (per-pixel PBR) and the fast path (baked light maps, per
// vertex lighting for models, optional depth pre-pass), each binding materials and lights per batch.
#include "render/scene_renderer.h"

#include "render/gpu_mesh.h"
#include "render/lightmap_texture.h"
#include "render/material.h"
#include "render/scene_renderer_units.h"
#include "render/texture_cache.h"

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <bit>

namespace ks::render {

using namespace scene_units;

void SceneRenderer::draw_batches(const Mat4& view_projection, const Vec3& eye, const SceneFrame& frame,
                                 FrameStats& stats, bool view_model) {
    upload_instances();
    pbr_.use();
    const Environment& env = frame.environment;
    glUniformMatrix4fv(pbr_.location("u_view_projection"), 1, GL_FALSE, glm::value_ptr(view_projection));
    glUniformMatrix4fv(pbr_.location("u_shadow_matrix"), 1, GL_FALSE, glm::value_ptr(shadow_matrix_));
    glUniform3fv(pbr_.location("u_camera_position"), 1, glm::value_ptr(eye));
    Vec3 to_sun = -glm::normalize(env.sun_direction);
    glUniform3fv(pbr_.location("u_sun_direction"), 1, glm::value_ptr(to_sun));
    Vec3 sun = env.sun_color * kLegacyLightScale;
    glUniform3fv(pbr_.location("u_sun_color"), 1, glm::value_ptr(sun));
    glUniform3fv(pbr_.location("u_sky_color"), 1, glm::value_ptr(env.sky_color));
    glUniform3fv(pbr_.location("u_ground_color"), 1, glm::value_ptr(env.ground_color));
    glUniform3fv(pbr_.location("u_fog_color"), 1, glm::value_ptr(env.fog_color));
    glUniform1f(pbr_.location("u_fog_density"), view_model ? 0.0f : env.fog_density);
    glUniform1f(pbr_.location("u_exposure"), env.exposure);
    glActiveTexture(GL_TEXTURE0 + kShadow);
    glBindTexture(GL_TEXTURE_2D, shadow_texture_);
    const bool shadows = settings_.shadows && shadow_texture_ != 0 && !view_model;

    const Material* bound_material = nullptr;
    std::uint32_t bound_mask = ~0u;
    const GLint loc_flags = pbr_.location("u_map_flags");
    const GLint loc_base = pbr_.location("u_base_factor"), loc_emissive = pbr_.location("u_emissive_factor");
    const GLint loc_mr = pbr_.location("u_metal_rough"), loc_bump = pbr_.location("u_bump_strength");
    for (const Batch& b : batches_) {
        if (b.material != bound_material) {
            const Material& m = *b.material;
            auto bind = [&](int unit, unsigned id, unsigned fallback) {
                glActiveTexture(GL_TEXTURE0 + unit);
                glBindTexture(GL_TEXTURE_2D, id ? id : fallback);
            };
            bind(kBase, m.base_map, textures_.white().id);
            bind(kNormal, m.normal_map, textures_.flat_normal().id);
            bind(kOrm, m.orm_map, textures_.white().id);
            bind(kEmissive, m.emissive_map, textures_.white().id);
            bind(kHeight, m.height_map, textures_.white().id);
            const bool detail = settings_.surface_detail;
            int flags = (m.normal_map && detail ? 1 : 0) | (m.orm_map ? 2 : 0) | (m.emissive_map ? 4 : 0) |
                        (m.height_map && detail ? 8 : 0) | (shadows ? 16 : 0);
            glUniform1i(loc_flags, flags);
            glUniform4fv(loc_base, 1, glm::value_ptr(m.base_factor));
            glUniform3fv(loc_emissive, 1, glm::value_ptr(m.emissive_factor));
            glUniform2f(loc_mr, m.metallic, m.roughness);
            glUniform1f(loc_bump, m.bump_strength);
            bound_material = b.material;
        }
        if (b.light_mask != bound_mask) {
            upload_lights(pbr_, b.light_mask, frame);
            bound_mask = b.light_mask;
        }
        cull_faces_for(b);
        draw_instanced(b, stats);
        stats.instances_drawn += b.count;
    }
    reset_face_culling();
}

void SceneRenderer::draw_instanced(const Batch& b, FrameStats& stats) {
    glBindVertexArray(b.mesh->vao());
    b.mesh->bind_instances(instance_buffer_, static_cast<size_t>(b.first) * sizeof(InstanceData));
    glDrawElementsInstanced(GL_TRIANGLES, b.mesh->index_count(), GL_UNSIGNED_INT, nullptr, b.count);
    ++stats.draw_calls;
    stats.triangles += static_cast<long long>(b.mesh->index_count() / 3) * b.count;
}

void SceneRenderer::cull_faces_for(const Batch& b) {
    // Bit 1: cull back faces; bit 2: front faces wind clockwise (a mirrored matrix), which also keeps
    // gl_FrontFacing true on a mirrored instance's fronts (pbr.frag turns the normal of back faces).
    const int wanted =
        (settings_.cull_single_sided && !b.material->double_sided ? 1 : 0) | (b.mirrored ? 2 : 0);
    if (wanted == face_culling_) return;
    if ((wanted & 1) != (face_culling_ & 1)) {
        if (wanted & 1)
            glEnable(GL_CULL_FACE);
        else
            glDisable(GL_CULL_FACE);
    }
    if ((wanted & 2) != (face_culling_ & 2)) glFrontFace(wanted & 2 ? GL_CW : GL_CCW);
    face_culling_ = wanted;
}

void SceneRenderer::reset_face_culling() {
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    face_culling_ = 0;
}

void SceneRenderer::upload_lights(const ShaderProgram& program, std::uint32_t light_mask,
                                  const SceneFrame& frame) {
    Vec4 pos[kMaxLightsPerDraw], color[kMaxLightsPerDraw], dir[kMaxLightsPerDraw];
    float inner[kMaxLightsPerDraw];
    int n = 0;
    for (std::uint32_t bits = light_mask; bits && n < kMaxLightsPerDraw; bits &= bits - 1) {
        int k = std::countr_zero(bits);
        const Light& l = (*frame.lights)[static_cast<size_t>(lights_in_view_[static_cast<size_t>(k)])];
        pos[n] = Vec4(l.position, l.range);
        color[n] = Vec4(l.color * l.intensity * kLegacyLightScale, l.type == Light::Type::Spot ? 1.0f : 0.0f);
        dir[n] = Vec4(glm::normalize(l.direction), l.cos_outer);
        inner[n] = std::max(l.cos_inner, l.cos_outer + 1e-3f);
        ++n;
    }
    glUniform1i(program.location("u_light_count"), n);
    if (n > 0) {
        glUniform4fv(program.location("u_light_position"), n, glm::value_ptr(pos[0]));
        glUniform4fv(program.location("u_light_color"), n, glm::value_ptr(color[0]));
        glUniform4fv(program.location("u_light_direction"), n, glm::value_ptr(dir[0]));
        glUniform1fv(program.location("u_light_inner"), n, inner);
    }
}

void SceneRenderer::draw_batches_fast(const geometry::Camera& camera, const SceneFrame& frame,
                                      FrameStats& stats, bool view_model) {
    upload_instances();
    const Environment& env = frame.environment;
    const Mat4 view_projection = camera.projection() * camera.view();
    const Vec3 to_sun = -glm::normalize(env.sun_direction);
    const Vec3 sun = env.sun_color * kLegacyLightScale;
    // Fog from the view depth (perspective only; orthographic views have no fog here).
    const bool fog = !view_model && !camera.orthographic();
    // The frame's uniforms, in every fast program (a uniform a program does not have is location -1, which
    // GL ignores): fast (any surface the others cannot draw), fast_level (baked level surfaces, no branches),
    // fast_level_lit (those a dynamic light reaches) and the six fast_model programs (models, where their
    // occlusion and metalness come from and their emissive lookup fixed at compile time).
    constexpr int kFirstModel = 3, kPrograms = kFirstModel + kFastModelPrograms;
    struct Locations {
        GLint flags, baked, receive, base, emissive, metal_rough;
    } loc[kPrograms];
    const ShaderProgram* programs[kPrograms] = {&fast_program_,  &fast_level_,    &fast_level_lit_,
                                                &fast_model_[0], &fast_model_[1], &fast_model_[2],
                                                &fast_model_[3], &fast_model_[4], &fast_model_[5]};
    for (int i = 0; i < kPrograms; ++i) {
        const ShaderProgram& p = *programs[i];
        p.use();
        glUniformMatrix4fv(p.location("u_view_projection"), 1, GL_FALSE, glm::value_ptr(view_projection));
        glUniformMatrix4fv(p.location("u_shadow_matrix"), 1, GL_FALSE, glm::value_ptr(shadow_matrix_));
        glUniform3fv(p.location("u_camera_position"), 1, glm::value_ptr(camera.position));
        glUniform3fv(p.location("u_sun_direction"), 1, glm::value_ptr(to_sun));
        glUniform3fv(p.location("u_sun_color"), 1, glm::value_ptr(sun));
        glUniform3fv(p.location("u_sky_color"), 1, glm::value_ptr(env.sky_color));
        glUniform3fv(p.location("u_ground_color"), 1, glm::value_ptr(env.ground_color));
        glUniform3fv(p.location("u_fog_color"), 1, glm::value_ptr(env.fog_color));
        glUniform1f(p.location("u_fog_density"), fog ? env.fog_density : 0.0f);
        glUniform1f(p.location("u_exposure"), env.exposure);
        glUniform1f(p.location("u_lightmap_range"), lightmap_encoding_range(settings_.lightmap_float));
        loc[i] = {p.location("u_map_flags"),       p.location("u_baked"),
                  p.location("u_receive_shadow"),  p.location("u_base_factor"),
                  p.location("u_emissive_factor"), p.location("u_metal_rough")};
    }
    glActiveTexture(GL_TEXTURE0 + kShadow);
    glBindTexture(GL_TEXTURE_2D, shadow_texture_);
    const bool shadows = settings_.shadows && shadow_texture_ != 0 && !view_model;

    // Depth pre-pass of the baked level geometry (walls, stairs: a few hundred triangles), position only,
    // pushed back by a polygon offset so that the shaded pass's own fragments still pass GL_LESS even if the
    // two programs round a vertex differently (and a model touching a wall wins the tie). The floors and
    // ceilings the eye stands over or under are left out (prepass_skips_floors): drawn last, against the
    // walls' depth, they are shaded only where visible anyway. Then models are shaded first (nearest
    // first), the level last: every level pixel and most model pixels are shaded once.
    const bool prepass = settings_.depth_prepass && !view_model;
    if (prepass) {
        shadow_.use();
        glUniformMatrix4fv(shadow_.location("u_light_view_projection"), 1, GL_FALSE,
                           glm::value_ptr(view_projection));
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0f, 2.0f);
        for (const Batch& b : batches_)
            if (b.lightmap != 0 && !(b.floor_or_ceiling && settings_.prepass_skips_floors))
                draw_instanced(b, stats);
        glDisable(GL_POLYGON_OFFSET_FILL);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }

    int current = -1; // index into programs
    const Material* bound_material = nullptr;
    unsigned bound_lightmap = ~0u;
    std::uint32_t bound_mask = ~0u;
    for (int pass = prepass ? 0 : 1; pass < 2; ++pass)
        for (const Batch& b : batches_) {
            // With the pre-pass: models (pass 0), then the level (pass 1); without it, one pass in distance
            // order.
            if (prepass && (b.lightmap != 0) != (pass == 1)) continue;
            const Material& m = *b.material;
            const bool baked = b.lightmap != 0;
            // Baked level surfaces read base colour x occlusion from one map (no ORM lookup per pixel).
            const bool occluded_base = baked && m.fast_base_map != 0 && settings_.fast_occluded_base;
            // fast_level draws a baked surface whose maps are base x occlusion (read raw) and the light map;
            // fast_level_lit the same when a dynamic light reaches it (the general fast program's baked
            // surfaces, rare, leave dynamic lights out).
            const bool level_program = baked && occluded_base && !m.emissive_map && raw_srgb_ &&
                                       !m.placeholder && settings_.fast_level_shader;
            const bool model_program = !baked && settings_.fast_model_shaders;
            // A model whose base map also carries its occlusion (rgb) and metalness (alpha): one lookup.
            const bool orm_in_base = !baked && m.fast_base_map != 0 && m.fast_metal_in_alpha && raw_srgb_ &&
                                     !m.placeholder && settings_.fast_occluded_base;
            const ModelOrm orm = orm_in_base ? ModelOrm::InBase : m.orm_map ? ModelOrm::Map : ModelOrm::None;
            const int program = level_program ? (b.light_mask != 0 ? 2 : 1)
                                : model_program
                                    ? kFirstModel + static_cast<int>(orm) + (m.emissive_map ? 3 : 0)
                                    : 0;
            if (program != current) {
                programs[program]->use();
                current = program;
                bound_material = nullptr;
                bound_lightmap = ~0u;
                bound_mask = ~0u;
            }
            const Locations& l = loc[program];
            if (b.material != bound_material || b.lightmap != bound_lightmap) {
                if (b.material != bound_material || (b.lightmap == 0) != (bound_lightmap == 0)) {
                    auto bind = [&](int unit, unsigned id, unsigned fallback) {
                        glActiveTexture(GL_TEXTURE0 + unit);
                        glBindTexture(GL_TEXTURE_2D, id ? id : fallback);
                    };
                    bind(kBase, occluded_base || orm_in_base ? m.fast_base_map : m.base_map,
                         textures_.white().id);
                    bind(kOrm, m.orm_map, textures_.white().id);
                    bind(kEmissive, m.emissive_map, textures_.white().id);
                    // The placeholder checker has no mipmaps (a mip filter would make it incomplete): it
                    // keeps its own nearest filtering and sRGB decode.
                    const unsigned sampler = m.placeholder ? 0u : fast_sampler_;
                    glBindSampler(kBase, sampler);
                    glBindSampler(kEmissive, sampler);
                    glUniform4fv(l.base, 1, glm::value_ptr(m.base_factor));
                    glUniform3fv(l.emissive, 1, glm::value_ptr(m.emissive_factor));
                    glUniform2f(l.metal_rough, occluded_base ? m.fast_metallic : m.metallic, m.roughness);
                }
                if (b.lightmap != bound_lightmap && b.lightmap != 0) {
                    glActiveTexture(GL_TEXTURE0 + kLightmap);
                    glBindTexture(GL_TEXTURE_2D, b.lightmap);
                }
                glUniform1i(l.flags, (m.orm_map && !occluded_base && !orm_in_base ? 2 : 0) |
                                         (m.emissive_map ? 4 : 0) | (baked ? 32 : 0) |
                                         (raw_srgb_ && !m.placeholder ? 64 : 0) | (orm_in_base ? 128 : 0));
                glUniform1i(l.baked, baked ? 1 : 0);
                glUniform1i(l.receive, shadows && !baked ? 1 : 0);
                bound_material = b.material;
                bound_lightmap = b.lightmap;
            }
            if ((b.lightmap == 0 || program == 2) && b.light_mask != bound_mask) {
                upload_lights(*programs[program], b.light_mask, frame);
                bound_mask = b.light_mask;
            }
            cull_faces_for(b);
            draw_instanced(b, stats);
            stats.instances_drawn += b.count;
        }
    reset_face_culling();
    glBindSampler(kBase, 0);
    glBindSampler(kEmissive, 0);
}

} // namespace ks::render
