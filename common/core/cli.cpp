#include "core/cli.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace ks {

Result<CommandLine> CommandLine::parse(int argc, const char* const* argv,
                                       const std::vector<std::string>& flags) {
    CommandLine cl;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg.rfind("--", 0) != 0 || arg.size() == 2) {
            cl.positional_.push_back(arg);
            continue;
        }
        std::string name = arg.substr(2);
        if (auto eq = name.find('='); eq != std::string::npos) {
            cl.values_[name.substr(0, eq)] = name.substr(eq + 1);
            continue;
        }
        if (std::find(flags.begin(), flags.end(), name) != flags.end()) {
            cl.values_[name] = "";
            continue;
        }
        if (i + 1 >= argc) return Error("option --" + name + " needs a value", Location{"command line"});
        cl.values_[name] = argv[++i];
    }
    return cl;
}

std::optional<std::string> CommandLine::get(const std::string& name) const {
    auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

std::string CommandLine::get_or(const std::string& name, const std::string& fallback) const {
    return get(name).value_or(fallback);
}

Result<int> CommandLine::get_int(const std::string& name, int fallback, int min, int max) const {
    auto text = get(name);
    if (!text) return fallback;
    int value = 0;
    auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), value);
    if (ec != std::errc() || end != text->data() + text->size() || value < min || value > max)
        return Error("--" + name + " must be a whole number from " + std::to_string(min) + " to " +
                         std::to_string(max) + ", got '" + *text + "'",
                     Location{"command line"});
    return value;
}

Result<double> CommandLine::get_double(const std::string& name, double fallback) const {
    auto text = get(name);
    if (!text) return fallback;
    char* end = nullptr;
    double value = std::strtod(text->c_str(), &end);
    if (text->empty() || *end != '\0' || !std::isfinite(value))
        return Error("--" + name + " must be a finite number, got '" + *text + "'", Location{"command line"});
    return value;
}

std::vector<std::string> CommandLine::unknown(const std::vector<std::string>& known) const {
    std::vector<std::string> out;
    for (auto& [name, value] : values_)
        if (std::find(known.begin(), known.end(), name) == known.end()) out.push_back("--" + name);
    return out;
}

namespace {
std::string_view trim_spaces(std::string_view text) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    return text;
}
} // namespace

Result<PoseArgument> parse_pose(std::string_view text) {
    static constexpr const char* kNames[] = {"x", "y", "z", "yaw", "pitch"};
    const char* hint = "five finite numbers separated by commas: x,y,z in metres, then yaw and pitch in "
                       "degrees, yaw 0 looking along -z; e.g. 0,3,25,0,-10";
    float values[5] = {};
    size_t count = 0;
    for (size_t start = 0;; ++count) {
        const size_t comma = text.find(',', start);
        const std::string_view field =
            trim_spaces(text.substr(start, comma == std::string_view::npos ? comma : comma - start));
        if (count == 5) return Error("expected x,y,z,yaw,pitch: more than five values", {}, hint);
        const std::string quoted = std::string(kNames[count]) + " '" + std::string(field) + "'";
        const char* end = field.data() + field.size();
        auto [stop, ec] = std::from_chars(field.data(), end, values[count]);
        if (field.empty() || stop != end || ec == std::errc::invalid_argument)
            return Error("expected x,y,z,yaw,pitch: " + quoted + " is not a number", {}, hint);
        if (ec == std::errc::result_out_of_range || !std::isfinite(values[count]))
            return Error("expected x,y,z,yaw,pitch: " + quoted + " is not a finite number", {}, hint);
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    if (count + 1 < 5)
        return Error("expected x,y,z,yaw,pitch: only " + std::to_string(count + 1) + " of the five values",
                     {}, hint);
    return PoseArgument{Vec3(values[0], values[1], values[2]), values[3], values[4]};
}

} // namespace ks
