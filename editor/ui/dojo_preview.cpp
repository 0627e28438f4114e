// The dojo's 3D preview: the posed robot on a tiled floor under two studio lights, orbited by dragging, and
// the onion skin: the poses at the keys before and after the playhead drawn over it, tinted.
#include "ui/dojo_preview.h"

#include "render/level_scene.h"
#include "render/mesh_data.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace ks::editor::ui {

namespace {
constexpr float kDojoBar = 212.0f; // transport, timeline (with its event lane) and transition tester

// The ghosts' washes (linear rgb added to the shading): the previous key blue, the next key magenta, both
// far from the robot's yellow.
const Vec3 kPreviousKeyTint(0.05f, 0.25f, 0.75f);
const Vec3 kNextKeyTint(0.8f, 0.08f, 0.55f);

bool same_matrix(const Mat4& a, const Mat4& b) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (std::abs(a[c][r] - b[c][r]) > 1e-4f) return false;
    return true;
}
} // namespace

void dojo_preview_size(float tab_width, float tab_height, float& w, float& h) {
    w = std::max(64.0f, std::floor(tab_width * 0.5f));
    h = std::max(64.0f, std::floor(tab_height - kDojoBar));
}

DojoPreview::DojoPreview(render::AssetLibrary& assets, render::SceneRenderer& renderer)
    : assets_(assets), renderer_(renderer) {
    render::MeshData floor;
    render::append_box(floor, Vec3(0, -0.05f, 0), Vec3(14, 0.1f, 14), Mat4(1.0f), 2.0f);
    floor_ = std::make_unique<render::GpuMesh>(floor);
    floor_material_ = &assets_.surface("tiles");
    lights_.push_back({render::Light::Type::Point, Vec3(3.0f, 5.0f, 4.0f), Vec3(0, -1, 0),
                       Vec3(1.0f, 0.85f, 0.7f), 1.2f, 20.0f, 0.8f, 0.9f});
    lights_.push_back({render::Light::Type::Point, Vec3(-4.0f, 3.0f, -2.0f), Vec3(0, -1, 0),
                       Vec3(0.5f, 0.7f, 1.0f), 0.8f, 20.0f, 0.8f, 0.9f});
}

const render::Model& DojoPreview::model() {
    model_ = &assets_.model("robot");
    return *model_;
}

void DojoPreview::bind(const anim::Rig& rig) {
    binding_ = anim::RigBinding(rig, model().node_names());
    pose_ = model_->rest_pose();
}

void DojoPreview::pose_from(const anim::Player& player) {
    binding_.write_locals(player.pose(), pose_.local);
}

// The keys either side of the playhead (model: dojo_keys_around), posed once per key time and file revision.
void DojoPreview::update_ghosts(const DojoContext& dojo) {
    ghosts_[0].shown = ghosts_[1].shown = false;
    const DojoPlayback& playback = dojo.playback;
    const anim::ClipDef* def = dojo.shown_def();
    const int clip = playback.clip();
    if (!onion_ || playback.transition() || !def ||
        static_cast<size_t>(clip) >= playback.clips().clips.size())
        return;
    const DojoKeysAround around = dojo_keys_around(*def, playback.time());
    const double times[2] = {around.previous, around.next};
    for (int g = 0; g < 2; ++g) {
        Ghost& ghost = ghosts_[static_cast<size_t>(g)];
        if (times[g] < 0) continue;
        ghost.shown = true;
        const std::uint64_t revision = dojo.edits.revision();
        if (ghost.time == times[g] && ghost.revision == revision && ghost.clip == clip) continue;
        ghost.time = times[g];
        ghost.revision = revision;
        ghost.clip = clip;
        anim::Player player(playback.clips(), playback.rig());
        player.play(clip, 0.0f);
        player.advance(ghost.time);
        if (ghost.pose.local.size() != model_->nodes.size()) ghost.pose = model_->rest_pose();
        binding_.write_locals(player.pose(), ghost.pose.local);
    }
}

// Appends the ghost's instances, keeping only the parts that are not where the live pose has them (a part
// drawn twice in the same place would flicker between its tinted and plain copies).
void DojoPreview::emit_ghost(const render::ModelPose& ghost, const Vec3& tint, std::size_t main_count) {
    const std::size_t first = instances_.size();
    model_->emit(Mat4(1.0f), ghost, scratch_, instances_);
    std::size_t kept = first;
    for (std::size_t i = first; i < instances_.size(); ++i) {
        const std::size_t k = i - first;
        if (k < main_count && same_matrix(instances_[i].world, instances_[k].world)) continue;
        render::MeshInstance inst = instances_[i];
        inst.tint = tint;
        inst.casts_shadow = false;
        instances_[kept++] = inst;
    }
    instances_.resize(kept);
    ghost_instances_ += static_cast<int>(kept - first);
}

