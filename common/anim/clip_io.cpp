#include "anim/clip_io.h"

#include "anim/clip_reader.h"
#include "core/files.h"
#include "jsonio/position_map.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace ks::anim {
namespace {

using Json = nlohmann::ordered_json;

// The JSON syntax check: the document, or one error at the place the parser stopped.
Result<Json> parse_document(std::string_view text, const std::string& file_name) {
    try {
        return Json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        // e.byte is 1-based, pointing just past the offending character.
        const std::size_t offset = e.byte > 0 ? e.byte - 1 : 0;
        std::string hint = "fix the JSON syntax";
        const std::string_view near = text.substr(offset >= 8 ? offset - 8 : 0, 16);
        for (const char* bad : {"NaN", "nan", "Infinity", "inf"})
            if (near.find(bad) != std::string_view::npos)
                hint = "JSON has no NaN or Infinity: write a finite number";
        std::string what = e.what();
        if (auto p = what.find("parse error"); p != std::string::npos) what = what.substr(p);
        return Error(what, jsonio::location_at(file_name, jsonio::position_of_offset(text, offset)), hint);
    } catch (const nlohmann::json::exception& e) {
        // Number overflow (1e999) is reported without a position: find the quoted token in the text.
        std::string what = e.what();
        jsonio::TextPosition pos{};
        auto open = what.find('\''), close = what.rfind('\'');
        if (open != std::string::npos && close > open) {
            auto at = text.find(what.substr(open + 1, close - open - 1));
            if (at != std::string_view::npos) pos = jsonio::position_of_offset(text, at);
        }
        return Error(what.substr(what.find(']') + 2) + ": number is not finite",
                     jsonio::location_at(file_name, pos), "write a finite number");
    }
}

// Whether one path is the other or inside it ("clips[1]" and "clips[1].name").
bool related(const std::string& a, const std::string& b) {
    const std::string& shorter = a.size() < b.size() ? a : b;
    const std::string& longer = a.size() < b.size() ? b : a;
    return longer.compare(0, shorter.size(), shorter) == 0 &&
           (longer.size() == shorter.size() || shorter.empty() || longer[shorter.size()] == '.' ||
            longer[shorter.size()] == '[');
}

// Semantic checks run on what could be read, so one pass reports everything; a semantic issue on a value the
// reader already rejected (or inside it) would only repeat that problem and is left out.
void add_semantic_issues(const AnimationFile& file, std::vector<Issue>& issues) {
    const std::size_t read_issues = issues.size();
    for (Issue& semantic : validate(file)) {
        bool repeat = false;
        for (std::size_t i = 0; i < read_issues && !repeat; ++i)
            repeat = related(issues[i].path.str(), semantic.path.str());
        if (!repeat) issues.push_back(std::move(semantic));
    }
}

// Every issue pinned to its line:column, in document order, as one error.
Error located_error(std::string_view text, const std::string& file_name, const std::vector<Issue>& issues) {
    const jsonio::PositionMap positions = jsonio::PositionMap::scan(text);
    std::vector<Error> errors;
    for (const Issue& issue : issues) {
        std::string path = issue.path.str();
        const jsonio::TextPosition pos = positions.find_value(path);
        errors.emplace_back(issue.message, jsonio::location_at(file_name, pos, std::move(path)), issue.hint);
    }
    std::stable_sort(errors.begin(), errors.end(), [](const Error& a, const Error& b) {
        return std::pair(a.where.line, a.where.column) < std::pair(b.where.line, b.where.column);
    });
    return combine_errors(errors);
}

} // namespace

Result<AnimationFile> load_animation_string(std::string_view text, const std::string& file_name) {
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
        return Error("the animation file is empty", Location(file_name, 1, 1),
                     std::string("expected a JSON object with \"format\": \"") + kAnimationFormat +
                         "\", \"version\", \"rig\" and \"clips\"");
    Result<Json> root = parse_document(text, file_name);
    if (!root) return root.error();

    AnimationFile file;
    std::vector<Issue> issues = read_animation_json(*root, file);
    add_semantic_issues(file, issues);
    if (issues.empty()) return file;
    return located_error(text, file_name, issues);
}

Result<AnimationFile> load_animation_file(const std::filesystem::path& path) {
    auto text = files::read_text(path);
    if (!text) {
        Error e = text.error();
        if (e.hint.empty()) e.hint = "animation files live in assets/animations/";
        return e;
    }
    return load_animation_string(*text, path.string());
}

Result<void> save_animation_file(const std::filesystem::path& path, const AnimationFile& file) {
    return files::write_atomic(path, save_animation_string(file));
}

Result<AnimationLibrary> load_animation_library(const std::filesystem::path& path) {
    auto file = load_animation_file(path);
    if (!file) return file.error();
    auto rig = build_rig(*file);
    if (!rig) return Error(rig.error().message, Location(path.string()), rig.error().hint);
    auto clips = compile(*file, *rig);
    if (!clips) return Error(clips.error().message, Location(path.string()), clips.error().hint);
    return AnimationLibrary{std::move(*file), std::move(*rig), std::move(*clips)};
}

} // namespace ks::anim
