#include "anim/clip_io.h"

#include "anim/clip_reader.h"
#include "core/files.h"
#include "core/log.h"
#include "jsonio/document.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace ks::anim {
namespace {

using Json = nlohmann::ordered_json;

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
            repeat = !issues[i].warning && related(issues[i].path.str(), semantic.path.str());
        if (!repeat) issues.push_back(std::move(semantic));
    }
}

// Every issue pinned to its line:column: errors (with the document's own) into one Error, warnings to the
// log.
Result<AnimationFile> located(const jsonio::Document& document, AnimationFile file,
                              const std::vector<Issue>& issues) {
    const std::string& file_name = document.file();
    std::vector<Error> errors;
    for (const jsonio::Problem& p : document.problems()) errors.push_back(p.error);
    for (const Issue& issue : issues) {
        std::string path = issue.path.str();
        const jsonio::TextPosition pos = document.positions().find_value(path);
        Error located(issue.message, jsonio::location_at(file_name, pos, std::move(path)), issue.hint);
        if (issue.warning)
            log::warn(located.str());
        else
            errors.push_back(std::move(located));
    }
    if (errors.empty()) return file;
    return jsonio::combined_error(std::move(errors), file_name);
}

} // namespace

Result<AnimationFile> load_animation_string(std::string_view text, const std::string& file_name) {
    const jsonio::Document document = jsonio::Document::parse(
        text, file_name,
        {"animation", std::string("an animation file is a JSON object with \"format\": \"") +
                          kAnimationFormat + "\", \"version\", \"rig\" and \"clips\""});
    AnimationFile file;
    std::vector<Issue> issues;
    if (const jsonio::Json* root = document.root()) {
        issues = read_animation_json(*root, file);
        add_semantic_issues(file, issues);
        // A number that overflowed was reported by the document and reads as null: one message is enough.
        jsonio::Problems reported(file_name, nullptr);
        document.report_to(reported);
        issues.erase(std::remove_if(issues.begin(), issues.end(),
                                    [&](const Issue& i) { return reported.already_reported(i.path.str()); }),
                     issues.end());
    }
    return located(document, std::move(file), issues);
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
    return AnimationLibrary{std::move(*file), std::move(*rig), std::move(*clips), path};
}

} // namespace ks::anim
