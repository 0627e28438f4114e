#pragma once
// The player's options (mouse sensitivity, invert Y, field of view, sound, key bindings, gamepad, difficulty)
// and their file, $XDG_CONFIG_HOME/killswitch/options.json (or ~/.config/killswitch/options.json). GL-free
// and header-only so the tests use it directly (runtime/ sources are compiled only into the killswitch
// executable). A missing file means defaults; a bad file (not JSON, wrong types, NaN, out of range, an
// unknown field) gives one warning per problem naming the file, line:column and field, and the defaults for
// what could not be read — never a failure.
#include "core/files.h"
#include "core/log.h"
#include "core/math.h"
#include "core/paths.h"
#include "core/result.h"
#include "game/difficulty.h"
#include "jsonio/document.h"
#include "jsonio/number_text.h"
#include "jsonio/object_reader.h"
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
    bool logic_debugger = false; // the in-game logic debugger shown (F3)
    // Controls: the keys of every action (key_bindings.h), and the gamepad's look speed (multiplies
    // GamepadInput::kLookRate) and its sticks' radial dead zone (a fraction of full tilt).
    Bindings bindings;
    float pad_look_sensitivity = 1.0f;
    float pad_dead_zone = 0.15f;
    // The robots' aim time, hit chance and damage (game/difficulty.h); `--difficulty` overrides it for a run.
    game::Difficulty difficulty = game::Difficulty::Normal;
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
    j["logic_debugger"] = o.logic_debugger;
    j["bindings"] = bindings_to_json(o.bindings);
    j["pad_look_sensitivity"] = o.pad_look_sensitivity;
    j["pad_dead_zone"] = o.pad_dead_zone;
    j["difficulty"] = game::difficulty_name(o.difficulty);
    return j.dump(2) + "\n";
}

// Problems with the bindings come from key_bindings.h as "bindings.jump: ..."; they get the place of their
// path in the file like every other problem.
inline std::string located_binding_problem(const std::string& problem, const jsonio::Document& document) {
    const std::string path = problem.substr(0, problem.find(':'));
    const jsonio::TextPosition at = document.positions().find(path);
    return document.file() + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": " + problem;
}

// Parses options text with the reader every file shares (jsonio/object_reader.h); every problem is appended
// to `problems` ("options.json:3:5: fov_degrees: 1000 is out of range (valid: 50 .. 110); the default is
// kept"), and the field keeps its default.
inline Options options_from_json(const std::string& text, std::vector<std::string>& problems,
                                 const std::string& file_name = "options.json") {
    using jsonio::Range;
    Options o;
    const jsonio::Document document = jsonio::Document::parse(
        text, file_name,
        {"options", "an options file is {\"format\": \"killswitch-options\", \"version\": 1, ...}; "
                    "Options in the menu rewrites it"});
    jsonio::Problems found(file_name, &document.positions());
    document.report_to(found);
    if (const jsonio::Json* root = document.root()) {
        jsonio::ObjectReader in(*root, "", found, "options");
        in.claim("format");
        in.claim("version");
        in.number("mouse_sensitivity", o.mouse_sensitivity,
                  Range{Options::kMinSensitivity, Options::kMaxSensitivity});
        in.number("fov_degrees", o.fov_degrees, Range{Options::kMinFov, Options::kMaxFov, "deg"});
        in.number("master_volume", o.master_volume, Range{0, 1});
        in.number("effects_volume", o.effects_volume, Range{0, 1});
        in.number("ambience_volume", o.ambience_volume, Range{0, 1});
        in.number("pad_look_sensitivity", o.pad_look_sensitivity,
                  Range{Options::kMinSensitivity, Options::kMaxSensitivity});
        in.number("pad_dead_zone", o.pad_dead_zone, Range{Options::kMinDeadZone, Options::kMaxDeadZone});
        if (float scale = 0.0f; in.number("render_scale", scale, Range{0, Options::kMaxRenderScale})) {
            if (scale == 0.0f || scale >= Options::kMinRenderScale)
                o.render_scale = scale;
            else
                found.report(jsonio::Severity::Error, "render_scale",
                             jsonio::format_readable(scale) + " is out of range",
                             "valid: 0 (automatic) or 0.25 .. 1");
        }
        if (std::string quality; in.choice("quality", quality, {"auto", "full", "fast"}))
            o.quality = quality == "full"   ? QualityOption::Full
                        : quality == "fast" ? QualityOption::Fast
                                            : QualityOption::Auto;
        if (std::string difficulty; in.choice("difficulty", difficulty, {"easy", "normal", "hard"}))
            o.difficulty = *game::parse_difficulty(difficulty, Location(file_name));
        in.flag("invert_y", o.invert_y);
        in.flag("muted", o.muted);
        in.flag("logic_debugger", o.logic_debugger);
        if (const jsonio::Json* bindings = in.get("bindings")) {
            std::vector<std::string> binding_problems;
            o.bindings = bindings_from_json(nlohmann::json(*bindings), binding_problems);
            for (const std::string& p : binding_problems)
                problems.push_back(located_binding_problem(p, document));
        }
        in.finish();
    }
    for (const Error& e : found.errors()) problems.push_back(e.str() + "; the default is kept");
    for (const Error& e : found.warnings()) problems.push_back(e.str());
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
    Options o = options_from_json(*text, problems, path.string());
    for (const auto& p : problems) log::warn(p, " (fix or delete the file; Options in the menu rewrites it)");
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
