#include "model/dojo_graph_ease.h"

#include "model/dojo_edit_support.h"
#include "model/dojo_keys.h"

#include <algorithm>
#include <cmath>

namespace ks::editor {
namespace {
using anim::Ease;
using anim::EaseFamily;
using anim::EaseMode;

double power_handle_u(EaseMode mode) {
    return mode == EaseMode::InOut ? 0.25 : 0.5;
}

float thousandth(double v) {
    return static_cast<float>(std::round(v * 1000.0) / 1000.0);
}
} // namespace

std::vector<EaseHandle> ease_handles(const Ease& ease) {
    if (ease.family == EaseFamily::CubicBezier)
        return {{ease.params[0], ease.params[1]}, {ease.params[2], ease.params[3]}};
    if (ease.family == EaseFamily::Power) {
        const double u = power_handle_u(ease.mode);
        return {{u, ease(u)}};
    }
    return {};
}

std::optional<Ease> drag_ease_handle(const Ease& ease, std::size_t handle, double u, double y) {
    if (!std::isfinite(u) || !std::isfinite(y)) return std::nullopt;
    if (ease.family == EaseFamily::CubicBezier && handle < 2) {
        Ease out = ease;
        out.params[handle * 2] = thousandth(std::clamp(u, 0.0, 1.0));
        out.params[handle * 2 + 1] = thousandth(std::clamp(y, -2.0, 3.0));
        return out;
    }
    if (ease.family == EaseFamily::Power && handle == 0) {
        // The point (u, y) on t^p (In), 1 - (1 - t)^p (Out) or (2t)^p / 2 (InOut, t < 0.5) gives p.
        const double hu = power_handle_u(ease.mode);
        const double h = std::clamp(y, 1e-4, 1.0 - 1e-4);
        double p = 0;
        switch (ease.mode) {
        case EaseMode::In:
            p = std::log(h) / std::log(hu);
            break;
        case EaseMode::Out:
            p = std::log(1.0 - h) / std::log(1.0 - hu);
            break;
        case EaseMode::InOut:
            p = std::log(std::min(2.0 * h, 1.0 - 1e-4)) / std::log(2.0 * hu);
            break;
        }
        return Ease::power(static_cast<float>(std::round(std::clamp(p, 0.05, 64.0) * 100.0) / 100.0),
                           ease.mode);
    }
    return std::nullopt;
}

Result<void> set_segment_ease(anim::AnimationFile& file, std::size_t clip, std::size_t phase,
                              const std::string& node, const Ease& ease) {
    auto found = dojo_support::clip_at(file, clip);
    if (!found) return found.error();
    if (phase >= (*found)->phases.size())
        return Error("clip '" + (*found)->name + "' has no key " + std::to_string(phase + 1), {},
                     "it has " + std::to_string((*found)->phases.size()) + " keys");
    if (const std::string why = anim::validate_ease(ease); !why.empty())
        return Error("cannot use that easing: " + why, {}, "drag the handle back inside the segment's time");
    anim::AnimationFile edited = file;
    auto keyed = [&](const anim::PhaseDef& p) {
        return std::any_of(p.targets.begin(), p.targets.end(),
                           [&](const anim::TargetDef& t) { return t.node == node; });
    };
    if (!keyed(edited.clips[clip].phases[phase]))
        if (auto added = add_node_key(edited, clip, phase, node); !added) return added.error();
    for (anim::TargetDef& t : edited.clips[clip].phases[phase].targets)
        if (t.node == node) t.ease = ease;
    if (auto valid = dojo_support::no_new_clip_issues(file, edited, clip); !valid) return valid.error();
    file = std::move(edited);
    return ok();
}

const std::vector<EasePreset>& ease_presets() {
    static const std::vector<EasePreset> presets = {
        {"Linear", Ease::linear()},
        {"Quadratic.In", Ease::named(EaseFamily::Quadratic, EaseMode::In)},
        {"Quadratic.Out", Ease::named(EaseFamily::Quadratic, EaseMode::Out)},
        {"Quadratic.InOut", Ease::named(EaseFamily::Quadratic, EaseMode::InOut)},
        {"Cubic.InOut", Ease::named(EaseFamily::Cubic, EaseMode::InOut)},
        {"Sinusoidal.InOut", Ease::named(EaseFamily::Sinusoidal, EaseMode::InOut)},
        {"Back.Out (overshoot)", Ease::named(EaseFamily::Back, EaseMode::Out)},
        {"Elastic.Out", Ease::named(EaseFamily::Elastic, EaseMode::Out)},
        {"Bounce.Out", Ease::named(EaseFamily::Bounce, EaseMode::Out)},
        {"Bezier: ease", Ease::bezier(0.25f, 0.1f, 0.25f, 1.0f)},
        {"Bezier: ease in", Ease::bezier(0.42f, 0.0f, 1.0f, 1.0f)},
        {"Bezier: ease out", Ease::bezier(0.0f, 0.0f, 0.58f, 1.0f)},
        {"Bezier: ease in-out", Ease::bezier(0.42f, 0.0f, 0.58f, 1.0f)},
        {"Bezier: overshoot", Ease::bezier(0.34f, 1.56f, 0.64f, 1.0f)},
        {"Bezier: anticipate", Ease::bezier(0.36f, -0.4f, 0.7f, 1.0f)},
        {"Power 2 (in)", Ease::power(2.0f, EaseMode::In)},
        {"Power 3 (out)", Ease::power(3.0f, EaseMode::Out)},
        {"Power 2.5 (in-out)", Ease::power(2.5f, EaseMode::InOut)},
    };
    return presets;
}

} // namespace ks::editor
