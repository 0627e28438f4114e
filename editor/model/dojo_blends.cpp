// The blend table's edits and the effective grid (dojo_clips.h).
#include "model/dojo_clips.h"

#include "anim/clip_issues.h"
#include "model/dojo_edit_support.h"

#include <algorithm>
#include <cmath>

namespace ks::editor {
namespace {
using dojo_support::seconds_text;

Result<void> check_blend_seconds(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0 || seconds > kMaxBlendSeconds)
        return Error("blend time " + seconds_text(seconds) + " is out of range", {},
                     "seconds in [0, " + seconds_text(kMaxBlendSeconds) + "]; 0 cuts without a blend");
    return ok();
}

Result<void> check_blend_end(const anim::AnimationFile& file, const std::string& name) {
    if (name == "*" || file.find_clip(name)) return ok();
    std::vector<std::string> names;
    for (const anim::ClipDef& c : file.clips) names.push_back(c.name);
    return Error("no clip '" + name + "' to blend", {},
                 anim::did_you_mean(name, names) + dojo_support::clip_list(file) + ", or * for any clip");
}

auto names_exactly(const std::string& from, const std::string& to) {
    return [&from, &to](const anim::BlendPair& p) { return p.from == from && p.to == to; };
}

} // namespace

Result<void> set_default_blend(anim::AnimationFile& file, double seconds) {
    if (auto r = check_blend_seconds(seconds); !r) return r;
    file.default_blend = seconds;
    return ok();
}

Result<void> set_blend(anim::AnimationFile& file, const std::string& from, const std::string& to,
                       double seconds) {
    if (auto r = check_blend_end(file, from); !r) return r;
    if (auto r = check_blend_end(file, to); !r) return r;
    if (auto r = check_blend_seconds(seconds); !r) return r;
    auto& pairs = file.blends;
    const auto first = std::find_if(pairs.begin(), pairs.end(), names_exactly(from, to));
    if (first == pairs.end()) {
        pairs.push_back({from, to, seconds});
        return ok();
    }
    first->time = seconds;
    // Only the last of duplicate pairs counted; keep one so the cell is what it shows.
    pairs.erase(std::remove_if(first + 1, pairs.end(), names_exactly(from, to)), pairs.end());
    return ok();
}

Result<void> clear_blend(anim::AnimationFile& file, const std::string& from, const std::string& to) {
    const std::size_t before = file.blends.size();
    std::erase_if(file.blends, names_exactly(from, to));
    if (file.blends.size() != before) return ok();
    std::string source = "it uses the default blend (" + seconds_text(file.default_blend) + ")";
    const auto from_index = find_clip_index(file, from), to_index = find_clip_index(file, to);
    if (from_index && to_index) {
        const BlendGrid grid = blend_grid(file); // kept: at() returns a reference into it
        const BlendCell& cell = grid.at(*from_index, *to_index);
        if (cell.source == BlendCell::Source::Wildcard)
            source = "its " + seconds_text(cell.seconds) + " comes from a pair with *; clear that one";
    }
    return Error("no blend is set for " + from + " -> " + to, {}, source);
}

BlendGrid blend_grid(const anim::AnimationFile& file) {
    BlendGrid grid;
    grid.default_seconds = file.default_blend;
    for (const anim::ClipDef& c : file.clips) grid.clips.push_back(c.name);
    const std::size_t n = grid.clips.size();
    grid.cells.assign(n * n, BlendCell{file.default_blend, BlendCell::Source::Default});
    // As anim::compile: wildcard pairs first, then exact ones over them; later pairs over earlier ones.
    for (const bool wildcard_pass : {true, false})
        for (const anim::BlendPair& pair : file.blends) {
            if ((pair.from == "*" || pair.to == "*") != wildcard_pass) continue;
            for (std::size_t f = 0; f < n; ++f)
                for (std::size_t t = 0; t < n; ++t)
                    if ((pair.from == "*" || pair.from == grid.clips[f]) &&
                        (pair.to == "*" || pair.to == grid.clips[t]))
                        grid.cells[f * n + t] = {pair.time, wildcard_pass ? BlendCell::Source::Wildcard
                                                                          : BlendCell::Source::Explicit};
        }
    return grid;
}

std::vector<std::string> short_clip_labels(const std::vector<std::string>& names, std::size_t max_chars) {
    max_chars = std::max<std::size_t>(max_chars, 3);
    std::vector<std::string> labels;
    labels.reserve(names.size());
    for (const std::string& name : names) {
        if (name.size() <= max_chars) {
            labels.push_back(name);
            continue;
        }
        const std::size_t tail = (max_chars - 1) / 2, head = max_chars - 1 - tail;
        labels.push_back(name.substr(0, head) + "." + name.substr(name.size() - tail));
    }
    std::vector<std::string> out = labels;
    for (std::size_t i = 0; i < labels.size(); ++i)
        if (std::count(labels.begin(), labels.end(), labels[i]) > 1) out[i] = "#" + std::to_string(i + 1);
    return out;
}

} // namespace ks::editor
