#include "model/dojo_gltf.h"

#include "anim/clip_io.h"
#include "anim/player.h"
#include "anim/rotation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace ks::editor {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kDegrees = 180.0 / std::numbers::pi;
constexpr double kSameTime = 1e-6; // seconds: two key times this close are one

// ---- export ---------------------------------------------------------------------------------------------

// Frame times 0, 1/fps, ... up to the clip's end, and the end itself when it falls between frames.
std::vector<double> frame_times(double duration, double fps) {
    std::vector<double> times;
    const auto frames = static_cast<long>(std::floor(duration * fps + 1e-9));
    for (long k = 0; k <= frames; ++k) times.push_back(static_cast<double>(k) / fps);
    if (duration - times.back() > 1e-9) times.push_back(duration);
    return times;
}

modelio::NodeAnimation bake_clip(const anim::Clip& clip, const anim::Rig& rig, double fps) {
    anim::Pose rest;
    rest.set_rest(rig);
    anim::Pose pose = rest;
    std::vector<char> rotates(static_cast<std::size_t>(rig.size()), 0), moves(rotates);
    for (const anim::Channel& ch : clip.channels)
        (ch.is_position ? moves : rotates)[static_cast<std::size_t>(ch.node)] = 1;
    std::vector<modelio::NodeTrack> tracks(static_cast<std::size_t>(rig.size()));
    for (const double t : frame_times(clip.duration, fps)) {
        anim::sample_clip(clip, rest.euler, rest.position, t, pose.euler, pose.position);
        for (std::size_t n = 0; n < tracks.size(); ++n) {
            modelio::NodeTrack& track = tracks[n];
            if (rotates[n]) {
                Quat q = anim::euler_xyz_to_quat(pose.euler[n]);
                // Keep each key in the previous one's hemisphere so a slerp between frames takes the short
                // way.
                if (!track.rotations.empty() && glm::dot(track.rotations.back(), q) < 0) q = -q;
                track.rotation_times.push_back(t);
                track.rotations.push_back(q);
            }
            if (moves[n]) {
                track.translation_times.push_back(t);
                track.translations.push_back(pose.position[n]);
            }
        }
    }
    modelio::NodeAnimation out;
    out.name = clip.name;
    for (std::size_t n = 0; n < tracks.size(); ++n) {
        if (tracks[n].rotations.empty() && tracks[n].translations.empty()) continue;
        tracks[n].node = rig.node(static_cast<int>(n)).name;
        out.tracks.push_back(std::move(tracks[n]));
    }
    return out;
}

// ---- import ---------------------------------------------------------------------------------------------

std::string clip_name_from(const std::string& name) {
    std::string out;
    for (const char c : name)
        out.push_back(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' ? c : '_');
    return out.empty() ? std::string("gltf_clip") : out;
}

// The Euler XYZ angles of `q` nearest `previous`: both decompositions of the rotation, each angle moved by
// whole turns towards the previous key's, so a spin keeps turning the way it did.
DVec3 continuous_euler(const Quat& q, const DVec3& previous) {
    const DVec3 a(anim::quat_to_euler_xyz(q));
    const DVec3 b(a.x + std::numbers::pi, std::numbers::pi - a.y, a.z + std::numbers::pi);
    DVec3 best{0};
    double best_distance = INFINITY;
    for (DVec3 candidate : {a, b}) {
        for (int i = 0; i < 3; ++i)
            candidate[i] += kTwoPi * std::round((previous[i] - candidate[i]) / kTwoPi);
        const double distance = glm::length(candidate - previous);
        if (distance < best_distance) best_distance = distance, best = candidate;
    }
    return best;
}

// The track's value at time t, arriving (`after` false) or leaving (`after` true): the two differ only at a
// step key.
template <class Value, class Mix>
Value value_at(const std::vector<double>& times, const std::vector<Value>& values,
               modelio::KeyInterpolation how, double t, bool after, Mix mix) {
    // Key times are the file's floats, t is on the grid key_times chose: they meet within kSameTime.
    const auto upper = std::upper_bound(times.begin(), times.end(), t + kSameTime);
    if (upper == times.begin()) return values.front();
    const std::size_t k = static_cast<std::size_t>(upper - times.begin()) - 1;
    if (how == modelio::KeyInterpolation::Step)
        return !after && k > 0 && std::abs(times[k] - t) <= kSameTime ? values[k - 1] : values[k];
    if (k + 1 >= times.size()) return values.back();
    const double u = (t - times[k]) / (times[k + 1] - times[k]);
    return mix(values[k], values[k + 1], static_cast<float>(std::clamp(u, 0.0, 1.0)));
}

// The key times of every mapped track, put on the frame grid of the common rate that fits the most of them
// (so 1/60 s keys are exactly k/60), the others on a microsecond grid; `grid` is that rate when it holds
// every time and one is past 0 s (the clip is then stored at that frame rate), else 0.
std::vector<double> key_times(const std::vector<const modelio::NodeTrack*>& tracks, double& grid) {
    std::vector<double> times;
    for (const modelio::NodeTrack* t : tracks) {
        times.insert(times.end(), t->rotation_times.begin(), t->rotation_times.end());
        times.insert(times.end(), t->translation_times.begin(), t->translation_times.end());
    }
    double best_fps = 0;
    std::size_t best_fit = 0;
    for (const double fps : {24.0, 25.0, 30.0, 50.0, 60.0, 120.0, 240.0}) {
        const auto fit = static_cast<std::size_t>(std::count_if(times.begin(), times.end(), [&](double t) {
            return std::abs(t * fps - std::round(t * fps)) < 1e-3;
        }));
        if (fit > best_fit) best_fit = fit, best_fps = fps;
    }
    // A clip whose only key is at 0 s says nothing of its rate.
    const bool timed = std::any_of(times.begin(), times.end(), [](double t) { return t > 0; });
    grid = timed && best_fit == times.size() ? best_fps : 0.0;
    for (double& t : times) {
        const bool on_grid = best_fps > 0 && std::abs(t * best_fps - std::round(t * best_fps)) < 1e-3;
        t = on_grid ? std::round(t * best_fps) / best_fps : std::round(t * 1e6) / 1e6;
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end(), [](double a, double b) { return b - a < kSameTime; }),
                times.end());
    return times;
}

