#include "model/dojo_edit_support.h"

#include "anim/clip_io.h"
#include "jsonio/number_text.h"

#include <algorithm>

namespace ks::editor::dojo_support {

Result<const anim::ClipDef*> clip_at(const anim::AnimationFile& file, std::size_t clip) {
    if (clip >= file.clips.size())
        return Error("clip " + std::to_string(clip) + " does not exist", {},
                     "the file has " + std::to_string(file.clips.size()) + " clips");
    return &file.clips[clip];
}

Result<anim::ClipDef*> clip_at(anim::AnimationFile& file, std::size_t clip) {
    auto found = clip_at(static_cast<const anim::AnimationFile&>(file), clip);
    if (!found) return found.error();
    return &file.clips[clip];
}

std::string clip_list(const anim::AnimationFile& file) {
    std::string names;
    for (const anim::ClipDef& c : file.clips) names += (names.empty() ? "" : ", ") + c.name;
    return "clips: " + names;
}

std::string seconds_text(double seconds) {
    return jsonio::shortest_text(seconds) + " s";
}

namespace {

std::vector<anim::Issue> issues_in_clip(const anim::AnimationFile& file, std::size_t clip) {
    std::vector<anim::Issue> out;
    if (clip >= file.clips.size()) return out;
    for (anim::Issue& issue : anim::validate(file)) {
        const auto& steps = issue.path.steps();
        if (steps.size() >= 2 && steps[0].key == "clips" && steps[1].index == static_cast<long>(clip))
            out.push_back(std::move(issue));
    }
    return out;
}

} // namespace

Result<void> no_new_clip_issues(const anim::AnimationFile& before, const anim::AnimationFile& edited,
                                std::size_t clip) {
    const auto old_issues = issues_in_clip(before, clip);
    for (const anim::Issue& issue : issues_in_clip(edited, clip)) {
        const bool had = std::any_of(old_issues.begin(), old_issues.end(), [&](const anim::Issue& o) {
            return o.path.str() == issue.path.str() && o.message == issue.message;
        });
        if (!had)
            return Error(issue.message, {},
                         issue.hint.empty() ? "the edit would make the clip invalid" : issue.hint);
    }
    return ok();
}

} // namespace ks::editor::dojo_support
