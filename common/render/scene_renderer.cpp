#include "render/scene_renderer.h"

#include "core/log.h"
#include "render/scene_renderer_units.h"
#include "render/shaders.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <tuple>

namespace ks::render {

using namespace scene_units;

Result<std::unique_ptr<SceneRenderer>> SceneRenderer::create(TextureCache& textures,
                                                             RendererSettings settings) {
    std::unique_ptr<SceneRenderer> r(new SceneRenderer(textures, settings));
    if (auto ok = r->init(); !ok) return ok.error();
    return r;
}

void SceneRenderer::resolve_settings() {
    if (settings_.quality == RenderQuality::Auto)
        settings_.quality = settings_.automatic_quality != RenderQuality::Auto
                                ? settings_.automatic_quality
                                : default_quality_for(gl_renderer_);
    fast_ = settings_.quality == RenderQuality::Fast;
    if (!(settings_.render_scale > 0.0f) || !is_finite(settings_.render_scale))
        settings_.render_scale =
            settings_.automatic_render_scale > 0.0f
                ? settings_.automatic_render_scale
                : default_render_scale_for(gl_renderer_, settings_.software_render_scale);
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
    if (name == "fast_level_lit") return fast_level_lit_.id();
    for (int i = 0; i < kFastModelPrograms; ++i)
        if (name == fast_model_program(i).name) return fast_model_[i].id();
    if (name == "shadow") return shadow_.id();
    if (name == "particle") return particle_.id();
    if (name == "line") return line_.id();
    if (name == "contact_shadow") return contact_shadow_.id();
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
          std::tuple{&fast_level_lit_program(), &fast_level_lit_,
                     std::function<void(ShaderProgram&)>(pbr_units)},
          std::tuple{&shadow_program(), &shadow_, std::function<void(ShaderProgram&)>()},
          std::tuple{&particle_program(), &particle_, std::function<void(ShaderProgram&)>(particle_units)},
          std::tuple{&line_program(), &line_, std::function<void(ShaderProgram&)>()},
          std::tuple{&contact_shadow_program(), &contact_shadow_, std::function<void(ShaderProgram&)>()}})
        if (auto r = shaders_->add(*files, *target, units); !r) return r.error();
    for (int i = 0; i < kFastModelPrograms; ++i)
        if (auto r = shaders_->add(fast_model_program(i), fast_model_[i], pbr_units); !r) return r.error();
    for (auto [files, program] : {std::pair{&view_model_composite_program(), &view_model_layer_.program()},
                                  std::pair{&view_model_mask_program(), &view_model_layer_.mask_program()}})
        if (auto r = shaders_->add(*files, *program,
                                   [](ShaderProgram& p) { glUniform1i(p.location("u_layer"), 0); });
            !r)
            return r.error();

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

    glGenVertexArrays(1, &contact_vao_);
    glGenBuffers(1, &contact_buffer_);
    glBindVertexArray(contact_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, contact_buffer_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(ContactVertex), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, sizeof(ContactVertex),
                          reinterpret_cast<void*>(offsetof(ContactVertex, ellipse)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(ContactVertex),
                          reinterpret_cast<void*>(offsetof(ContactVertex, darkness_feet)));
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
    glDeleteBuffers(1, &contact_buffer_);
    glDeleteVertexArrays(1, &contact_vao_);
    glDeleteVertexArrays(1, &particle_vao_);
    glDeleteVertexArrays(1, &line_vao_);
    if (shadow_fbo_) glDeleteFramebuffers(1, &shadow_fbo_);
    if (shadow_texture_) glDeleteTextures(1, &shadow_texture_);
    if (fast_sampler_) glDeleteSamplers(1, &fast_sampler_);
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

geometry::Camera SceneRenderer::view_model_camera(const SceneFrame& frame) const {
    geometry::Camera vm = frame.camera;
    vm.near_plane = 0.01f;
    vm.far_plane = 20.0f;
    vm.fov_y = frame.view_model->fov_y;
    return vm;
}

void SceneRenderer::draw_view_model(const SceneFrame& frame, FrameStats& stats) {
    // Camera space -> world (so scene lights reach it), its own near plane and a cleared depth buffer so it
    // never sinks into walls.
    const Mat4 camera_to_world = glm::inverse(frame.camera.view());
    for (const auto& inst : frame.view_model->instances) {
        MeshInstance w = inst;
        w.world = camera_to_world * inst.world;
        view_world_.push_back(w);
    }
    glClear(GL_DEPTH_BUFFER_BIT);
    cull_and_batch(frame, stats);
    const geometry::Camera vm = view_model_camera(frame);
    if (fast_)
        draw_batches_fast(vm, frame, stats, true);
    else
        draw_batches(vm.projection() * vm.view(), vm.position, frame, stats, true);
    view_world_.clear();
}

SceneRenderer::LayerState SceneRenderer::draw_view_model_into_layer(const SceneFrame& frame,
                                                                    FrameStats& stats) {
    ScreenFootprint& where = view_model_footprint_;
    view_model_footprint(frame.view_model->instances, view_model_camera(frame).projection(), frame.width,
                         frame.height, where);
    if (where.rect.empty()) return LayerState::Empty;
    if (auto begun =
            view_model_layer_.begin(frame.width, frame.height, settings_.view_model_msaa, where.rect);
        !begun) {
        log::warn("view model MSAA ", settings_.view_model_msaa, "x layer unsupported (",
                  begun.error().message, "); drawing it without antialiasing");
        settings_.view_model_msaa = 0;
        glDisable(GL_SCISSOR_TEST);
        return LayerState::Unsupported;
    }
    draw_view_model(frame, stats);
    glDisable(GL_SCISSOR_TEST); // begin left it on the footprint for the view model's draws
    return LayerState::Drawn;
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
    // The view model: in the scene's target when that is multisampled at full size, else in its own
    // antialiased layer composited over the finished scene. At the target's size without MSAA the layer is
    // drawn first and its opaque pixels masked in the scene's depth, so the scene is not shaded under it.
    const bool view_model = frame.view_model && !frame.view_model->instances.empty();
    const bool view_model_layer =
        view_model && settings_.view_model_msaa > 0 && (settings_.msaa_samples == 0 || scaled);
    const bool layer_first =
        view_model_layer && !scaled && settings_.msaa_samples == 0 && settings_.view_model_depth_mask;
    if (frame.instances) pick_lights(frame, stats);
    LayerState layer = LayerState::Empty;
    if (layer_first) layer = draw_view_model_into_layer(frame, stats);
    if (settings_.msaa_samples > 0) ensure_msaa_target(internal_width_, internal_height_);
    if (settings_.msaa_samples > 0)
        msaa_target_->bind();
    else if (scaled)
        scale_target_.bind();
    else
        glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target_fbo));
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
    reset_face_culling(); // level slabs are seen from both sides; single-sided materials cull per batch
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (layer == LayerState::Drawn)
        view_model_layer_.write_depth_mask(static_cast<unsigned>(target_fbo), view_model_footprint_);

    if (frame.instances) {
        view_world_.clear();
        cull_and_batch(frame, stats);
        if (fast_)
            draw_batches_fast(frame.camera, frame, stats, false);
        else
            draw_batches(frame.camera.projection() * frame.camera.view(), frame.camera.position, frame, stats,
                         false);
        draw_contact_shadows(frame, stats);
    }
    draw_particles(frame, stats);
    draw_debug(frame, stats);
    if (view_model && !view_model_layer) draw_view_model(frame, stats);

    if (settings_.msaa_samples > 0) {
        // Resolve (same size), then scale up if the scene was drawn smaller.
        msaa_target_->blit_to(scaled ? scale_target_.framebuffer() : static_cast<GLuint>(target_fbo),
                              internal_width_, internal_height_, false);
    }
    if (scaled) scale_target_.blit_to(static_cast<GLuint>(target_fbo), frame.width, frame.height, true);
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target_fbo));
    if (view_model_layer) {
        if (!layer_first) layer = draw_view_model_into_layer(frame, stats);
        if (layer == LayerState::Drawn) {
            view_model_layer_.composite(static_cast<unsigned>(target_fbo), view_model_footprint_,
                                        layer_first);
        } else if (layer == LayerState::Unsupported) {
            glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target_fbo));
            glViewport(0, 0, frame.width, frame.height);
            draw_view_model(frame, stats);
        }
    }
    glViewport(0, 0, frame.width, frame.height);
    glBindVertexArray(0);
    glUseProgram(0);
    glActiveTexture(GL_TEXTURE0);
    glDepthMask(GL_TRUE);
    return stats;
}

} // namespace ks::render
