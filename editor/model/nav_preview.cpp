#include "model/nav_preview.h"

#include "physics/character.h"

#include <chrono>

namespace ks::editor {

NavPreview::~NavPreview() {
    if (pending_.valid()) pending_.wait(); // the build owns a copy of the level: let it end cleanly
}

bool NavPreview::update(const level::Level& level, std::uint64_t revision) {
    bool changed = false;
    if (pending_.valid() && pending_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
        shown_revision_ = pending_revision_;
        take(pending_.get());
        changed = true;
    }
    if (!pending_.valid() && shown_revision_ != revision) {
        pending_revision_ = revision;
        // The robots' agent, as the game builds it (game/robot_navigation.cpp).
        const physics::CharacterSettings character;
        const nav::NavSettings settings =
            nav::robot_nav_settings(character.step_height, character.max_slope_degrees);
        pending_ = std::async(std::launch::async, [copy = level, settings]() {
            const auto start = std::chrono::steady_clock::now();
            Built built;
            if (auto mesh = nav::NavMesh::build(copy, settings))
                built.mesh = std::move(*mesh);
            else
                built.error = mesh.error().str();
            built.ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            return built;
        });
    }
    return changed;
}

void NavPreview::finish() {
    if (!pending_.valid()) return;
    shown_revision_ = pending_revision_;
    take(pending_.get());
}

void NavPreview::take(Built built) {
    ++stats_.builds;
    stats_.last_build_ms = built.ms;
    triangles_.clear();
    error_ = built.error;
    if (built.mesh) triangles_ = built.mesh->triangles();
    stats_.triangles = triangles_.size();
    stats_.door_triangles = 0;
    for (const auto& t : triangles_) stats_.door_triangles += t.door_id != 0 ? 1 : 0;
}

} // namespace ks::editor
