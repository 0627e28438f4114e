#pragma once
// The player's options (mouse sensitivity, invert Y, field of view, sound, key bindings, gamepad) and their
// file, $XDG_CONFIG_HOME/killswitch/options.json (or ~/.config/killswitch/options.json). GL-free and
// header-only so the tests use it directly (runtime/ sources are compiled only into the killswitch
// executable). A missing file means defaults; a bad file (not JSON, wrong types, NaN, out of range) gives one
// warning naming the file and the field, and the defaults for what could not be read — never a failure.
#include "core/files.h"
#include "core/log.h"
#include "core/math.h"
#include "core/paths.h"
#include "core/result.h"
#include "key_bindings.h"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace ks::runtime {

// Drawing quality (render::RenderQuality): Auto picks Fast on software rasterisers, Full on GPUs.
enum class QualityOption { Auto, Full, Fast };

inline const char* quality_name(QualityOption q) {
    return q == QualityOption::Full ? "full" : q == QualityOption::Fast ? "fast" : "auto";
}

struct Options {
    float mouse_sensitivity = 1.0f; // multiplies the base 0.0022 rad per pixel
    bool invert_y = false;
    float fov_degrees = 75.0f; // vertical field of view
    // What makes a slow machine playable: the 3D scene's resolution as a fraction of the window (0 =
    // automatic: 1 on GPUs, 0.5 on software rasterisers; else 0.25..1) and the shading quality.
    float render_scale = 0.0f;
    QualityOption quality = QualityOption::Auto;
    // Sound: master multiplies the effects (shots, robots, doors, the menu's clicks) and the ambience (the
    // level's ambient loop and its sound emitters); M mutes everything.
    float master_volume = 0.8f;
    float effects_volume = 1.0f;
    float ambience_volume = 0.7f;
    bool muted = false;
    // Controls: the keys of every action (key_bindings.h), and the gamepad's look speed (multiplies
    // GamepadInput::kLookRate) and its sticks' radial dead zone (a fraction of full tilt).
    Bindings bindings;
    float pad_look_sensitivity = 1.0f;
    float pad_dead_zone = 0.15f;
    bool operator==(const Options&) const = default;

    static constexpr float kMinSensitivity = 0.1f, kMaxSensitivity = 5.0f;
    static constexpr float kMinFov = 50.0f, kMaxFov = 110.0f;
    static constexpr float kRadiansPerPixel = 0.0022f;
    static constexpr float kMinRenderScale = 0.25f, kMaxRenderScale = 1.0f;
    static constexpr float kMinDeadZone = 0.0f, kMaxDeadZone = 0.5f;
};

// Where the options live: paths::user_config_dir() ($XDG_CONFIG_HOME/killswitch, else ~/.config/killswitch),
// else ./.killswitch.
inline std::filesystem::path options_path() {
    const std::filesystem::path dir = paths::user_config_dir();
    return (dir.empty() ? std::filesystem::path(".killswitch") : dir) / "options.json";
}

inline std::string options_to_json(const Options& o) {
    nlohmann::json j;
    j["format"] = "killswitch-options";
    j["version"] = 1;
    j["mouse_sensitivity"] = o.mouse_sensitivity;
    j["invert_y"] = o.invert_y;
    j["fov_degrees"] = o.fov_degrees;
    j["render_scale"] = o.render_scale;
    j["quality"] = quality_name(o.quality);
    j["master_volume"] = o.master_volume;
    j["effects_volume"] = o.effects_volume;
    j["ambience_volume"] = o.ambience_volume;
    j["muted"] = o.muted;
    j["bindings"] = bindings_to_json(o.bindings);
    j["pad_look_sensitivity"] = o.pad_look_sensitivity;
    j["pad_dead_zone"] = o.pad_dead_zone;
    return j.dump(2) + "\n";
}

