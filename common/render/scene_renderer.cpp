#include "render/scene_renderer.h"

#include "core/log.h"
#include "core/paths.h"
#include "render/gpu_mesh.h"
#include "render/lightmap_texture.h"
#include "render/material.h"
#include "render/shaders.h"
#include "render/texture_cache.h"

#include <epoxy/gl.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <tuple>

namespace ks::render {

int default_msaa_for(const std::string& gl_renderer) {
    return is_software_renderer(gl_renderer) ? 0 : 4;
}

RenderQuality default_quality_for(const std::string& gl_renderer) {
    if (const char* q = std::getenv("KS_RENDER_QUALITY"); q && *q) {
        if (std::strcmp(q, "full") == 0) return RenderQuality::Full;
        if (std::strcmp(q, "fast") == 0) return RenderQuality::Fast;
        log::warn("KS_RENDER_QUALITY='", q, "' is not 'full' or 'fast'; choosing from the GL renderer");
    }
    return is_software_renderer(gl_renderer) ? RenderQuality::Fast : RenderQuality::Full;
}

float default_render_scale_for(const std::string& gl_renderer, float software_scale) {
    if (const char* v = std::getenv("KS_RENDER_SCALE"); v && *v) {
        char* end = nullptr;
        float scale = std::strtof(v, &end);
        if (end != v && *end == '\0' && is_finite(scale) && scale > 0.0f)
            return std::clamp(scale, 0.25f, 1.0f);
        log::warn("KS_RENDER_SCALE='", v, "' is not a number in 0.25..1; choosing from the GL renderer");
    }
    return is_software_renderer(gl_renderer) ? std::clamp(software_scale, 0.25f, 1.0f) : 1.0f;
}

namespace {
enum TextureUnit { kBase = 0, kNormal, kOrm, kEmissive, kHeight, kShadow, kLightmap };
constexpr int kMaxLightsInView = 32;     // one bit each in a draw's light mask
constexpr float kLegacyLightScale = kPi; // three.js legacy light units (see pbr.frag)
} // namespace

Result<std::unique_ptr<SceneRenderer>> SceneRenderer::create(TextureCache& textures,
                                                             RendererSettings settings) {
    std::unique_ptr<SceneRenderer> r(new SceneRenderer(textures, settings));
    if (auto ok = r->init(); !ok) return ok.error();
    return r;
}

void SceneRenderer::resolve_settings() {
    if (settings_.quality == RenderQuality::Auto) settings_.quality = default_quality_for(gl_renderer_);
    fast_ = settings_.quality == RenderQuality::Fast;
    if (!(settings_.render_scale > 0.0f) || !is_finite(settings_.render_scale))
        settings_.render_scale = default_render_scale_for(gl_renderer_, settings_.software_render_scale);
    settings_.render_scale = std::clamp(settings_.render_scale, 0.25f, 1.0f);
}

void SceneRenderer::set_quality(RenderQuality quality) {
    settings_.quality = quality;
    resolve_settings();
    shadow_hash_ = 0; // the fast path's shadow map holds fewer casters
}

void SceneRenderer::set_render_scale(float scale) {
    settings_.render_scale = scale;
    resolve_settings();
}

int SceneRenderer::poll_shaders(bool force) {
    return shaders_ ? shaders_->poll(ShaderLibrary::Clock::now(), force) : 0;
}

unsigned SceneRenderer::program_id(const std::string& name) const {
    if (name == "pbr") return pbr_.id();
    if (name == "fast") return fast_program_.id();
    if (name == "fast_level") return fast_level_.id();
    if (name == "shadow") return shadow_.id();
    if (name == "particle") return particle_.id();
    if (name == "line") return line_.id();
    return 0;
}

Result<void> SceneRenderer::init() {
    if (const GLubyte* r = glGetString(GL_RENDERER)) gl_renderer_ = reinterpret_cast<const char*>(r);
    resolve_settings();
    if (settings_.shader_hot_reload < 0) settings_.shader_hot_reload = default_shader_hot_reload() ? 1 : 0;
    shaders_ = std::make_unique<ShaderLibrary>(
        settings_.shader_dir.empty() ? default_shader_dir() : std::filesystem::path(settings_.shader_dir));
    // Sampler units are program state: set again whenever hot reload rebuilds a program.
    auto pbr_units = [](ShaderProgram& p) {
        glUniform1i(p.location("u_base_map"), kBase);
        glUniform1i(p.location("u_normal_map"), kNormal);
        glUniform1i(p.location("u_orm_map"), kOrm);
        glUniform1i(p.location("u_emissive_map"), kEmissive);
        glUniform1i(p.location("u_height_map"), kHeight);
        glUniform1i(p.location("u_shadow_map"), kShadow);
        glUniform1i(p.location("u_lightmap"), kLightmap);
    };
    auto particle_units = [](ShaderProgram& p) { glUniform1i(p.location("u_sprite"), 0); };
    for (auto [files, target, units] :
         {std::tuple{&pbr_program(), &pbr_, std::function<void(ShaderProgram&)>(pbr_units)},
          std::tuple{&fast_program(), &fast_program_, std::function<void(ShaderProgram&)>(pbr_units)},
          std::tuple{&fast_level_program(), &fast_level_, std::function<void(ShaderProgram&)>(pbr_units)},
          std::tuple{&shadow_program(), &shadow_, std::function<void(ShaderProgram&)>()},
          std::tuple{&particle_program(), &particle_, std::function<void(ShaderProgram&)>(particle_units)},
          std::tuple{&line_program(), &line_, std::function<void(ShaderProgram&)>()}})
        if (auto r = shaders_->add(*files, *target, units); !r) return r.error();

    glGenBuffers(1, &instance_buffer_);

    // The fast path samples colour maps with the nearest mip (one bilinear lookup instead of two; trilinear
    // with settings_.fast_trilinear) and, where the driver allows, without the sampler's per-texel sRGB
    // decode (the shader squares instead): texture lookups are most of a software rasteriser's pixel cost.
    glGenSamplers(1, &fast_sampler_);
    glSamplerParameteri(fast_sampler_, GL_TEXTURE_MIN_FILTER,
                        settings_.fast_trilinear ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_NEAREST);
    glSamplerParameteri(fast_sampler_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(fast_sampler_, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glSamplerParameteri(fast_sampler_, GL_TEXTURE_WRAP_T, GL_REPEAT);
    raw_srgb_ = epoxy_has_gl_extension("GL_EXT_texture_sRGB_decode");
    if (raw_srgb_) glSamplerParameteri(fast_sampler_, GL_TEXTURE_SRGB_DECODE_EXT, GL_SKIP_DECODE_EXT);

    // Particles: a unit quad (per vertex) plus a per-particle stream.
    const float quad[] = {-0.5f, -0.5f, 0.5f, -0.5f, 0.5f, 0.5f, -0.5f, -0.5f, 0.5f, 0.5f, -0.5f, 0.5f};
    glGenVertexArrays(1, &particle_vao_);
    glGenBuffers(1, &particle_quad_);
    glGenBuffers(1, &particle_buffer_);
    glBindVertexArray(particle_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, particle_quad_);
    glBufferData(GL_ARRAY_BUFFER, sizeof(quad), quad, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, particle_buffer_);
    for (GLuint i = 1; i <= 3; ++i) {
        glEnableVertexAttribArray(i);
        glVertexAttribDivisor(i, 1);
    }
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(ParticleVertex), nullptr);
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, sizeof(ParticleVertex),
                          reinterpret_cast<void*>(sizeof(Vec4)));
    glVertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, sizeof(ParticleVertex),
                          reinterpret_cast<void*>(2 * sizeof(Vec4)));