void DojoPreview::render(const DojoContext& dojo, float tab_width, float tab_height) {
    dojo_preview_size(tab_width, tab_height, width_, height_);
    target_.ensure(static_cast<int>(width_), static_cast<int>(height_));
    target_.bind();
    instances_.clear();
    ghost_instances_ = 0;
    pose_tools_.sync(dojo);
    if (model_ && !pose_tools_.edits().empty()) // the turned, not yet keyed nodes
        binding_.write_locals(shown_pose(dojo.playback, pose_tools_.edits()), pose_.local);
    if (model_) {
        model_->emit(Mat4(1.0f), pose_, scratch_, instances_);
        const std::size_t main_count = instances_.size();
        update_ghosts(dojo);
        if (ghosts_[0].shown) emit_ghost(ghosts_[0].pose, kPreviousKeyTint, main_count);
        if (ghosts_[1].shown) emit_ghost(ghosts_[1].pose, kNextKeyTint, main_count);
    }
    instances_.push_back({floor_.get(), floor_material_, Mat4(1.0f), 1.0f, false});
    const Vec3 target(0.0f, 1.6f, 0.0f);
    view_.set_viewport(Vec2(static_cast<float>(target_.width()), static_cast<float>(target_.height())));
    geometry::Camera& camera = view_.camera;
    camera.fov_y = radians(40.0f);
    camera.aspect = width_ / height_;
    camera.yaw = orbit_yaw_;
    camera.pitch = -orbit_pitch_;
    camera.position = target - camera.forward() * orbit_distance_;
    debug_.clear();
    for (int i = -3; i <= 3; ++i) { // a floor grid, one unit apart, to read motion against
        debug_.line(Vec3(i, 0.01f, -3), Vec3(i, 0.01f, 3), Vec4(0.6f, 0.7f, 0.8f, 0.25f));
        debug_.line(Vec3(-3, 0.01f, i), Vec3(3, 0.01f, i), Vec4(0.6f, 0.7f, 0.8f, 0.25f));
    }
    render::SceneFrame frame;
    frame.camera = camera;
    frame.environment = render::preview_environment(0.02f);
    frame.instances = &instances_;
    frame.lights = &lights_;
    frame.debug = &debug_;
    frame.width = target_.width();
    frame.height = target_.height();
    renderer_.invalidate_shadows(); // the level viewport shares the renderer's shadow cache
    renderer_.render(frame);
    renderer_.invalidate_shadows();
}

// The rendered preview (drag to orbit) with the onion-skin toggle and its legend over its top-left corner.
void DojoPreview::draw(const DojoContext& dojo, float w, float h) {
    const ImVec2 corner = ImGui::GetCursorScreenPos();
    if (target_.texture() == 0) { // not rendered yet (the tab's first frame): keep its place
        ImGui::Dummy(ImVec2(w, h));
        return;
    }
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(target_.texture())), ImVec2(w, h),
                 ImVec2(0, 1), ImVec2(1, 0));
    const bool posing =
        pose_tools_.overlay(dojo, view_, Vec2(corner.x, corner.y), ImGui::IsItemHovered() && !orbiting_);
    if (ImGui::IsItemHovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) orbiting_ = !posing;
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) orbiting_ = false;
    if (orbiting_ && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
        const ImVec2 d = ImGui::GetIO().MouseDelta;
        orbit_yaw_ -= d.x * 0.01f;
        orbit_pitch_ = std::clamp(orbit_pitch_ + d.y * 0.01f, -0.2f, 1.3f);
    }
    if (ImGui::IsItemHovered() && ImGui::GetIO().MouseWheel != 0.0f) // zoom
        orbit_distance_ =
            std::clamp(orbit_distance_ * std::pow(0.9f, ImGui::GetIO().MouseWheel), 3.0f, 20.0f);
    const ImVec2 after = ImGui::GetCursorScreenPos();
    ImGui::SetCursorScreenPos(ImVec2(corner.x + 6, corner.y + 6));
    ImGui::Checkbox("Onion skin", &onion_);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Ghosts of the keys around the playhead: the previous key blue, the next magenta");
    if (onion_) {
        ImDrawList* draw = ImGui::GetWindowDrawList();
        const float line = ImGui::GetTextLineHeight();
        float y = ImGui::GetCursorScreenPos().y + 2;
        const struct {
            const Vec3& tint;
            const char* label;
        } legend[2] = {{kPreviousKeyTint, "previous key"}, {kNextKeyTint, "next key"}};
        for (const auto& item : legend) {
            const ImU32 colour =
                ImGui::GetColorU32(ImVec4(item.tint.x + 0.2f, item.tint.y + 0.2f, item.tint.z + 0.2f, 1.0f));
            draw->AddRectFilled(ImVec2(corner.x + 10, y + 3), ImVec2(corner.x + 10 + line - 6, y + line - 3),
                                colour, 2.0f);
            draw->AddText(ImVec2(corner.x + 10 + line, y), IM_COL32(230, 232, 240, 255), item.label);
            y += line + 2;
        }
    }
    ImGui::SetCursorScreenPos(ImVec2(corner.x + 6, corner.y + h - ImGui::GetFrameHeight() - 4));
    pose_tools_.bar(dojo);
    ImGui::SetCursorScreenPos(after);
}

} // namespace ks::editor::ui