double rounded(double v, double grid) {
    return std::round(v / grid) * grid;
}

struct MappedTrack {
    const modelio::NodeTrack* track = nullptr;
    int node = -1;
    DVec3 euler{0}; // the last key's angles, radians (continuity)
};

anim::PhaseDef phase_at(const anim::AnimationFile& file, const anim::Rig& rig,
                        std::vector<MappedTrack>& mapped, double duration, double t, bool after) {
    anim::PhaseDef phase;
    phase.duration = duration;
    phase.ease = anim::Ease::linear();
    for (MappedTrack& m : mapped) {
        const modelio::NodeTrack& tr = *m.track;
        const anim::RigNode& node = rig.node(m.node);
        anim::TargetDef target;
        target.node = node.name;
        if (!tr.rotations.empty()) {
            const Quat q =
                value_at(tr.rotation_times, tr.rotations, tr.rotation_interpolation, t, after,
                         [](const Quat& a, const Quat& b, float u) { return anim::slerp_shortest(a, b, u); });
            m.euler = continuous_euler(q, m.euler);
            target.rot = DVec3(rounded(m.euler.x * kDegrees, 1e-6), rounded(m.euler.y * kDegrees, 1e-6),
                               rounded(m.euler.z * kDegrees, 1e-6));
        }
        if (!tr.translations.empty()) {
            const Vec3 p =
                value_at(tr.translation_times, tr.translations, tr.translation_interpolation, t, after,
                         [](const Vec3& a, const Vec3& b, float u) { return glm::mix(a, b, u); });
            const DVec3 offset = DVec3(p) - DVec3(node.rest_position);
            target.pos = DVec3(rounded(offset.x, 1e-7), rounded(offset.y, 1e-7), rounded(offset.z, 1e-7));
        }
        // A node eased by the file's node_ease would not move linearly between the keys.
        if (std::any_of(file.node_ease.begin(), file.node_ease.end(),
                        [&](const anim::NodeEase& e) { return e.node == node.name; }))
            target.ease = anim::Ease::linear();
        phase.targets.push_back(std::move(target));
    }
    return phase;
}

bool has_step_at(const std::vector<MappedTrack>& mapped, double t) {
    for (const MappedTrack& m : mapped) {
        auto step = [&](const std::vector<double>& times, modelio::KeyInterpolation how) {
            return how == modelio::KeyInterpolation::Step &&
                   std::any_of(times.begin() + (times.empty() ? 0 : 1), times.end(),
                               [&](double k) { return std::abs(k - t) <= kSameTime; });
        };
        if (step(m.track->rotation_times, m.track->rotation_interpolation) ||
            step(m.track->translation_times, m.track->translation_interpolation))
            return true;
    }
    return false;
}

// Phases through every key time: the first key at once (0 s), then a linear phase to each next key; a step
// key adds a 0 s phase after the hold. On a frame grid (`grid`, see key_times) durations are whole frames.
std::vector<anim::PhaseDef> phases_of(const anim::AnimationFile& file, const anim::Rig& rig,
                                      std::vector<MappedTrack>& mapped, double& grid) {
    std::vector<const modelio::NodeTrack*> tracks;
    for (const MappedTrack& m : mapped) tracks.push_back(m.track);
    const std::vector<double> times = key_times(tracks, grid);
    std::vector<anim::PhaseDef> phases;
    phases.push_back(phase_at(file, rig, mapped, 0.0, times.front(), true));
    double previous = 0;
    for (std::size_t k = 0; k < times.size(); ++k) {
        const double t = times[k];
        if (k == 0 && t <= 0) continue;
        const double duration =
            grid > 0 ? std::round((t - previous) * grid) / grid : rounded(t - previous, 1e-12);
        phases.push_back(phase_at(file, rig, mapped, duration, t, false));
        if (has_step_at(mapped, t)) phases.push_back(phase_at(file, rig, mapped, 0.0, t, true));
        previous = t;
    }
    return phases;
}