    glGenVertexArrays(1, &line_vao_);
    glGenBuffers(1, &line_buffer_);
    glBindVertexArray(line_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, line_buffer_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(DebugVertex), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(DebugVertex),
                          reinterpret_cast<void*>(sizeof(Vec3)));
    glBindVertexArray(0);

    if (settings_.shadows) {
        settings_.shadow_map_size = std::clamp(settings_.shadow_map_size, 256, 8192);
        glGenTextures(1, &shadow_texture_);
        glBindTexture(GL_TEXTURE_2D, shadow_texture_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, settings_.shadow_map_size,
                     settings_.shadow_map_size, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
        // Hardware comparison with linear filtering: 2x2 PCF for the price of one fetch.
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        glGenFramebuffers(1, &shadow_fbo_);
        glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow_texture_, 0);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            log::warn("shadow map framebuffer incomplete (status ", status,
                      "); rendering without sun shadows");
            settings_.shadows = false;
        }
    }
    return ok();
}

SceneRenderer::~SceneRenderer() {
    glDeleteBuffers(1, &instance_buffer_);
    glDeleteBuffers(1, &particle_quad_);
    glDeleteBuffers(1, &particle_buffer_);
    glDeleteBuffers(1, &line_buffer_);
    glDeleteVertexArrays(1, &particle_vao_);
    glDeleteVertexArrays(1, &line_vao_);
    if (shadow_fbo_) glDeleteFramebuffers(1, &shadow_fbo_);
    if (shadow_texture_) glDeleteTextures(1, &shadow_texture_);
    if (fast_sampler_) glDeleteSamplers(1, &fast_sampler_);
}

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