// Parses options text; every problem is appended to `problems` ("field: what, using default X").
inline Options options_from_json(const std::string& text, std::vector<std::string>& problems) {
    Options o;
    auto j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        problems.push_back("not a JSON object");
        return o;
    }
    auto read_number = [&](const char* key, float& value, float lo, float hi) {
        if (!j.contains(key)) return;
        const auto& v = j[key];
        // nlohmann reads NaN/inf as null or rejects them; anything not a finite number in range is refused.
        if (!v.is_number() || !is_finite(v.get<float>()) || v.get<float>() < lo || v.get<float>() > hi) {
            problems.push_back(std::string(key) + ": expected a number in " + std::to_string(lo) + ".." +
                               std::to_string(hi) + ", got " + v.dump() + "; using the default " +
                               std::to_string(value));
            return;
        }
        value = v.get<float>();
    };
    read_number("mouse_sensitivity", o.mouse_sensitivity, Options::kMinSensitivity, Options::kMaxSensitivity);
    read_number("fov_degrees", o.fov_degrees, Options::kMinFov, Options::kMaxFov);
    read_number("master_volume", o.master_volume, 0.0f, 1.0f);
    read_number("effects_volume", o.effects_volume, 0.0f, 1.0f);
    read_number("ambience_volume", o.ambience_volume, 0.0f, 1.0f);
    read_number("pad_look_sensitivity", o.pad_look_sensitivity, Options::kMinSensitivity,
                Options::kMaxSensitivity);
    read_number("pad_dead_zone", o.pad_dead_zone, Options::kMinDeadZone, Options::kMaxDeadZone);
    if (j.contains("bindings")) o.bindings = bindings_from_json(j["bindings"], problems);
    if (j.contains("render_scale")) {
        const auto& v = j["render_scale"];
        const bool number = v.is_number() && is_finite(v.get<float>());
        const float f = number ? v.get<float>() : -1.0f;
        if (number && (f == 0.0f || (f >= Options::kMinRenderScale && f <= Options::kMaxRenderScale)))
            o.render_scale = f;
        else
            problems.push_back("render_scale: expected 0 (automatic) or a number in 0.25..1, got " +
                               v.dump() + "; using the default 0 (automatic)");
    }
    if (j.contains("quality")) {
        const auto& v = j["quality"];
        const std::string q = v.is_string() ? v.get<std::string>() : "";
        if (q == "auto" || q == "full" || q == "fast")
            o.quality = q == "full"   ? QualityOption::Full
                        : q == "fast" ? QualityOption::Fast
                                      : QualityOption::Auto;
        else
            problems.push_back("quality: expected \"auto\", \"full\" or \"fast\", got " + v.dump() +
                               "; using the default \"auto\"");
    }
    auto read_flag = [&](const char* key, bool& value) {
        if (!j.contains(key)) return;
        if (j[key].is_boolean())
            value = j[key].get<bool>();
        else
            problems.push_back(std::string(key) + ": expected true or false, got " + j[key].dump() +
                               "; using the default " + (value ? "true" : "false"));
    };
    read_flag("invert_y", o.invert_y);
    read_flag("muted", o.muted);
    return o;
}

// Reads the options file; missing → defaults silently, bad → defaults (per field) with one warning.
inline Options load_options(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return Options{};
    auto text = files::read_text(path);
    if (!text) {
        log::warn(text.error().str(), " (using default options)");
        return Options{};
    }
    std::vector<std::string> problems;
    Options o = options_from_json(*text, problems);
    for (const auto& p : problems)
        log::warn(path.string(), ": ", p, " (fix or delete the file; Options in the menu rewrites it)");
    return o;
}

// Writes the options atomically (temporary file + rename), creating the folder.
inline Result<void> save_options(const std::filesystem::path& path, const Options& o) {
    std::error_code ec;
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
    if (ec)
        return Error("cannot create the options folder: " + ec.message(),
                     Location(path.parent_path().string()),
                     "check the folder's permissions or set XDG_CONFIG_HOME");
    return files::write_atomic(path, options_to_json(o));
}

} // namespace ks::runtime