std::string node_list(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

} // namespace

std::string GltfImportReport::summary() const {
    std::string out = "imported " + std::to_string(added.size() + replaced.size()) + " clip(s)";
    if (!added.empty()) out += "; added: " + node_list(added);
    if (!replaced.empty()) out += "; replaced: " + node_list(replaced);
    if (!unmapped.empty()) out += "; not mapped: " + node_list(unmapped);
    return out;
}

Result<modelio::AnimatedScene> clips_to_gltf_scene(const anim::AnimationFile& file, const anim::Rig& rig,
                                                   std::span<const std::size_t> clips, double fps) {
    if (!std::isfinite(fps) || fps < 1 || fps > 1000)
        return Error("a frame rate of " + std::to_string(fps) + " frames per second", {},
                     "use 1 to 1000, e.g. 60");
    auto compiled = anim::compile(file, rig);
    if (!compiled) return compiled.error();
    modelio::AnimatedScene scene;
    for (const anim::RigNode& n : rig.nodes())
        scene.nodes.push_back(
            {n.name, n.parent, n.rest_position, anim::euler_xyz_to_quat(n.rest_euler), n.rest_scale});
    std::vector<std::size_t> chosen(clips.begin(), clips.end());
    if (chosen.empty())
        for (std::size_t c = 0; c < file.clips.size(); ++c) chosen.push_back(c);
    for (const std::size_t c : chosen) {
        if (c >= compiled->clips.size())
            return Error("there is no clip " + std::to_string(c + 1), {}, "pick a clip of the file");
        scene.animations.push_back(bake_clip(compiled->clips[c], rig, fps));
    }
    return scene;
}

Result<void> export_clips_gltf(const anim::AnimationFile& file, const anim::Rig& rig,
                               std::span<const std::size_t> clips, const std::filesystem::path& path,
                               double fps) {
    auto scene = clips_to_gltf_scene(file, rig, clips, fps);
    if (!scene) return scene.error();
    return modelio::write_gltf_animations(path, *scene);
}

Result<GltfImportReport> import_clips_gltf(anim::AnimationFile& file, const anim::Rig& rig,
                                           const std::filesystem::path& path) {
    auto scene = modelio::read_gltf_animations(path);
    if (!scene) return scene.error();
    return import_clips_gltf(file, rig, *scene, path.string());
}

Result<GltfImportReport> import_clips_gltf(anim::AnimationFile& file, const anim::Rig& rig,
                                           const modelio::AnimatedScene& scene, const std::string& source) {
    GltfImportReport report;
    anim::AnimationFile result = file;
    std::vector<std::string> file_nodes, rig_nodes;
    for (const modelio::AnimNode& n : scene.nodes) file_nodes.push_back(n.name);
    for (const anim::RigNode& n : rig.nodes()) rig_nodes.push_back(n.name);
    for (const modelio::NodeAnimation& animation : scene.animations) {
        std::vector<MappedTrack> mapped;
        for (const modelio::NodeTrack& track : animation.tracks) {
            const int node = rig.find(track.node);
            if (node < 0) {
                report.unmapped.push_back("animation '" + animation.name + "', node '" + track.node +
                                          "' (not in the rig)");
                continue;
            }
            mapped.push_back({&track, node, DVec3(rig.node(node).rest_euler)});
        }
        if (mapped.empty()) continue;
        anim::ClipDef clip;
        clip.name = clip_name_from(animation.name);
        clip.unlisted = anim::UnlistedRule::Hold;
        double grid = 0;
        clip.phases = phases_of(file, rig, mapped, grid);
        if (grid > 0) clip.frame_rate = grid; // shown in frames at the rate its keys were made at
        auto existing = std::find_if(result.clips.begin(), result.clips.end(),
                                     [&](const anim::ClipDef& c) { return c.name == clip.name; });
        if (existing != result.clips.end()) {
            existing->phases = std::move(clip.phases);
            existing->unlisted = clip.unlisted;
            if (clip.frame_rate) existing->frame_rate = clip.frame_rate;
            report.replaced.push_back(clip.name);
        } else {
            result.clips.push_back(std::move(clip));
            report.added.push_back(result.clips.back().name);
        }
    }
    report.unmapped.insert(report.unmapped.end(), scene.ignored.begin(), scene.ignored.end());
    if (report.added.empty() && report.replaced.empty())
        return Error("no node the file animates is in the rig (the file's nodes: " + node_list(file_nodes) +
                         ")",
                     Location(source), "name the nodes as the rig does: " + node_list(rig_nodes));
    for (const anim::Issue& issue : anim::validate(result))
        if (!issue.warning)
            return Error("the imported clips are not valid: " + issue.message,
                         Location(source, 0, 0, issue.path.str()), issue.hint);
    file = std::move(result);
    return report;
}

} // namespace ks::editor