void SceneRenderer::pick_lights(const SceneFrame& frame, FrameStats& stats) {
    lights_in_view_.clear();
    if (!frame.lights) return;
    Frustum frustum(frame.camera.projection() * frame.camera.view());
    for (size_t i = 0; i < frame.lights->size() && lights_in_view_.size() < kMaxLightsInView; ++i) {
        const Light& l = (*frame.lights)[i];
        if (l.intensity <= 0.0f || l.range <= 0.0f) continue;
        if (frustum.intersects_sphere(l.position, l.range)) lights_in_view_.push_back(static_cast<int>(i));
    }
    stats.lights_in_view = static_cast<int>(lights_in_view_.size());
}

namespace {
float distance_to_box(const Vec3& p, const Aabb& b) {
    Vec3 d = glm::max(glm::max(b.min - p, p - b.max), Vec3(0.0f));
    return glm::length(d);
}
} // namespace

void SceneRenderer::cull_and_batch(const SceneFrame& frame, FrameStats& stats) {
    visible_.clear();
    batches_.clear();
    instance_data_.clear();
    const Vec3 eye = frame.camera.position;
    const bool view_model_pass = !view_world_.empty();
    const std::vector<MeshInstance>& source = view_model_pass ? view_world_ : *frame.instances;
    Frustum frustum(frame.camera.projection() * frame.camera.view());
    const int light_cap = std::clamp(settings_.max_lights_per_draw, 0, kMaxLightsPerDraw);
    // Fast path: the faces of the occluder boxes (walls, floors) in view that face the eye. What lies
    // entirely behind one of them is skipped: the rooms next door cost no vertex shading or binning.
    occluder_faces_.clear();
    const bool occlusion =
        fast_ && settings_.occlusion_culling && !view_model_pass && !frame.camera.orthographic();
    if (occlusion)
        for (const auto& inst : source)
            if (inst.occluder && inst.mesh) {
                Aabb local = inst.mesh->bounds();
                local.min += inst.occluder_inset;
                local.max -= inst.occluder_inset;
                Aabb box = transform_aabb(local, inst.world);
                if (frustum.intersects(box)) append_occluder_faces(box, eye, occluder_faces_);
            }
    if (occlusion) merge_occluder_faces(occluder_faces_);
    for (const auto& inst : source) {
        if (!inst.mesh || !inst.material) continue;
        Aabb box = transform_aabb(inst.mesh->bounds(), inst.world);
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
        if (fast_ && inst.lightmap != 0) { // its light is baked: no light list
            visible_.push_back({&inst, distance_to_box(eye, box), 0u, box, inst.lightmap});
            continue;
        }
        // The lights whose range reaches this box; keep the nearest light_cap.
        std::uint32_t mask = 0;
        float nearest[kMaxLightsPerDraw];
        int count = 0;
        int slot_of[kMaxLightsPerDraw];
        for (size_t k = 0; k < lights_in_view_.size(); ++k) {
            const Light& l = (*frame.lights)[static_cast<size_t>(lights_in_view_[k])];
            float d = distance_to_box(l.position, box);
            if (d >= l.range) continue;
            if (count < light_cap) {
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
        visible_.push_back({&inst, distance_to_box(eye, box), mask, box, 0u});
    }
    // Group identical (material, mesh, lights) together; each group is drawn at its nearest member's
    // distance.
    std::sort(visible_.begin(), visible_.end(), [](const Visible& a, const Visible& b) {
        if (a.instance->material->id != b.instance->material->id)
            return a.instance->material->id < b.instance->material->id;
        if (a.instance->mesh != b.instance->mesh) return a.instance->mesh < b.instance->mesh;
        if (a.light_mask != b.light_mask) return a.light_mask < b.light_mask;
        if (a.lightmap != b.lightmap) return a.lightmap < b.lightmap;
        return a.distance < b.distance;
    });
    std::vector<float>& batch_distance = batch_distance_;
    batch_distance.clear();
    for (size_t i = 0; i < visible_.size();) {
        size_t j = i;
        const Visible& head = visible_[i];
        while (j < visible_.size() && visible_[j].instance->material == head.instance->material &&
               visible_[j].instance->mesh == head.instance->mesh &&
               visible_[j].light_mask == head.light_mask && visible_[j].lightmap == head.lightmap)
            ++j;
        batches_.push_back({head.instance->mesh, head.instance->material, head.light_mask,
                            static_cast<int>(i), static_cast<int>(j - i), head.lightmap});
        batch_distance.push_back(head.distance);
        i = j;
    }
    // Nearest batch first (front to back); ties keep material order.
    order_.resize(batches_.size());
    for (size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
    std::stable_sort(order_.begin(), order_.end(),
                     [&](int a, int b) { return batch_distance[a] < batch_distance[b]; });
    sorted_batches_.clear();
    for (int b : order_) {
        Batch batch = batches_[static_cast<size_t>(b)];
        int first = static_cast<int>(instance_data_.size());
        for (int k = 0; k < batch.count; ++k) {
            const MeshInstance& inst = *visible_[static_cast<size_t>(batch.first + k)].instance;
            instance_data_.push_back({inst.world, Vec4(inst.emissive_scale, 0, 0, 0)});
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
    Aabb bounds = empty_aabb();
    shadow_order_.clear();
    for (const auto& inst : *frame.instances)
        if (casts_shadow(inst) && inst.mesh) {
            bounds = merge(bounds, transform_aabb(inst.mesh->bounds(), inst.world));
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
        shadow_batches_.push_back(
            {shadow_order_[i]->mesh, nullptr, 0, static_cast<int>(i), static_cast<int>(j - i), 0u});
        i = j;
    }
    Vec3 center = bounds.center();
    float radius = glm::length(bounds.extent()) + 1.0f;
    Vec3 up = std::abs(sun.y) > 0.99f ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
    Mat4 light_view = glm::lookAt(center - sun * radius, center, up);
    Aabb ls = transform_aabb(bounds, light_view);
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
        draw_instanced(b, stats);
        stats.instances_drawn += b.count;
    }
}

void SceneRenderer::draw_instanced(const Batch& b, FrameStats& stats) {
    glBindVertexArray(b.mesh->vao());
    b.mesh->bind_instances(instance_buffer_, static_cast<size_t>(b.first) * sizeof(InstanceData));
    glDrawElementsInstanced(GL_TRIANGLES, b.mesh->index_count(), GL_UNSIGNED_INT, nullptr, b.count);
    ++stats.draw_calls;
    stats.triangles += static_cast<long long>(b.mesh->index_count() / 3) * b.count;
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

void SceneRenderer::draw_batches_fast(const Camera& camera, const SceneFrame& frame, FrameStats& stats,
                                      bool view_model) {
    upload_instances();
    const Environment& env = frame.environment;
    const Mat4 view_projection = camera.projection() * camera.view();
    const Vec3 to_sun = -glm::normalize(env.sun_direction);
    const Vec3 sun = env.sun_color * kLegacyLightScale;
    // Fog from the depth buffer's value (perspective only; orthographic views have no fog here).
    const bool fog = !view_model && !camera.orthographic();
    const float n = camera.near_plane, f = camera.far_plane;
    // The frame's uniforms, in both fast programs (a uniform a program does not have is location -1, which
    // GL ignores): fast (models, and any surface fast_level cannot draw) and fast_level (baked level
    // surfaces, no branches).
    struct Locations {
        GLint flags, baked, receive, base, emissive, metal_rough;
    } loc[2];
    const ShaderProgram* programs[2] = {&fast_program_, &fast_level_};
    for (int i = 0; i < 2; ++i) {
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
        glUniform2f(p.location("u_depth_to_view"), n * f / (f - n), f / (f - n));
        glUniform1f(p.location("u_exposure"), env.exposure);
        glUniform1f(p.location("u_lightmap_range"), lightmap_encoding_range());
        loc[i] = {p.location("u_map_flags"),       p.location("u_baked"),
                  p.location("u_receive_shadow"),  p.location("u_base_factor"),
                  p.location("u_emissive_factor"), p.location("u_metal_rough")};
    }
    glActiveTexture(GL_TEXTURE0 + kShadow);
    glBindTexture(GL_TEXTURE_2D, shadow_texture_);
    const bool shadows = settings_.shadows && shadow_texture_ != 0 && !view_model;

    // Depth pre-pass of the baked level geometry (walls, floors, stairs: a few hundred triangles), position
    // only, pushed back by a polygon offset so that the shaded pass's own fragments still pass GL_LESS
    // even if the two programs round a vertex differently (and a model touching a wall wins the tie). Then
    // models are shaded first (nearest first), the level last: every level pixel and most model pixels are
    // shaded once.
    const bool prepass = settings_.depth_prepass && !view_model;
    if (prepass) {
        shadow_.use();
        glUniformMatrix4fv(shadow_.location("u_light_view_projection"), 1, GL_FALSE,
                           glm::value_ptr(view_projection));
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0f, 2.0f);
        for (const Batch& b : batches_)
            if (b.lightmap != 0) draw_instanced(b, stats);
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
            // fast_level draws a baked surface whose maps are base x occlusion (read raw) and the light map.
            const int program = baked && occluded_base && !m.emissive_map && raw_srgb_ && !m.placeholder &&
                                        settings_.fast_level_shader
                                    ? 1
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
                    bind(kBase, occluded_base ? m.fast_base_map : m.base_map, textures_.white().id);
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
                glUniform1i(l.flags, (m.orm_map && !occluded_base ? 2 : 0) | (m.emissive_map ? 4 : 0) |
                                         (baked ? 32 : 0) | (raw_srgb_ && !m.placeholder ? 64 : 0));
                glUniform1i(l.baked, baked ? 1 : 0);
                glUniform1i(l.receive, shadows && !baked ? 1 : 0);
                bound_material = b.material;
                bound_lightmap = b.lightmap;
            }
            if (b.lightmap == 0 && b.light_mask != bound_mask) {
                upload_lights(*programs[program], b.light_mask, frame);
                bound_mask = b.light_mask;
            }
            draw_instanced(b, stats);
            stats.instances_drawn += b.count;
        }
    glBindSampler(kBase, 0);
    glBindSampler(kEmissive, 0);
}

void SceneRenderer::draw_particles(const SceneFrame& frame, FrameStats& stats) {
    if (!frame.particles || frame.particles->empty()) return;
    particle_.use();
    const Mat4 view = frame.camera.view(), proj = frame.camera.projection();
    glUniformMatrix4fv(particle_.location("u_view"), 1, GL_FALSE, glm::value_ptr(view));
    glUniformMatrix4fv(particle_.location("u_projection"), 1, GL_FALSE, glm::value_ptr(proj));
    glEnable(GL_BLEND);
    glDepthMask(GL_FALSE);
    glBindVertexArray(particle_vao_);
    glActiveTexture(GL_TEXTURE0);
    for (const ParticleEmitter* emitter : *frame.particles) {
        if (!emitter || emitter->particles().empty()) continue;
        const auto& ps = emitter->particles();
        particle_vertices_.clear();
        particle_order_.clear();
        for (size_t i = 0; i < ps.size(); ++i)
            particle_order_.push_back({(view * Vec4(ps[i].position, 1.0f)).z, static_cast<int>(i)});
        const bool alpha = emitter->params().blend == ParticleBlend::Alpha;
        if (alpha) // back to front: most negative view-space z first
            std::sort(particle_order_.begin(), particle_order_.end(),
                      [](auto& a, auto& b) { return a.first < b.first; });
        for (auto [z, i] : particle_order_) {
            const Particle& p = ps[static_cast<size_t>(i)];
            particle_vertices_.push_back({Vec4(p.position, p.current_size), p.color, p.rotation});
        }
        auto it = sprite_ids_.find(emitter->params().texture);
        if (it == sprite_ids_.end()) {
            const Texture& t = textures_.get(
                paths::asset("textures/particles/" + emitter->params().texture + ".png"), ColorSpace::Srgb);
            it = sprite_ids_.emplace(emitter->params().texture, t.id).first;
        }
        glBindTexture(GL_TEXTURE_2D, it->second);
        glBlendFunc(GL_ONE, alpha ? GL_ONE_MINUS_SRC_ALPHA : GL_ONE);
        glBindBuffer(GL_ARRAY_BUFFER, particle_buffer_);
        glBufferData(GL_ARRAY_BUFFER,
                     static_cast<GLsizeiptr>(particle_vertices_.size() * sizeof(ParticleVertex)),
                     particle_vertices_.data(), GL_STREAM_DRAW);
        glDrawArraysInstanced(GL_TRIANGLES, 0, 6, static_cast<GLsizei>(particle_vertices_.size()));
        ++stats.draw_calls;
        stats.triangles += 2 * static_cast<long long>(particle_vertices_.size());
    }
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

void SceneRenderer::draw_debug(const SceneFrame& frame, FrameStats& stats) {
    if (!frame.debug || frame.debug->vertices().empty()) return;
    const auto& v = frame.debug->vertices();
    line_.use();
    Mat4 vp = frame.camera.projection() * frame.camera.view();
    glUniformMatrix4fv(line_.location("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
    glBindVertexArray(line_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, line_buffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(DebugVertex)), v.data(),
                 GL_STREAM_DRAW);
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(v.size()));
    ++stats.draw_calls;
}

void SceneRenderer::ensure_msaa_target(int width, int height) {
    if (!msaa_target_ || msaa_target_->format().samples != settings_.msaa_samples)
        msaa_target_ = std::make_unique<RenderTarget>(
            RenderTargetFormat{ColourStorage::Renderbuffer, settings_.msaa_samples});
    if (auto made = msaa_target_->ensure(width, height); !made) {
        log::warn("MSAA ", settings_.msaa_samples, "x framebuffer unsupported; rendering without MSAA");
        settings_.msaa_samples = 0;
    }
}

void SceneRenderer::ensure_scale_target(int width, int height) {
    if (auto made = scale_target_.ensure(width, height); !made) {
        log::warn("render scale ", settings_.render_scale, ": offscreen target unsupported; full resolution");
        settings_.render_scale = 1.0f;
    }
}

FrameStats SceneRenderer::render(const SceneFrame& frame) {
    FrameStats stats;
    if (settings_.shader_hot_reload > 0) poll_shaders();
    GLint target_fbo = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target_fbo);
    // The 3D scene's own resolution; a smaller one is scaled up into the target at the end.
    const float scale = settings_.render_scale;
    internal_width_ = std::max(1, static_cast<int>(std::lround(frame.width * scale)));
    internal_height_ = std::max(1, static_cast<int>(std::lround(frame.height * scale)));
    bool scaled = internal_width_ != frame.width || internal_height_ != frame.height;
    if (scaled) {
        ensure_scale_target(internal_width_, internal_height_);
        if (settings_.render_scale >= 1.0f) { // the target failed: draw at full size
            scaled = false;
            internal_width_ = frame.width;
            internal_height_ = frame.height;
        }
    }
    stats.internal_width = internal_width_;
    stats.internal_height = internal_height_;
    stats.fast_path = fast_;
    render_shadows(frame, stats);
    if (settings_.msaa_samples > 0) ensure_msaa_target(internal_width_, internal_height_);
    if (settings_.msaa_samples > 0)
        msaa_target_->bind();
    else if (scaled)
        scale_target_.bind();
    glViewport(0, 0, internal_width_, internal_height_);
    const Vec3 fog_srgb =
        frame.environment.fog_color; // the clear shows the fog colour, encoded like the shader
    auto encode = [](float c) {
        return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    };
    glClearColor(encode(fog_srgb.r), encode(fog_srgb.g), encode(fog_srgb.b), 1.0f);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE); // level slabs are seen from both sides in the editor; models are not all closed
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    if (frame.instances) {
        pick_lights(frame, stats);
        view_world_.clear();
        cull_and_batch(frame, stats);
        if (fast_)
            draw_batches_fast(frame.camera, frame, stats, false);
        else
            draw_batches(frame.camera.projection() * frame.camera.view(), frame.camera.position, frame, stats,
                         false);
    }
    draw_particles(frame, stats);
    draw_debug(frame, stats);

    if (frame.view_model && !frame.view_model->instances.empty()) {
        // The view model: camera space -> world (so scene lights reach it), its own near plane and a
        // cleared depth buffer so it never sinks into walls.
        const Mat4 camera_to_world = glm::inverse(frame.camera.view());
        for (const auto& inst : frame.view_model->instances) {
            MeshInstance w = inst;
            w.world = camera_to_world * inst.world;
            view_world_.push_back(w);
        }
        glClear(GL_DEPTH_BUFFER_BIT);
        cull_and_batch(frame, stats);
        Camera vm = frame.camera;
        vm.near_plane = 0.01f;
        vm.far_plane = 20.0f;
        vm.fov_y = frame.view_model->fov_y;
        if (fast_)
            draw_batches_fast(vm, frame, stats, true);
        else
            draw_batches(vm.projection() * vm.view(), vm.position, frame, stats, true);
        view_world_.clear();
    }

    if (settings_.msaa_samples > 0) {
        // Resolve (same size), then scale up if the scene was drawn smaller.
        msaa_target_->blit_to(scaled ? scale_target_.framebuffer() : static_cast<GLuint>(target_fbo),
                              internal_width_, internal_height_, false);
    }
    if (scaled) scale_target_.blit_to(static_cast<GLuint>(target_fbo), frame.width, frame.height, true);
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target_fbo));
    glViewport(0, 0, frame.width, frame.height);
    glBindVertexArray(0);
    glUseProgram(0);
    glActiveTexture(GL_TEXTURE0);
    glDepthMask(GL_TRUE);
    return stats;
}

} // namespace ks::render
