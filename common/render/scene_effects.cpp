// SceneRenderer's passes after the opaque geometry: particles (additive, or alpha-blended back to front)
// and debug lines.
#include "render/scene_renderer.h"

#include "core/paths.h"
#include "render/texture_cache.h"

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace ks::render {

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

} // namespace ks::render
