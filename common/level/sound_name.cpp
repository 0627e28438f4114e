#include "level/sound_name.h"

#include "jsonio/text.h"

#include <algorithm>
#include <cctype>

namespace ks::level {
namespace {

bool allowed(char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
}

std::string lowered(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

const char* const kNaming = "name a file in assets/sounds without its .wav, e.g. \"machine_hum\"";

} // namespace

bool is_valid_sound_name(std::string_view name, int min_length, int max_length) {
    const auto length = static_cast<long>(name.size());
    return length >= min_length && length <= max_length && std::all_of(name.begin(), name.end(), allowed);
}

SoundNameProblem sound_name_problem(std::string_view name, int min_length, int max_length) {
    if (name.empty() && min_length > 0) return {"sound name is empty", kNaming};
    if (static_cast<long>(name.size()) > max_length)
        return {"sound name is " + std::to_string(name.size()) + " characters long; at most " +
                    std::to_string(max_length),
                kNaming};
    if (std::all_of(name.begin(), name.end(), allowed)) return {};
    std::string hint = "sound names hold only a-z, 0-9 and _";
    if (const std::string fix = respelled_sound_name(name); !fix.empty())
        hint = "write \"" + fix + "\" (the file assets/sounds/" + fix + ".wav); " + hint;
    return {"sound name " + jsonio::quote_text(name) + " has characters other than a-z, 0-9 and _", hint};
}

std::string respelled_sound_name(std::string_view name) {
    std::string text = lowered(name);
    if (text.size() >= 4 && text.compare(text.size() - 4, 4, ".wav") == 0) text.resize(text.size() - 4);
    std::string out;
    for (char c : text) {
        if (allowed(c))
            out += c;
        else if (!out.empty() && out.back() != '_')
            out += '_';
    }
    while (!out.empty() && out.back() == '_') out.pop_back();
    return out;
}

} // namespace ks::level
